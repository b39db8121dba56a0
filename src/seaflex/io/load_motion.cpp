// `motion:` of a rigid body, a ground marker or a beam support (model/motion.hpp):
//   free (rigid bodies only: the body floats, the default), or a mapping with a type from
//   the registry below: constant_velocity, harmonic, table, rao. Common keys: origin (m,
//   the point the rotations turn about; default the body's position, the marker's point
//   or the node) and ramp (s, a quintic ramp in from rest).
// Files (the table's CSV, the RAO table, the drift table) are read relative to the model
// file; their problems are reported at the key that names the file, with the file's own
// line and column: "motion.file: heave.csv:7:1: t: ...".
#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <sstream>

#include "seaflex/core/input_file.hpp"
#include "seaflex/hydro/rao_motion.hpp"
#include "seaflex/io/load_context.hpp"
#include "seaflex/model/table_motion.hpp"

namespace seaflex::io {

namespace {

constexpr double kRad = std::numbers::pi / 180.0;
const std::vector<std::string> kTableColumns{"t", "x", "y", "z", "roll", "pitch", "yaw"};
const Vec6 kDofScale = (Vec6() << 1.0, 1.0, 1.0, kRad, kRad, kRad).finished();

std::string resolve(const std::string& file, const LoadContext& ctx) {
  std::filesystem::path p(file);
  if (p.is_relative()) p = std::filesystem::path(ctx.diag.file()).parent_path() / p;
  return p.string();
}

// six numbers (m, m, m, deg, deg, deg) or, when allow_scalar, one number for all six
std::optional<Vec6> read_six(MapReader& r, std::string_view key, Need need, bool allow_scalar,
                             const std::string& unit) {
  const YAML::Node n = r.get(key, need,
                             "a list of six numbers (surge, sway, heave, roll, pitch, "
                             "yaw)");
  if (!n.IsDefined()) return std::nullopt;
  Vec6 v;
  if (allow_scalar && n.IsScalar()) {
    const auto x = read_number(r.diagnostics(), n, r.key_path(key), NumberRule::any(unit));
    if (!x) return std::nullopt;
    v.setConstant(*x);
    return v;
  }
  if (!n.IsSequence() || n.size() != 6) {
    r.error(key, fmt::format("expected six numbers [surge, sway, heave, roll, pitch, yaw] in {}{}, "
                             "got {}",
                             unit, allow_scalar ? " (or one number for all)" : "", describe(n)));
    return std::nullopt;
  }
  for (int i = 0; i < 6; ++i) {
    const auto x = read_number(r.diagnostics(), n[i], fmt::format("{}[{}]", r.key_path(key), i),
                               NumberRule::any(unit));
    if (!x) return std::nullopt;
    v[i] = *x;
  }
  return v;
}

// a CSV time table t, x, y, z, roll, pitch, yaw (s, m, deg): its problems are reported at
// the file key with the CSV's line and column
std::shared_ptr<const Motion> read_table_file(MapReader& r, std::string_view key,
                                              const LoadContext& ctx) {
  const auto file = r.text(key, Need::kRequired);
  if (!file) return nullptr;
  const std::string path = resolve(*file, ctx);
  auto problem = [&](int line, int column, const std::string& column_name, const std::string& m) {
    r.error(key, fmt::format("{}:{}:{}: {}: {}", *file, line, column, column_name, m));
  };
  std::istringstream in;
  try {
    in.str(read_input_file(path, "motion table", kMaxDataFileBytes));
  } catch (const InputError& e) {
    for (const auto& d : e.diagnostics()) r.error(key, d.format());
    return nullptr;
  }
  std::vector<double> times;
  std::vector<Vec6> values;
  std::string line;
  int n = 0, problems = 0;
  bool first = true;
  while (std::getline(in, line) && problems < 10) {
    ++n;
    const auto s = line.find_first_not_of(" \t\r");
    if (s == std::string::npos || line[s] == '#') continue;
    // fields separated by commas (or white space), with their 1-based columns
    std::vector<std::pair<std::string, int>> fields;
    std::size_t i = 0;
    while (i <= line.size()) {
      std::size_t j = line.find(',', i);
      if (j == std::string::npos) j = line.size();
      std::string f = line.substr(i, j - i);
      const auto a = f.find_first_not_of(" \t\r"), b = f.find_last_not_of(" \t\r");
      const int col = static_cast<int>(i + (a == std::string::npos ? 0 : a)) + 1;
      f = a == std::string::npos ? std::string() : f.substr(a, b - a + 1);
      std::istringstream words(f);
      std::string w;
      bool any = false;
      while (words >> w) {
        fields.emplace_back(w, col);
        any = true;
      }
      if (!any) fields.emplace_back("", col);
      i = j + 1;
    }
    double v = 0.0;
    auto parse = [&](const std::string& text) {
      const char* b = text.data();
      const char* e = b + text.size();
      if (b != e && *b == '+') ++b;
      const auto [ptr, ec] = std::from_chars(b, e, v);
      return !text.empty() && ec == std::errc() && ptr == e;
    };
    if (first && !parse(fields[0].first)) {  // a header line
      first = false;
      continue;
    }
    first = false;
    if (fields.size() < kTableColumns.size()) {
      problem(n, 0, kTableColumns[fields.size()],
              fmt::format("missing: the row has {} of 7 columns (t, x, y, z, roll, pitch, yaw in "
                          "s, m, deg)",
                          fields.size()));
      ++problems;
      continue;
    }
    Vec6 row;
    double t = 0.0;
    bool ok = true;
    for (std::size_t c = 0; c < kTableColumns.size(); ++c) {
      if (!parse(fields[c].first) || !std::isfinite(v)) {
        problem(n, fields[c].second, kTableColumns[c],
                fmt::format("expected a finite number, got '{}'", fields[c].first));
        ++problems;
        ok = false;
        continue;
      }
      if (c == 0)
        t = v;
      else
        row[c - 1] = v * kDofScale[c - 1];
    }
    if (!ok) continue;
    if (!times.empty() && !(t > times.back())) {
      problem(n, fields[0].second, "t",
              fmt::format("time must increase strictly down the table: {:g} s follows {:g} s", t,
                          times.back()));
      ++problems;
      continue;
    }
    times.push_back(t);
    values.push_back(row);
  }
  if (problems > 0) return nullptr;
  if (times.size() < 2) {
    r.error(key, fmt::format("{}: too few rows: a motion table needs at least 2 (got {})", *file,
                             times.size()));
    return nullptr;
  }
  return std::make_shared<TableMotion>(std::move(times), std::move(values));
}

std::shared_ptr<const Motion> read_rao_motion(MapReader& r, const Vec3& origin, LoadContext& ctx) {
  const bool has_file = r.has("file"), has_wamit = r.has("wamit");
  const auto phase = r.choice("phase", Need::kOptional, {"lead", "lag"});
  const auto reference =
      r.choice("phase_reference", Need::kOptional, {"rao_origin", "global_origin"});
  const auto ulen = r.number("ulen", Need::kOptional, NumberRule::positive("m"));
  std::shared_ptr<const Motion> drift;
  if (r.has("drift")) drift = read_table_file(r, "drift", ctx);
  if (has_file == has_wamit) {
    r.error(has_wamit ? "wamit" : "file",
            "give the RAOs as either file (the plain table) or wamit (a WAMIT .4 file)");
    return nullptr;
  }
  if (ulen && !has_wamit) r.error("ulen", "applies only to a WAMIT .4 file (wamit)");
  const std::string_view key = has_file ? "file" : "wamit";
  const auto file = r.text(key, Need::kRequired);
  if (!file) return nullptr;
  if (!ctx.model.ocean || !ctx.model.ocean->has_waves()) {
    r.error("type",
            "a RAO motion is the response to the model's waves, but the model has no "
            "environment.waves");
    return nullptr;
  }
  const hydro::RaoPhase ph =
      phase.value_or("lead") == "lead" ? hydro::RaoPhase::kLead : hydro::RaoPhase::kLag;
  hydro::RaoTable table;
  try {
    table = has_file ? hydro::read_rao_table(resolve(*file, ctx), ph)
                     : hydro::read_wamit_rao(resolve(*file, ctx), ulen.value_or(1.0), ph);
  } catch (const InputError& e) {
    for (const auto& d : e.diagnostics())
      r.error(key, d.line > 0 ? fmt::format("{}:{}: {}: {}", *file, d.line, d.key, d.message)
                              : fmt::format("{}: {}: {}", *file, d.key, d.message));
    return nullptr;
  }
  const auto ref = reference.value_or("rao_origin") == "rao_origin"
                       ? hydro::RaoPhaseReference::kRaoOrigin
                       : hydro::RaoPhaseReference::kGlobalOrigin;
  int clamped = 0;
  auto motion = std::make_shared<hydro::RaoMotion>(table, ctx.model.ocean->waves().components(),
                                                   origin, ref, &clamped);
  if (clamped > 0) {
    const auto& h = table.data.headings;
    r.error(key, fmt::format("the RAO headings ({:g} to {:g} deg) do not cover the waves: {} "
                             "wave component(s) travel in a direction outside them; give RAOs "
                             "for every wave heading (seaflex does not extrapolate in heading)",
                             h.front() / kRad, h.back() / kRad, clamped));
    return nullptr;
  }
  if (drift) return std::make_shared<hydro::SumMotion>(std::move(motion), std::move(drift));
  return motion;
}

}  // namespace

std::optional<MotionEntry> read_motion(MapReader& owner, std::string_view key,
                                       const Vec3& default_origin, bool allow_free,
                                       LoadContext& ctx) {
  MotionEntry entry;
  entry.origin = default_origin;
  const YAML::Node n = owner.get(key);
  if (!n.IsDefined()) return entry;
  if (n.IsScalar() && n.Scalar() == "free") {
    if (!allow_free) {
      owner.error(key,
                  "'free' applies to rigid bodies only; here give a motion mapping with a "
                  "type (constant_velocity, harmonic, table, rao)");
      return std::nullopt;
    }
    return entry;
  }
  MapReader r(ctx.diag, n, owner.key_path(key));
  if (!r.valid()) return std::nullopt;
  const auto type =
      r.choice("type", Need::kRequired, {"constant_velocity", "harmonic", "table", "rao"});
  const std::size_t errors = ctx.diag.count();
  if (const auto o = r.vec3("origin", Need::kOptional, "m")) entry.origin = *o;
  const auto ramp = r.number("ramp", Need::kOptional, NumberRule::positive("s"));
  std::shared_ptr<const Motion> m;
  if (type == "constant_velocity") {
    Vec6 v = Vec6::Zero();
    if (const auto u = r.vec3("velocity", Need::kOptional, "m/s")) v.head<3>() = *u;
    if (const auto w = r.vec3("angular_velocity", Need::kOptional, "deg/s (roll, pitch, yaw)"))
      v.tail<3>() = *w * kRad;
    m = std::make_shared<ConstantVelocityMotion>(v);
  } else if (type == "harmonic") {
    const auto a = read_six(r, "amplitude", Need::kRequired, false, "m, deg");
    const auto T = read_six(r, "period", Need::kRequired, true, "s");
    const auto ph = read_six(r, "phase", Need::kOptional, true, "deg");
    if (a && T) {
      bool ok = true;
      for (int i = 0; i < 6; ++i)
        if ((*a)[i] != 0.0 && !((*T)[i] > 0.0)) {
          r.error("period", fmt::format("must be positive where the amplitude is not zero; "
                                        "entry {} is {:g} s",
                                        i, (*T)[i]));
          ok = false;
          break;
        }
      if (ok)
        m = std::make_shared<HarmonicMotion>(a->cwiseProduct(kDofScale), *T,
                                             ph.value_or(Vec6::Zero()) * kRad);
    }
  } else if (type == "table") {
    m = read_table_file(r, "file", ctx);
  } else if (type == "rao") {
    m = read_rao_motion(r, entry.origin, ctx);
  }
  r.finish();
  if (!type || !m || ctx.diag.count() != errors) return std::nullopt;
  if (ramp) m = std::make_shared<RampedMotion>(std::move(m), *ramp);
  entry.motion = std::move(m);
  return entry;
}

}  // namespace seaflex::io
