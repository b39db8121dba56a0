// environment.water / waves / current / wave_probes, and the hydrodynamics section: Morison
// coefficients of beams; hull, Morison members, hydrodynamic matrices and BEM data of
// rigid bodies. Format: docs/model-format.md sections 4 and 11.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <tuple>

#include "seaflex/forces/hull_hydrostatics.hpp"
#include "seaflex/forces/hydro_matrices.hpp"
#include "seaflex/forces/morison_beam.hpp"
#include "seaflex/forces/rigid_morison.hpp"
#include "seaflex/hydro/directional_spreading.hpp"
#include "seaflex/hydro/wave_grid.hpp"
#include "seaflex/hydro/wave_spectrum.hpp"
#include "seaflex/io/load_context.hpp"
#include "seaflex/math/rotation.hpp"

namespace seaflex::io {

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// kinematics: exact | grid, and the grid's spacings (docs/model-format.md 4.2)
std::optional<hydro::WaveGridSpec> read_kinematics(MapReader& w) {
  const bool grid =
      w.has("kinematics") &&
      w.choice("kinematics", Need::kRequired, {"exact", "grid"}).value_or("") == "grid";
  if (!w.has("grid")) return grid ? std::optional(hydro::WaveGridSpec{}) : std::nullopt;
  MapReader gr(w.diagnostics(), w.get("grid"), w.key_path("grid"));
  if (!grid) {
    w.error("grid", "grid spacings need kinematics: grid");
    return std::nullopt;
  }
  hydro::WaveGridSpec spec;
  spec.ds = gr.number("ds", Need::kOptional, NumberRule::positive("m")).value_or(spec.ds);
  spec.dz = gr.number("dz", Need::kOptional, NumberRule::positive("m")).value_or(spec.dz);
  spec.dz_growth = gr.number("dz_growth", Need::kOptional, NumberRule::range(0.0, 10.0, ""))
                       .value_or(spec.dz_growth);
  spec.dt = gr.number("dt", Need::kOptional, NumberRule::positive("s")).value_or(spec.dt);
  gr.finish();
  return spec;
}

// spreading: {type: cos2s, s, directions, max_angle} of an irregular sea with `components`
// components per direction (docs/model-format.md 4.2); false after an error
bool read_spreading(MapReader& w, int components, hydro::DirectionSet& set) {
  MapReader sp(w.diagnostics(), w.get("spreading"), w.key_path("spreading"));
  if (!sp.valid()) return false;
  bool ok = true;
  const auto fail = [&](std::string_view key, std::string message) {
    sp.error(key, std::move(message));
    ok = false;
  };
  const auto type = sp.choice("type", Need::kRequired, {"cos2s"});
  const auto s = sp.number("s", Need::kRequired, NumberRule::positive(""));
  // 1000: a half-width of about 2/sqrt(s) rad = 3.6 deg, long-crested for any purpose
  if (s && *s > 1000.0)
    fail("s", fmt::format("must be at most 1000 (a narrower sea is long-crested: give no "
                          "spreading), got {:g}",
                          *s));
  const bool gave_directions = sp.has("directions");
  const auto directions = sp.integer("directions", Need::kOptional, 1, 1000);
  const int m = directions.value_or(9);
  if (m % 2 == 0)
    fail("directions",
         fmt::format("must be odd, so that one direction lies on the mean direction, got {}", m));
  const bool gave_max_angle = sp.has("max_angle");
  const auto max_angle = sp.number("max_angle", Need::kOptional, NumberRule::positive("deg"));
  if (max_angle && *max_angle > 180.0)
    fail("max_angle",
         fmt::format("must be at most 180 deg (cos-2s spreads over the whole circle), got {:g} deg",
                     *max_angle));
  // the cap of a long-crested sea's components holds for the whole spread sea
  if (static_cast<long>(components) * m > 100000)
    fail("directions",
         fmt::format("{} components x {} directions{} = {} components, more than 100000: use "
                     "fewer components (they count per direction) or directions",
                     components, m, directions ? "" : " (the default)",
                     static_cast<long>(components) * m));
  sp.finish();
  if (!ok || !type || !s || (gave_directions && !directions) || (gave_max_angle && !max_angle))
    return false;
  hydro::SpreadingSpec spec;
  spec.s = *s;
  spec.directions = m;
  spec.max_angle = std::min(std::numbers::pi, max_angle.value_or(180.0) * kDeg);
  set = hydro::cos2s_directions(spec);
  return true;
}

std::optional<std::vector<hydro::WaveComponent>> read_waves(MapReader& w, double depth, double g,
                                                            hydro::Ramp& ramp, bool& wheeler) {
  const auto type = w.choice("type", Need::kRequired, {"airy", "jonswap", "pierson_moskowitz"});
  const double direction =
      w.number("direction", Need::kOptional, NumberRule::range(-360, 360, "deg")).value_or(0.0) *
      kDeg;
  if (w.has("ramp")) {
    MapReader rr(w.diagnostics(), w.get("ramp"), w.key_path("ramp"));
    ramp.start = rr.number("start", Need::kOptional, NumberRule::nonnegative("s")).value_or(0.0);
    ramp.duration =
        rr.number("duration", Need::kRequired, NumberRule::nonnegative("s")).value_or(0.0);
    rr.finish();
  }
  if (w.has("wheeler_stretching")) {
    const auto ws = w.choice("wheeler_stretching", Need::kRequired, {"true", "false"});
    wheeler = ws.value_or("true") == "true";
  }
  if (!type) {
    // the keys of every kind are known: only the type is reported
    for (const char* k : {"height", "period", "phase", "hs", "tp", "gamma", "seed", "components",
                          "omega_min", "omega_max", "spreading"})
      w.has(k);
    return std::nullopt;
  }
  std::vector<hydro::WaveComponent> components;
  if (*type == "airy") {
    const auto height = w.number("height", Need::kRequired, NumberRule::positive("m"));
    const auto period = w.number("period", Need::kRequired, NumberRule::positive("s"));
    const double phase =
        w.number("phase", Need::kOptional, NumberRule::range(-360, 360, "deg")).value_or(0.0) *
        kDeg;
    if (w.has("spreading")) {
      w.error("spreading",
              "applies to irregular seas (type: jonswap or pierson_moskowitz): an airy wave "
              "travels in one direction");
      return std::nullopt;
    }
    if (!height || !period) return std::nullopt;
    components.push_back(hydro::regular_component(*height, *period, direction, phase, depth, g));
    return components;
  }
  hydro::SpectrumSpec spec;
  spec.kind =
      *type == "jonswap" ? hydro::SpectrumKind::kJonswap : hydro::SpectrumKind::kPiersonMoskowitz;
  const auto hs = w.number("hs", Need::kRequired, NumberRule::positive("m"));
  const auto tp = w.number("tp", Need::kRequired, NumberRule::positive("s"));
  if (*type == "jonswap")
    spec.gamma = w.number("gamma", Need::kOptional, NumberRule::range(1.0, 20.0, "")).value_or(3.3);
  spec.seed = static_cast<unsigned>(w.integer("seed", Need::kOptional, 0, 2147483647).value_or(1));
  spec.components = w.integer("components", Need::kOptional, 1, 100000).value_or(200);
  spec.omega_min =
      w.number("omega_min", Need::kOptional, NumberRule::positive("rad/s")).value_or(0.0);
  spec.omega_max =
      w.number("omega_max", Need::kOptional, NumberRule::positive("rad/s")).value_or(0.0);
  if (spec.omega_min > 0.0 && spec.omega_max > 0.0 && spec.omega_max <= spec.omega_min) {
    w.error("omega_max", fmt::format("must exceed omega_min ({} rad/s), got {} rad/s",
                                     spec.omega_min, spec.omega_max));
    return std::nullopt;
  }
  hydro::DirectionSet directions = hydro::DirectionSet::long_crested();
  if (w.has("spreading") && !read_spreading(w, spec.components, directions)) return std::nullopt;
  if (!hs || !tp) return std::nullopt;
  spec.hs = *hs;
  spec.tp = *tp;
  spec.direction = direction;
  try {
    return hydro::irregular_components(spec, depth, g, directions);
  } catch (const std::invalid_argument& e) {
    // the spectrum's own checks: the band (omega_min alone above the default top)
    const std::string what = e.what();
    w.error(what.find("omega") != std::string::npos ? "omega_min" : "type", what);
    return std::nullopt;
  }
}

std::optional<hydro::CurrentProfile> read_current(MapReader& c) {
  const bool uniform = c.has("speed"), profiled = c.has("profile");
  if (uniform == profiled) {
    c.has("direction");
    c.error(uniform ? "profile" : "speed",
            "give either speed (m/s) and direction (deg) for a uniform current, or profile "
            "[[z, speed, direction], ...]");
    return std::nullopt;
  }
  if (uniform) {
    const auto speed = c.number("speed", Need::kRequired, NumberRule::nonnegative("m/s"));
    const double dir =
        c.number("direction", Need::kOptional, NumberRule::range(-360, 360, "deg")).value_or(0.0);
    if (!speed) return std::nullopt;
    return hydro::CurrentProfile({{0.0, *speed, dir * kDeg}});
  }
  const auto rows = c.table("profile", Need::kRequired, 3, "z");
  if (!rows) return std::nullopt;
  std::vector<std::array<double, 3>> table;
  for (const auto& row : *rows) {
    if (row[0] > 0.0) {
      c.error("profile",
              fmt::format("z must be <= 0 (the mean surface is z = 0), got {} m", row[0]));
      return std::nullopt;
    }
    if (row[1] < 0.0) {
      c.error("profile", fmt::format("a speed must be >= 0 m/s, got {} m/s", row[1]));
      return std::nullopt;
    }
    table.push_back({row[0], row[1], row[2] * kDeg});
  }
  try {
    return hydro::CurrentProfile(std::move(table));
  } catch (const std::invalid_argument& e) {
    c.error("profile", e.what());
    return std::nullopt;
  }
}

// a 6x6 matrix: a list of six rows of six numbers
std::optional<Mat6> read_mat6(MapReader& r, std::string_view key, std::string_view unit) {
  const YAML::Node n = r.get(key);
  if (!n.IsDefined()) return Mat6::Zero();
  const std::string path = r.key_path(key);
  if (!n.IsSequence() || n.size() != 6) {
    r.error(key, fmt::format("expected a 6x6 matrix (six rows of six numbers, {}; modes surge, "
                             "sway, heave, roll, pitch, yaw)",
                             unit));
    return std::nullopt;
  }
  Mat6 M;
  for (int i = 0; i < 6; ++i) {
    if (!n[i].IsSequence() || n[i].size() != 6) {
      r.diagnostics().error(n[i].Mark(), fmt::format("{}[{}]", path, i),
                            "expected a row of six numbers");
      return std::nullopt;
    }
    for (int j = 0; j < 6; ++j) {
      const auto x = read_number(r.diagnostics(), n[i][j], fmt::format("{}[{}][{}]", path, i, j),
                                 NumberRule::any(std::string(unit)));
      if (!x) return std::nullopt;
      M(i, j) = *x;
    }
  }
  return M;
}

// cd, cd_axial, cm (default 0) and ca (default max(0, cm - 1)), for beams and members
std::tuple<double, double, double, double> read_morison_coefficients(MapReader& r) {
  const NumberRule rule = NumberRule::range(0.0, 10.0, "");
  const double cd = r.number("cd", Need::kOptional, rule).value_or(0.0);
  const double cd_axial = r.number("cd_axial", Need::kOptional, rule).value_or(0.0);
  const double cm = r.number("cm", Need::kOptional, rule).value_or(0.0);
  const double ca = r.number("ca", Need::kOptional, rule).value_or(std::max(0.0, cm - 1.0));
  return {cd, cd_axial, cm, ca};
}

// one set of a beam's (or one of its sections') Morison coefficients; d holds the defaults
// (the beam's entry for a section's, whose diameter and contents diameter are already the
// section's), od the section's outer diameter
MorisonBeamCoefficients read_beam_coefficients(MapReader& r, const MorisonBeamCoefficients& d,
                                               bool section, double od, double length) {
  MorisonBeamCoefficients c = d;
  c.diameter = r.number("diameter", d.diameter > 0.0 ? Need::kOptional : Need::kRequired,
                        NumberRule::positive("m"))
                   .value_or(d.diameter);
  if (c.diameter > length && !(od > length))  // od: reported at the body
    r.error("diameter",
            fmt::format("{:g} m is more than the beam's length ({:g} m): a beam is much longer "
                        "than its diameter; seaflex uses m, not mm ({:g} mm = {:g} m)",
                        c.diameter, length, c.diameter, c.diameter / 1000.0));
  const NumberRule rule = NumberRule::range(0.0, 10.0, "");
  c.cd = r.number("cd", Need::kOptional, rule).value_or(d.cd);
  c.cd_axial = r.number("cd_axial", Need::kOptional, rule).value_or(d.cd_axial);
  const auto cm = r.number("cm", Need::kOptional, rule);
  c.cm = cm.value_or(d.cm);
  // ca defaults to max(0, cm - 1) (of this entry's cm when it gives one)
  c.ca = r.number("ca", Need::kOptional, rule)
             .value_or(cm || !section ? std::max(0.0, c.cm - 1.0) : d.ca);
  // axial: added mass ca_axial (default 0) and inertia cm_axial, by default the Froude-Krylov
  // 1 plus ca_axial when the beam has a water inertia at all (cm > 0), as cm = 1 + ca
  c.ca_axial = r.number("ca_axial", Need::kOptional, rule).value_or(d.ca_axial);
  c.cm_axial =
      r.number("cm_axial", Need::kOptional, rule).value_or(c.ca_axial + (c.cm > 0.0 ? 1.0 : 0.0));
  if (r.has("buoyancy"))
    c.buoyancy =
        r.choice("buoyancy", Need::kRequired, {"true", "false"}).value_or("true") == "true";
  c.internal_density =
      r.number("contents_density", Need::kOptional, NumberRule::nonnegative("kg/m^3"))
          .value_or(d.internal_density);
  c.internal_diameter = r.number("contents_diameter", Need::kOptional, NumberRule::positive("m"))
                            .value_or(d.internal_diameter);
  if (c.internal_density > 0.0 && !(c.internal_diameter > 0.0))
    r.error("contents_diameter",
            "required when contents_density is given and the beam has no "
            "inner_diameter");
  if (!section) c.gauss_points = r.integer("gauss_points", Need::kOptional, 1, 20).value_or(5);
  // the fluid kept per Gauss point within one time (forces/morison_beam.hpp); at most 0.1 m,
  // where its error (delta |grad u|) would reach a few per cent of the wave velocity
  if (!section)
    c.fluid_reuse =
        r.number("fluid_reuse", Need::kOptional, NumberRule::range(0.0, 0.1, "m")).value_or(0.0);
  return c;
}

void load_beam_hydro(MapReader& r, const AncfBeam& beam, LoadContext& ctx) {
  const BeamSection& first = beam.section(0);
  MorisonBeamCoefficients defaults;
  defaults.diameter = first.outer_diameter;
  defaults.internal_diameter = first.inner_diameter;
  const bool gave_diameter = r.has("diameter"), gave_contents = r.has("contents_diameter");
  const MorisonBeamCoefficients beam_c =
      read_beam_coefficients(r, defaults, false, first.outer_diameter, beam.length());
  // a line made of sections: each section takes the beam's entry, with its own diameters
  // unless the entry gives them, and its own `hydrodynamics` map over that
  std::vector<MorisonBeamCoefficients> per_section;
  const auto overrides = ctx.section_hydrodynamics.find(beam.name());
  for (std::size_t i = 0; i < beam.sections().size(); ++i) {
    const BeamSection& sec = beam.sections()[i];
    MorisonBeamCoefficients c = beam_c;
    if (!gave_diameter) c.diameter = sec.outer_diameter;
    if (!gave_contents) c.internal_diameter = sec.inner_diameter;
    bool own = false;
    if (overrides != ctx.section_hydrodynamics.end())
      for (const auto& o : overrides->second)
        if (o.section == i) {
          MapReader sr(ctx.diag, o.node, o.path);
          if (sr.valid())
            c = read_beam_coefficients(sr, c, true, sec.outer_diameter, beam.length());
          sr.finish();
          own = true;
        }
    if (!own && !(c.diameter > 0.0) && i > 0)
      r.error("diameter", fmt::format("required: section {} of beam '{}' has no outer_diameter", i,
                                      beam.name()));
    if (!own && c.internal_density > 0.0 && !(c.internal_diameter > 0.0) && i > 0)
      r.error(
          "contents_diameter",
          fmt::format("required: section {} of beam '{}' has no inner_diameter", i, beam.name()));
    per_section.push_back(c);
  }
  r.finish();
  if (overrides != ctx.section_hydrodynamics.end()) ctx.section_hydrodynamics.erase(overrides);
  ctx.system.add_force(std::make_unique<MorisonBeam>(fmt::format("{}.morison", beam.name()), beam,
                                                     std::move(per_section), ctx.model.ocean));
}

std::optional<Vec3> read_point(MapReader& r, std::string_view key, Need need) {
  return r.vec3(key, need, "m");
}

void load_hull(const YAML::Node& node, const std::string& path, const RigidBody& body,
               LoadContext& ctx) {
  if (!node.IsSequence()) {
    ctx.diag.error(node.Mark(), path,
                   "expected a list of pieces (- box: {...} or - cylinder: {...})");
    return;
  }
  std::vector<hydro::ConvexPolyhedron> pieces;
  for (std::size_t i = 0; i < node.size(); ++i) {
    const std::string p = fmt::format("{}[{}]", path, i);
    MapReader item(ctx.diag, node[i], p);
    if (!item.valid()) continue;
    if (item.has("box") && item.has("cylinder")) {
      ctx.diag.error(node[i].Mark(), p,
                     "a hull piece is a box or a cylinder, not both: give each as its own item");
      continue;
    }
    if (item.has("box")) {
      MapReader b(ctx.diag, item.get("box"), p + ".box");
      const auto center = read_point(b, "center", Need::kRequired);
      const auto size = b.vec3("size", Need::kRequired, "m");
      const auto axes = read_orientation(b, false);
      b.finish();
      if (size && (size->minCoeff() <= 0.0)) {
        b.error("size", fmt::format("every edge must be > 0 m, got [{}, {}, {}]", size->x(),
                                    size->y(), size->z()));
        continue;
      }
      if (center && size && axes)
        pieces.push_back(hydro::ConvexPolyhedron::box(*center, *size, *axes));
    } else if (item.has("cylinder")) {
      MapReader c(ctx.diag, item.get("cylinder"), p + ".cylinder");
      const auto a = read_point(c, "end_a", Need::kRequired);
      const auto b = read_point(c, "end_b", Need::kRequired);
      const auto d = c.number("diameter", Need::kRequired, NumberRule::positive("m"));
      c.finish();
      if (a && b && (*a - *b).norm() == 0.0) {
        c.error("end_b", "coincides with end_a: a cylinder needs a length");
        continue;
      }
      if (a && b && d) pieces.push_back(hydro::ConvexPolyhedron::cylinder(*a, *b, *d));
    } else {
      std::string given;
      for (const auto& kv : node[i]) {
        // a key that is not a plain name (a mapping or a list) has no text to show
        given +=
            (given.empty() ? "" : ", ") +
            (kv.first.IsScalar() ? kv.first.Scalar() : std::string("a key that is not a name"));
        item.has(kv.first.Scalar());
      }
      ctx.diag.error(
          node[i].Mark(), p,
          fmt::format("a hull piece is box: {{...}} or cylinder: {{...}}, got {}", given));
    }
    item.finish();
  }
  ctx.system.add_force(std::make_unique<HullHydrostatics>(
      fmt::format("{}.hydrostatics", body.name()), body, std::move(pieces), ctx.model.ocean->rho(),
      ctx.model.ocean->g()));
}

void load_members(const YAML::Node& node, const std::string& path, const RigidBody& body,
                  std::shared_ptr<const hydro::Ocean> ocean, LoadContext& ctx) {
  if (!node.IsSequence()) {
    ctx.diag.error(node.Mark(), path, "expected a list of members");
    return;
  }
  std::vector<MorisonMember> members;
  for (std::size_t i = 0; i < node.size(); ++i) {
    MapReader m(ctx.diag, node[i], fmt::format("{}[{}]", path, i));
    if (!m.valid()) continue;
    MorisonMember mem;
    const auto a = read_point(m, "end_a", Need::kRequired);
    const auto b = read_point(m, "end_b", Need::kRequired);
    const auto d = m.number("diameter", Need::kRequired, NumberRule::positive("m"));
    std::tie(mem.cd, mem.cd_axial, mem.cm, mem.ca) = read_morison_coefficients(m);
    mem.strips = m.integer("strips", Need::kOptional, 1, 64).value_or(10);
    if (m.has("end_effects"))
      mem.end_effects =
          m.choice("end_effects", Need::kRequired, {"true", "false"}).value_or("false") == "true";
    m.finish();
    if (a && b && (*a - *b).norm() == 0.0) {
      m.error("end_b", "coincides with end_a: a member needs a length");
      continue;
    }
    if (!a || !b || !d) continue;
    mem.a = *a;
    mem.b = *b;
    mem.diameter = *d;
    members.push_back(mem);
  }
  ctx.system.add_force(std::make_unique<RigidMorison>(fmt::format("{}.morison", body.name()), body,
                                                      std::move(members), std::move(ocean)));
}

void load_rigid_hydro(MapReader& r, const RigidBody& body, LoadContext& ctx) {
  const hydro::Ocean& ocean = *ctx.model.ocean;
  if (const YAML::Node n = r.get("hull"); n.IsDefined())
    load_hull(n, r.key_path("hull"), body, ctx);
  // include_current: false: the members feel the waves only (the mean current load on the
  // hull is taken by station keeping that is not modelled, as in thesis 3.3.3)
  std::shared_ptr<const hydro::Ocean> member_ocean = ctx.model.ocean;
  if (r.has("include_current") &&
      r.choice("include_current", Need::kRequired, {"true", "false"}).value_or("true") == "false")
    member_ocean = std::make_shared<const hydro::Ocean>(ocean.rho(), ocean.g(), ocean.depth(),
                                                        ocean.waves(), hydro::CurrentProfile{});
  if (const YAML::Node n = r.get("morison"); n.IsDefined())
    load_members(n, r.key_path("morison"), body, std::move(member_ocean), ctx);

  HydroMatrixSet set;
  set.heading = math::roll_pitch_yaw_from_rotation(body.initial().orientation)[2];
  set.rho = ocean.rho();
  set.g = ocean.g();
  set.reference = read_point(r, "reference_point", Need::kOptional).value_or(Vec3::Zero());
  const auto added = read_mat6(r, "added_mass", "kg, kg m, kg m^2");
  const auto lin = read_mat6(r, "linear_damping", "N s/m, N s, N m s");
  const auto quad = read_mat6(r, "quadratic_damping", "N s^2/m^2, ...");
  if (added) set.added_mass = *added;
  if (lin) set.linear_damping = *lin;
  if (quad) set.quadratic_damping = *quad;
  bool any = !set.added_mass.isZero(0.0) || !set.linear_damping.isZero(0.0) ||
             !set.quadratic_damping.isZero(0.0);

  if (r.has("bem")) {
    MapReader b(ctx.diag, r.get("bem"), r.key_path("bem"));
    if (r.has("hull") && b.has("displaced_volume"))
      ctx.model.warnings.push_back(fmt::format(
          "{}:{}:{}: {}: both a hull and a BEM displaced_volume give buoyancy: it is counted "
          "twice; drop one of them",
          ctx.diag.file(), b.mark().line + 1, b.mark().column + 1, b.path()));
    load_bem(b, body, set, ctx);
    b.finish();
    any = true;
  }
  if (any || set.has_stiffness)
    ctx.system.add_force(
        std::make_unique<HydroMatrices>(fmt::format("{}.hydro_matrices", body.name()), body, set));
}

}  // namespace

void load_water(MapReader& env, LoadContext& ctx, double g) {
  const bool water = env.has("water");
  const YAML::Node waves = env.get("waves");
  const YAML::Node current = env.get("current");
  const YAML::Node probes = env.get("wave_probes");
  if (!water) {
    for (const auto& [node, key] :
         {std::pair{waves, "waves"}, {current, "current"}, {probes, "wave_probes"}})
      if (node.IsDefined()) env.error(key, "needs environment.water (density and depth)");
    return;
  }
  MapReader w(ctx.diag, env.get("water"), env.key_path("water"));
  const auto rho_read = w.number("density", Need::kOptional, NumberRule::positive("kg/m^3"));
  const double rho = rho_read.value_or(1025.0);
  if (rho_read && *rho_read < 100.0)
    w.error("density", fmt::format("{:g} kg/m^3 is implausibly low for water; seaflex uses "
                                   "kg/m^3 (sea water: 1025), not t/m^3",
                                   *rho_read));
  // the densest brines are about 1,300 kg/m^3 (the Dead Sea 1,240)
  if (rho_read && *rho_read > 1500.0)
    w.error("density",
            fmt::format("{:g} kg/m^3 is implausibly high for water (the densest brines: about "
                        "1300 kg/m^3){}; seaflex uses kg/m^3 (sea water: 1025)",
                        *rho_read,
                        *rho_read / 1000.0 >= 900.0 && *rho_read / 1000.0 <= 1500.0
                            ? fmt::format(": it looks like g/m^3 ({:g} g/m^3 = {:g} kg/m^3)",
                                          *rho_read, *rho_read / 1000.0)
                            : ""));
  double depth = std::numeric_limits<double>::infinity();
  if (const YAML::Node d = w.get("depth", Need::kRequired, "the water depth in m, or infinite");
      d.IsDefined()) {
    if (!(d.IsScalar() && d.Scalar() == "infinite"))
      depth =
          read_number(ctx.diag, d, w.key_path("depth"), NumberRule::positive("m")).value_or(depth);
  }
  w.finish();
  if (!(g > 0.0)) {
    env.error("water", "water needs gravity (hydrostatics and waves): gravity is zero");
    return;
  }
  std::vector<hydro::WaveComponent> components;
  hydro::Ramp ramp;
  bool wheeler = true;
  std::optional<hydro::WaveGridSpec> grid;
  std::string grid_path, kinematics_path;
  if (waves.IsDefined()) {
    MapReader wr(ctx.diag, waves, env.key_path("waves"));
    kinematics_path = wr.key_path("kinematics");
    if (wr.valid()) {
      if (auto c = read_waves(wr, depth, g, ramp, wheeler)) components = std::move(*c);
      grid = read_kinematics(wr);
      grid_path = wr.key_path(wr.has("grid") ? "grid" : "kinematics");
    }
    wr.finish();
  }
  hydro::CurrentProfile profile;
  if (current.IsDefined()) {
    MapReader cr(ctx.diag, current, env.key_path("current"));
    if (cr.valid())
      if (auto c = read_current(cr)) profile = std::move(*c);
    cr.finish();
  }
  hydro::WaveField field(depth, g, rho, std::move(components), ramp, wheeler);
  const auto& comps = field.components();
  const bool spread = std::any_of(comps.begin(), comps.end(), [&](const hydro::WaveComponent& c) {
    return c.direction != comps.front().direction;
  });
  if (grid && spread) {
    // checked here rather than left to WaveGrid, to name the key and the way out
    ctx.diag.error(waves["kinematics"].Mark(), kinematics_path,
                   "grid kinematics need a long-crested sea, and `spreading` spreads this one "
                   "over several directions: use kinematics: exact (the default)");
  } else if (grid && !comps.empty()) {
    try {
      field.set_grid(std::make_shared<const hydro::WaveGrid>(field, *grid));
    } catch (const std::invalid_argument& e) {
      // the spacings' own checks: too many levels (the loader checked the signs)
      const YAML::Node n = waves["grid"] ? waves["grid"] : waves["kinematics"];
      ctx.diag.error(n.Mark(), grid_path, e.what());
    }
  }
  ctx.model.ocean =
      std::make_shared<const hydro::Ocean>(rho, g, depth, std::move(field), std::move(profile));
  ctx.model.wave_probes.emplace_back("wave.eta", Vec3::Zero());
  if (probes.IsDefined()) {
    MapReader pr(ctx.diag, probes, env.key_path("wave_probes"));
    if (pr.valid())
      for (const auto& kv : probes) {
        if (!kv.first.IsScalar()) {
          ctx.diag.error(kv.first.Mark(), pr.path(),
                         fmt::format("a wave probe's name must be plain text, got {} as a key",
                                     describe(kv.first)));
          continue;
        }
        const std::string name = kv.first.Scalar();
        pr.has(name);
        if (const std::string problem = name_problem(name, "wave probe", "wave.eta.<name>");
            !problem.empty()) {
          ctx.diag.error(kv.first.Mark(), name_key(pr.path(), name), problem);
          continue;
        }
        const YAML::Node& xy = kv.second;
        if (!xy.IsSequence() || xy.size() != 2) {
          ctx.diag.error(xy.Mark(), pr.key_path(name), "expected [x, y] in m");
          continue;
        }
        const auto x = read_number(ctx.diag, xy[0], pr.key_path(name), NumberRule::any("m"));
        const auto y = read_number(ctx.diag, xy[1], pr.key_path(name), NumberRule::any("m"));
        if (x && y)
          ctx.model.wave_probes.emplace_back(fmt::format("wave.eta.{}", name), Vec3(*x, *y, 0));
      }
  }
}

void load_hydrodynamics(const YAML::Node& node, LoadContext& ctx) {
  MapReader top(ctx.diag, node, "hydrodynamics");
  if (!top.valid()) return;
  if (!ctx.model.ocean) {
    ctx.diag.error(node.Mark(), "hydrodynamics",
                   "needs environment.water (density and depth): there is no sea to act");
    return;
  }
  for (const auto& kv : node) {
    if (!kv.first.IsScalar()) {
      ctx.diag.error(kv.first.Mark(), "hydrodynamics",
                     fmt::format("expected a body's name as the key, got {}", describe(kv.first)));
      continue;
    }
    const std::string name = kv.first.Scalar();
    top.has(name);
    const std::string path = top.key_path(name);
    const Body* body = ctx.system.find_body(name);
    if (!body) {
      std::vector<std::string> names;
      for (const auto& b : ctx.system.bodies()) names.push_back(b->name());
      if (std::find(ctx.failed_bodies.begin(), ctx.failed_bodies.end(), name) ==
          ctx.failed_bodies.end())
        ctx.diag.error(kv.first.Mark(), path,
                       fmt::format("no body named '{}'; {}", name, suggestion(name, names)));
      continue;
    }
    MapReader r(ctx.diag, kv.second, path);
    if (!r.valid()) continue;
    if (const auto* beam = dynamic_cast<const AncfBeam*>(body))
      load_beam_hydro(r, *beam, ctx);
    else if (const auto* rigid = dynamic_cast<const RigidBody*>(body)) {
      load_rigid_hydro(r, *rigid, ctx);
      r.finish();
    } else {
      r.error("", fmt::format("body '{}' is a {}: hydrodynamics apply to ancf_beam and "
                              "rigid_body bodies",
                              name, body->kind()));
    }
  }
}

}  // namespace seaflex::io
