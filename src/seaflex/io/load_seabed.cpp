// environment.seabed: the seabed's shape (flat at the water depth, a sloped plane, or a
// bathymetry grid from a file) and its contact properties; every ANCF beam (or the ones
// listed in `lines`) then touches it along its length (forces/seabed_contact.hpp), and the
// rigid-body points listed in `points` touch it too (forces/rigid_body_seabed_contact.hpp).
// Format: docs/model-format.md section 4.5.
#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <map>
#include <numbers>
#include <set>
#include <sstream>

#include "seaflex/core/errors.hpp"
#include "seaflex/core/input_file.hpp"
#include "seaflex/forces/morison_beam.hpp"
#include "seaflex/forces/rigid_body_seabed_contact.hpp"
#include "seaflex/forces/seabed_contact.hpp"
#include "seaflex/io/load_context.hpp"

namespace seaflex::io {

namespace {

constexpr double kRad = std::numbers::pi / 180.0;

// a bathymetry table: rows x, y, depth (m), comma or white-space separated, '#' comments,
// an optional header line; every (x, y) of a rectangular grid exactly once
std::shared_ptr<const hydro::Seabed> read_grid(MapReader& r, const LoadContext& ctx) {
  const auto file = r.text("file", Need::kRequired);
  if (!file) return nullptr;
  std::filesystem::path path(*file);
  if (path.is_relative()) path = std::filesystem::path(ctx.diag.file()).parent_path() / path;
  std::istringstream in;
  try {
    in.str(read_input_file(path.string(), "bathymetry file", kMaxDataFileBytes));
  } catch (const InputError& e) {
    for (const auto& d : e.diagnostics()) r.error("file", d.format());
    return nullptr;
  }
  auto problem = [&](int line, const std::string& m) {
    r.error("file", fmt::format("{}:{}: {}", *file, line, m));
  };
  std::map<std::pair<double, double>, std::pair<double, int>> points;  // (x, y) -> depth, line
  std::string line;
  int n = 0;
  bool first = true;
  while (std::getline(in, line)) {
    ++n;
    const auto s = line.find_first_not_of(" \t\r");
    if (s == std::string::npos || line[s] == '#') continue;
    for (char& c : line)
      if (c == ',' || c == ';' || c == '\t' || c == '\r') c = ' ';
    std::istringstream words(line);
    std::vector<std::string> fields;
    for (std::string w; words >> w;) fields.push_back(w);
    std::vector<double> v;
    for (const auto& f : fields) {
      double x = 0.0;
      const char* b = f.data() + (f[0] == '+' ? 1 : 0);
      const auto [ptr, err] = std::from_chars(b, f.data() + f.size(), x);
      if (err != std::errc() || ptr != f.data() + f.size() || !std::isfinite(x)) break;
      v.push_back(x);
    }
    if (first && v.size() != fields.size()) {  // a header line
      first = false;
      continue;
    }
    first = false;
    if (fields.size() != 3 || v.size() != 3) {
      problem(n, "expected three numbers x, y, depth (m) on each row");
      return nullptr;
    }
    if (!(v[2] > 0.0)) {
      problem(n,
              fmt::format("depth: must be > 0 m (below the mean surface z = 0), got {} m", v[2]));
      return nullptr;
    }
    const auto [it, fresh] = points.emplace(std::pair{v[0], v[1]}, std::pair{v[2], n});
    if (!fresh) {
      problem(n, fmt::format("the point ({}, {}) repeats line {}", v[0], v[1], it->second.second));
      return nullptr;
    }
  }
  std::set<double> xs, ys;
  for (const auto& [xy, d] : points) {
    xs.insert(xy.first);
    ys.insert(xy.second);
  }
  if (xs.size() < 2 || ys.size() < 2) {
    r.error("file", fmt::format("{}: a bathymetry grid needs at least two distinct x and two "
                                "distinct y values, got {} and {}",
                                *file, xs.size(), ys.size()));
    return nullptr;
  }
  std::vector<double> depths;
  for (double y : ys)
    for (double x : xs) {
      const auto it = points.find({x, y});
      if (it == points.end()) {
        r.error("file", fmt::format("{}: the grid is not rectangular: no depth at x = {}, y = {} "
                                    "(give every combination of its {} x and {} y values)",
                                    *file, x, y, xs.size(), ys.size()));
        return nullptr;
      }
      depths.push_back(it->second.first);
    }
  return std::make_shared<const hydro::Seabed>(
      hydro::Seabed::grid(std::vector<double>(xs.begin(), xs.end()),
                          std::vector<double>(ys.begin(), ys.end()), std::move(depths)));
}

// one entry of environment.seabed.points: {body, points, area | stiffness, friction}; the
// body is checked once the bodies are read
struct PointEntry {
  YAML::Node node;
  std::string path;
  std::vector<Vec3> points;
  double stiffness = 0.0;  // per point (N/m), or the area (m^2) when by_area
  bool by_area = false;
  std::optional<double> friction;
};

std::optional<PointEntry> read_point_entry(Diagnostics& diag, const YAML::Node& node,
                                           const std::string& path) {
  MapReader r(diag, node, path);
  if (!r.valid()) return std::nullopt;
  PointEntry e;
  e.node = node;
  e.path = path;
  bool ok = r.get("body", Need::kRequired).IsDefined();
  const YAML::Node pts = r.get("points", Need::kRequired);
  if (pts.IsDefined()) {
    if (!pts.IsSequence() || pts.size() == 0 || pts[0].IsScalar()) {
      r.error("points", fmt::format("expected a list of points [x, y, z] (m, body axes from the "
                                    "centre of gravity; one point is [[x, y, z]]), got {}",
                                    !pts.IsSequence() ? describe(pts)
                                    : pts.size() == 0 ? std::string("an empty list")
                                                      : std::string("a list of numbers")));
      ok = false;
    } else {
      for (std::size_t i = 0; i < pts.size(); ++i) {
        const auto v = read_vec3(diag, pts[i], fmt::format("{}.points[{}]", path, i), "m");
        if (v)
          e.points.push_back(*v);
        else
          ok = false;
      }
    }
  } else {
    ok = false;
  }
  const bool has_area = r.has("area"), has_stiffness = r.has("stiffness");
  if (has_area && has_stiffness) {
    r.error("stiffness", "give either area (m^2 per point) or stiffness (N/m per point), not both");
    ok = false;
  } else if (!has_area && !has_stiffness) {
    r.error("",
            "give area (m^2 per point: k = normal_stiffness x area) or stiffness (N/m per "
            "point)");
    ok = false;
  } else {
    e.by_area = has_area;
    const auto v = has_area ? r.number("area", Need::kRequired, NumberRule::positive("m^2"))
                            : r.number("stiffness", Need::kRequired, NumberRule::positive("N/m"));
    if (v)
      e.stiffness = *v;
    else
      ok = false;
  }
  if (r.has("friction")) {
    e.friction = r.number("friction", Need::kRequired, NumberRule::range(0.0, 10.0, ""));
    if (!e.friction) ok = false;
  }
  r.finish();
  if (!ok) return std::nullopt;
  return e;
}

}  // namespace

void load_seabed(MapReader& env, LoadContext& ctx) {
  if (!env.has("seabed")) return;
  MapReader r(ctx.diag, env.get("seabed"), env.key_path("seabed"));
  if (!r.valid()) return;
  const auto shape = r.choice("shape", Need::kOptional, {"flat", "plane", "grid"}).value_or("flat");
  const double depth = ctx.model.ocean ? ctx.model.ocean->depth() : 0.0;
  std::shared_ptr<const hydro::Seabed> seabed;
  if (shape == "grid") {
    seabed = read_grid(r, ctx);
  } else if (!ctx.model.ocean || !std::isfinite(depth)) {
    r.error("shape", fmt::format("a {} seabed lies at the water depth: give environment.water "
                                 "a finite depth (m)",
                                 shape));
  } else if (shape == "flat") {
    seabed = std::make_shared<const hydro::Seabed>(hydro::Seabed::flat(depth));
  } else {
    const auto slope = r.number("slope", Need::kRequired, NumberRule::range(0.0, 60.0, "deg"));
    const double direction =
        r.number("direction", Need::kOptional, NumberRule::range(-360, 360, "deg")).value_or(0.0);
    if (slope)
      seabed = std::make_shared<const hydro::Seabed>(
          hydro::Seabed::plane(depth, *slope * kRad, direction * kRad));
  }
  SeabedContactProperties p;
  const auto k = r.number("normal_stiffness", Need::kRequired, NumberRule::positive("N/m/m^2"));
  p.damping = r.number("damping", Need::kOptional, NumberRule::range(0.0, 10.0, "")).value_or(0.0);
  if (const YAML::Node f = r.get("friction"); f.IsDefined()) {
    if (f.IsMap()) {
      MapReader fr(ctx.diag, f, r.key_path("friction"));
      p.friction_axial =
          fr.number("axial", Need::kRequired, NumberRule::range(0.0, 10.0, "")).value_or(0.0);
      p.friction_lateral =
          fr.number("lateral", Need::kRequired, NumberRule::range(0.0, 10.0, "")).value_or(0.0);
      fr.finish();
    } else {
      const double mu =
          r.number("friction", Need::kOptional, NumberRule::range(0.0, 10.0, "")).value_or(0.0);
      p.friction_axial = p.friction_lateral = mu;
    }
  }
  p.slip_velocity =
      r.number("slip_velocity", Need::kOptional, NumberRule::positive("m/s")).value_or(0.01);
  p.gauss_points = r.integer("gauss_points", Need::kOptional, 1, 20).value_or(5);
  std::vector<std::string> lines;
  bool lines_ok = true;
  bool lines_given = false;  // absent: every beam; a list (even empty): those listed
  if (const YAML::Node l = r.get("lines"); l.IsDefined()) {
    lines_given = true;
    if (!l.IsSequence()) {
      r.error("lines", "expected a list of beam names");
      lines_ok = false;
    } else {
      for (const auto& e : l) lines.push_back(e.Scalar());
    }
  }
  std::vector<PointEntry> entries;
  bool points_ok = true;
  if (const YAML::Node l = r.get("points"); l.IsDefined()) {
    if (!l.IsSequence()) {
      r.error("points", "expected a list of {body, points, area or stiffness} entries");
      points_ok = false;
    } else {
      for (std::size_t i = 0; i < l.size(); ++i) {
        const std::string at = fmt::format("{}[{}]", r.key_path("points"), i);
        auto e = read_point_entry(ctx.diag, l[i], at);
        if (!e) {
          points_ok = false;
          continue;
        }
        // a point has no line axis: one coefficient, the seabed's when it gives one
        if (!e->friction && p.friction_axial != p.friction_lateral) {
          ctx.diag.error(l[i].Mark(), at,
                         fmt::format("the seabed's friction differs along and across lines "
                                     "(axial {:g}, lateral {:g}): give these points their own "
                                     "friction (one coefficient)",
                                     p.friction_axial, p.friction_lateral));
          points_ok = false;
          continue;
        }
        entries.push_back(std::move(*e));
      }
    }
  }
  const YAML::Mark mark = r.mark();
  const std::string path = r.path();
  r.finish();
  if (!seabed || !k || !lines_ok || !points_ok) return;
  p.normal_stiffness = *k;
  ctx.model.seabed = seabed;
  if (!entries.empty())
    ctx.after_bodies.push_back([seabed, p, entries](LoadContext& c) {
      std::set<std::string> seen;
      for (const auto& e : entries) {
        MapReader r(c.diag, e.node, e.path);
        const Body* body = c.body_ref(r, "body", false, nullptr);
        if (!body) continue;
        const auto* rigid = dynamic_cast<const RigidBody*>(body);
        if (!rigid) {
          r.error("body", fmt::format("'{}' is an {}, not a rigid body: beams touch the seabed "
                                      "along their length (environment.seabed.lines)",
                                      body->name(), body->kind()));
          continue;
        }
        if (!seen.insert(rigid->name()).second) {
          r.error("body", fmt::format("'{}' is listed twice: give all its points in one entry",
                                      rigid->name()));
          continue;
        }
        std::vector<SeabedContactPoint> points;
        const double k_point = e.by_area ? p.normal_stiffness * e.stiffness : e.stiffness;
        for (const auto& u : e.points) points.push_back({u, k_point});
        PointContactProperties pp;
        pp.damping = p.damping;
        pp.friction = e.friction.value_or(p.friction_lateral);
        pp.slip_velocity = p.slip_velocity;
        c.system.add_force(std::make_unique<RigidBodySeabedContact>(
            fmt::format("{}.seabed", rigid->name()), *rigid, seabed, std::move(points), pp));
      }
    });
  // the lines touch it once every body and its hydrodynamics are known
  ctx.after_bodies.push_back([seabed, p, lines, lines_given, mark, path](LoadContext& c) {
    std::vector<std::string> beams;
    for (const auto& b : c.system.bodies())
      if (dynamic_cast<const AncfBeam*>(b.get())) beams.push_back(b->name());
    for (const auto& name : lines)
      if (std::find(beams.begin(), beams.end(), name) == beams.end())
        c.diag.error(mark, path + ".lines",
                     fmt::format("no beam named '{}'; {}", name, suggestion(name, beams)));
    for (const auto& b : c.system.bodies()) {
      const auto* beam = dynamic_cast<const AncfBeam*>(b.get());
      if (!beam ||
          (lines_given && std::find(lines.begin(), lines.end(), beam->name()) == lines.end()))
        continue;
      // the contact width of each section: its outer diameter, or else its Morison diameter
      const MorisonBeam* morison = nullptr;
      for (const auto& f : c.system.forces())
        if (const auto* m = dynamic_cast<const MorisonBeam*>(f.get()); m && &m->beam() == beam)
          morison = m;
      std::vector<double> widths, masses;
      for (std::size_t i = 0; i < beam->sections().size(); ++i) {
        double width = beam->sections()[i].outer_diameter;
        if (!(width > 0.0) && morison) width = morison->coefficients(static_cast<int>(i)).diameter;
        widths.push_back(width);
        masses.push_back(beam->sections()[i].mass_per_length());
      }
      if (!(*std::min_element(widths.begin(), widths.end()) > 0.0)) {
        c.diag.error(mark, path,
                     fmt::format("line '{}' has no contact width: give bodies.{}.outer_diameter "
                                 "or a Morison diameter in hydrodynamics.{}, or leave it out of "
                                 "{}.lines",
                                 beam->name(), beam->name(), beam->name(), path));
        continue;
      }
      c.system.add_force(std::make_unique<SeabedContact>(fmt::format("{}.seabed", beam->name()),
                                                         *beam, seabed, p, widths, masses));
    }
  });
}

}  // namespace seaflex::io
