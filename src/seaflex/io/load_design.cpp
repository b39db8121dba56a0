// The model's `fatigue` and `code_check` sections (docs/model-format.md, "Fatigue" and
// "Code checks"): the beams they cover (ANCF beams with a pipe section), the S-N curve of
// DNV-RP-C203 (2016) or a user curve, stress factors, material and partial factors.
#include <fmt/format.h>

#include <algorithm>
#include <limits>

#include "seaflex/io/load_context.hpp"

namespace seaflex::io {

namespace {

constexpr double kInf = NumberRule::kInf;

// every section of the beam is a pipe (outer and inner diameter given)
bool is_pipe(const AncfBeam& beam) {
  for (const auto& sec : beam.sections())
    if (!(sec.outer_diameter > 0.0)) return false;
  return true;
}

// the list at `beams` (every pipe beam when absent): each an ANCF beam with a pipe section
std::vector<std::string> read_pipe_beams(MapReader& r, LoadContext& ctx) {
  std::vector<std::string> out;
  const YAML::Node n = r.get("beams");
  std::vector<std::string> beams;
  for (const auto& b : ctx.system.bodies())
    if (dynamic_cast<const AncfBeam*>(b.get())) beams.push_back(b->name());
  if (!n.IsDefined()) {
    for (const auto& name : beams) {
      const auto* beam = dynamic_cast<const AncfBeam*>(ctx.system.find_body(name));
      if (is_pipe(*beam)) out.push_back(name);
    }
    if (out.empty())
      r.error("beams",
              "the model has no ancf_beam with a pipe section "
              "(outer_diameter, inner_diameter) to check");
    return out;
  }
  if (!n.IsSequence() || n.size() == 0) {
    r.error("beams", fmt::format("expected a non-empty list of beam names, got {}",
                                 n.IsSequence() ? "an empty list" : describe(n)));
    return out;
  }
  for (std::size_t i = 0; i < n.size(); ++i) {
    const std::string path = fmt::format("{}[{}]", r.key_path("beams"), i);
    if (!n[i].IsScalar()) {
      ctx.diag.error(n[i].Mark(), path,
                     fmt::format("expected a beam name, got {}", describe(n[i])));
      continue;
    }
    const std::string name = n[i].Scalar();
    if (std::find(ctx.failed_bodies.begin(), ctx.failed_bodies.end(), name) !=
        ctx.failed_bodies.end())
      continue;  // reported where the body is defined
    const Body* body = ctx.system.find_body(name);
    const auto* beam = dynamic_cast<const AncfBeam*>(body);
    if (!body)
      ctx.diag.error(n[i].Mark(), path,
                     fmt::format("no beam named '{}'; {}", name, suggestion(name, beams)));
    else if (!beam)
      ctx.diag.error(n[i].Mark(), path,
                     fmt::format("body '{}' is a {}; only ancf_beam bodies are accepted here", name,
                                 body->kind()));
    else if (!is_pipe(*beam))
      ctx.diag.error(n[i].Mark(), path,
                     fmt::format("beam '{}' has no pipe section: give outer_diameter and "
                                 "inner_diameter (stresses need the wall)",
                                 name));
    else if (std::find(out.begin(), out.end(), name) != out.end())
      ctx.diag.error(n[i].Mark(), path, fmt::format("beam '{}' is listed twice", name));
    else
      out.push_back(name);
  }
  return out;
}

// the S-N curve: a DNV-RP-C203 name, or {m1, log_a1[, m2, log_a2]}
std::optional<post::SnCurve> read_curve(MapReader& r, post::SnEnvironment env, double scf) {
  const YAML::Node n = r.get("curve", Need::kRequired,
                             "a DNV-RP-C203 curve name (B1 ... W3, T) or {m1, log_a1, m2, log_a2}");
  if (!n.IsDefined()) return std::nullopt;
  if (n.IsScalar()) {
    const auto c = post::dnv_curve(n.Scalar(), env, scf);
    if (!c)
      r.error("curve", fmt::format("no DNV-RP-C203 S-N curve named '{}'; {}", n.Scalar(),
                                   suggestion(n.Scalar(), post::dnv_curve_names())));
    return c;
  }
  MapReader c(r.diagnostics(), n, r.key_path("curve"));
  if (!c.valid()) return std::nullopt;
  const auto m1 = c.number("m1", Need::kRequired, NumberRule::positive(""));
  const auto a1 = c.number("log_a1", Need::kRequired, NumberRule::any("log10 cycles"));
  const auto m2 = c.number("m2", Need::kOptional, NumberRule::positive(""));
  const auto a2 =
      c.number("log_a2", m2 ? Need::kRequired : Need::kOptional, NumberRule::any("log10 cycles"));
  const auto k = c.number("k", Need::kOptional, NumberRule::range(0.0, 1.0, ""));
  const auto t_ref = c.number("t_ref", Need::kOptional, NumberRule::positive("m"));
  if (a2 && !m2) c.error("log_a2", "log_a2 needs m2, the second slope");
  if (m1 && m2 && *m1 == *m2) c.error("m2", fmt::format("must differ from m1 ({:g})", *m1));
  c.finish();
  if (!m1 || !a1 || (m2 && !a2) || (m1 && m2 && *m1 == *m2)) return std::nullopt;
  return post::user_curve(*m1, *a1, m2.value_or(0.0), a2.value_or(0.0), k.value_or(0.0),
                          t_ref.value_or(0.025));
}

}  // namespace

void load_fatigue(const YAML::Node& node, LoadContext& ctx) {
  MapReader r(ctx.diag, node, "fatigue");
  if (!r.valid()) return;
  FatigueSettings f;
  f.beams = read_pipe_beams(r, ctx);
  if (const auto e =
          r.choice("environment", Need::kOptional, {"air", "seawater_cp", "free_corrosion"}))
    f.environment = *e == "air"           ? post::SnEnvironment::kAir
                    : *e == "seawater_cp" ? post::SnEnvironment::kSeawaterCp
                                          : post::SnEnvironment::kFreeCorrosion;
  f.scf = r.number("scf", Need::kOptional, NumberRule{1.0, kInf, false, ""}).value_or(1.0);
  const auto curve = read_curve(r, f.environment, f.scf);
  f.thickness = r.number("thickness", Need::kOptional, NumberRule::positive("m")).value_or(0.0);
  f.points = r.integer("points", Need::kOptional, 1, 360).value_or(8);
  f.start = r.number("start", Need::kOptional, NumberRule::nonnegative("s")).value_or(0.0);
  f.exposure = r.number("exposure", Need::kOptional, NumberRule::positive("s")).value_or(0.0);
  if (r.has("write_stresses")) f.write_stresses = read_bool(r, "write_stresses").value_or(false);
  if (ctx.model.dynamics && ctx.model.dynamics->duration > 0.0 &&
      f.start >= ctx.model.dynamics->duration)
    r.error("start", fmt::format("{:g} s is not before the end of the run (dynamics.duration "
                                 "{:g} s): no output row would be counted",
                                 f.start, ctx.model.dynamics->duration));
  r.finish();
  if (!curve) return;
  f.curve = *curve;
  ctx.model.fatigue = std::move(f);
}

void load_code_check(const YAML::Node& node, LoadContext& ctx) {
  MapReader r(ctx.diag, node, "code_check");
  if (!r.valid()) return;
  CodeCheckSettings c;
  c.beams = read_pipe_beams(r, ctx);
  const auto smys = r.number("smys", Need::kRequired, NumberRule::positive("Pa"));
  const auto smts = r.number("smts", Need::kRequired, NumberRule::positive("Pa"));
  if (smys && smts && *smts < *smys)
    r.error("smts", fmt::format("the tensile strength {:g} Pa is below the yield strength "
                                "smys {:g} Pa",
                                *smts, *smys));
  c.corrosion =
      r.number("corrosion_allowance", Need::kOptional, NumberRule::nonnegative("m")).value_or(0.0);
  c.fabrication = r.number("fabrication_tolerance", Need::kOptional, NumberRule::nonnegative("m"))
                      .value_or(0.0);
  post::DnvFactors& f = c.factors;
  const NumberRule factor{0.0, 10.0, true, ""};
  f.gamma_F = r.number("gamma_F", Need::kOptional, factor).value_or(f.gamma_F);
  f.gamma_E = r.number("gamma_E", Need::kOptional, factor).value_or(f.gamma_E);
  f.gamma_C = r.number("gamma_C", Need::kOptional, factor).value_or(f.gamma_C);
  f.gamma_SC = r.number("gamma_SC", Need::kOptional, factor).value_or(f.gamma_SC);
  f.gamma_m = r.number("gamma_m", Need::kOptional, factor).value_or(f.gamma_m);
  c.design_factor = r.number("design_factor", Need::kOptional, factor).value_or(1.0);
  c.start = r.number("start", Need::kOptional, NumberRule::nonnegative("s")).value_or(0.0);
  if (ctx.model.dynamics && ctx.model.dynamics->duration > 0.0 &&
      c.start >= ctx.model.dynamics->duration)
    r.error("start", fmt::format("{:g} s is not before the end of the run (dynamics.duration "
                                 "{:g} s): no output row would be checked",
                                 c.start, ctx.model.dynamics->duration));
  r.finish();
  if (!smys || !smts) return;
  c.smys = *smys;
  c.smts = *smts;
  for (const auto& name : c.beams) {
    double wall = std::numeric_limits<double>::infinity();
    for (const auto& sec : dynamic_cast<const AncfBeam*>(ctx.system.find_body(name))->sections())
      wall = std::min(wall, 0.5 * (sec.outer_diameter - sec.inner_diameter));
    if (c.corrosion + c.fabrication >= wall)
      r.error("corrosion_allowance",
              fmt::format("corrosion allowance and fabrication tolerance ({:g} m) leave no wall "
                          "of beam '{}' ({:g} m)",
                          c.corrosion + c.fabrication, name, wall));
  }
  ctx.model.code_check = std::move(c);
}

}  // namespace seaflex::io
