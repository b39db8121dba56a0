// environment.seabed: the seabed's shape (flat at the water depth, a sloped plane, or a
// bathymetry grid from a file) and its contact properties; every ANCF beam (or the ones
// listed in `lines`) then touches it along its length (forces/seabed_contact.hpp).
// Format: docs/model-format.md section 4.4.
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
  if (const YAML::Node l = r.get("lines"); l.IsDefined()) {
    if (!l.IsSequence()) {
      r.error("lines", "expected a list of beam names");
      lines_ok = false;
    } else {
      for (const auto& e : l) lines.push_back(e.Scalar());
    }
  }
  const YAML::Mark mark = r.mark();
  const std::string path = r.path();
  r.finish();
  if (!seabed || !k || !lines_ok) return;
  p.normal_stiffness = *k;
  ctx.model.seabed = seabed;
  // the lines touch it once every body and its hydrodynamics are known
  ctx.after_bodies.push_back([seabed, p, lines, mark, path](LoadContext& c) {
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
          (!lines.empty() && std::find(lines.begin(), lines.end(), beam->name()) == lines.end()))
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
