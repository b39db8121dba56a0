// connections: force elements between markers: spring (a spring-damper between two
// points), rope (a tension-only wire through a path of points, with reeving parts),
// pneumatic_cylinder (the gas spring with Stribeck friction of a riser tensioner, thesis
// eq. 184-185), and tensioner (a constant tension with stroke limits, constant_tensioner.hpp).
#include <fmt/format.h>

#include <limits>
#include <set>

#include "seaflex/forces/constant_tensioner.hpp"
#include "seaflex/forces/pneumatic_cylinder.hpp"
#include "seaflex/forces/rope.hpp"
#include "seaflex/forces/spring_damper.hpp"
#include "seaflex/io/load_context.hpp"

namespace seaflex::io {

namespace {

// the two ends of a spring or cylinder: on different bodies, not both on ground
bool check_ends(MapReader& r, const std::string& name, const Marker& from, const Marker& to) {
  if (from.body() == nullptr && to.body() == nullptr) {
    r.error("to", fmt::format("connection '{}' connects ground to ground", name));
    return false;
  }
  if (from.body() == to.body()) {
    r.error("to",
            fmt::format("connection '{}' connects body '{}' to itself", name, from.body()->name()));
    return false;
  }
  return true;
}

void load_spring(MapReader& r, const YAML::Node& node, const std::string& path,
                 std::set<std::string>& names, LoadContext& ctx) {
  const auto entry = read_pair(r, names, "connection");
  const auto free_length = r.number("free_length", Need::kRequired, NumberRule::nonnegative("m"));
  const bool linear = r.has("stiffness"), tabled = r.has("tension_table");
  std::optional<SpringLaw> law;
  if (linear && tabled) {
    r.error("tension_table", "give either stiffness or tension_table, not both");
  } else if (tabled) {
    if (const auto rows = r.table("tension_table", Need::kRequired, 2, "extensions")) {
      std::vector<double> x, t;
      for (const auto& row : *rows) {
        x.push_back(row[0]);
        t.push_back(row[1]);
      }
      try {
        law = SpringLaw::table(std::move(x), std::move(t));
      } catch (const std::invalid_argument&) {
        r.error("tension_table",
                "expected two or more rows [extension (m), tension (N)] with extensions "
                "increasing strictly");
      }
    }
  } else if (const auto k =
                 r.number("stiffness", Need::kRequired, NumberRule::nonnegative("N/m"))) {
    law = SpringLaw::linear(*k);
  }
  std::optional<double> damping = 0.0;
  if (r.has("damping"))
    damping = r.number("damping", Need::kRequired, NumberRule::nonnegative("N s/m"));
  const auto slack = read_bool(r, "slack");
  auto [from, to] = read_markers(r, entry, ctx);
  r.finish();
  if (!entry.name || !free_length || !law || !damping || !slack || !from || !to) return;
  if (!check_ends(r, *entry.name, *from, *to)) return;
  ctx.connection_origin[*entry.name] = {node.Mark(), path};
  ctx.system.add_force(std::make_unique<SpringDamper>(*entry.name, std::move(from), std::move(to),
                                                      *free_length, std::move(*law), *damping,
                                                      *slack));
}

void load_rope(MapReader& r, const YAML::Node& node, const std::string& path,
               std::set<std::string>& names, LoadContext& ctx) {
  const auto name = read_entry_name(r, names, "connection");
  const YAML::Node pnode = r.get("path", Need::kRequired,
                                 "a list of two or more markers: the points the rope runs through");
  const auto ea = r.number("axial_stiffness", Need::kRequired, NumberRule::positive("N"));
  std::optional<double> damping = 0.0;
  if (r.has("damping"))
    damping = r.number("damping", Need::kRequired, NumberRule::nonnegative("N s/m"));
  const bool by_length = r.has("free_length"), by_tension = r.has("initial_tension");
  std::optional<double> free_length, initial_tension;
  if (by_length && by_tension)
    r.error("initial_tension", "give either free_length or initial_tension, not both");
  else if (by_tension)
    initial_tension = r.number("initial_tension", Need::kRequired, NumberRule::nonnegative("N"));
  else
    free_length = r.number("free_length", Need::kRequired, NumberRule::positive("m"));

  // a winch: the free length changes at a constant rate or by a time table
  std::optional<Winch> winch;
  bool winch_ok = true;
  if (const YAML::Node wn = r.get("winch"); wn.IsDefined()) {
    MapReader w(ctx.diag, wn, r.key_path("winch"));
    winch_ok = false;
    if (w.valid()) {
      const bool by_rate = w.has("rate"), by_table = w.has("table");
      if (by_rate == by_table) {
        w.error(by_table ? "table" : "rate",
                "give either rate (m/s, paying out > 0) or table ([t, change] rows in s, m)");
        w.has("start");
      } else if (by_rate) {
        const auto rate = w.number("rate", Need::kRequired, NumberRule::any("m/s"));
        const auto start = w.number("start", Need::kOptional, NumberRule::nonnegative("s"));
        if (rate) {
          winch = Winch::constant_rate(*rate, start.value_or(0.0));
          winch_ok = true;
        }
      } else if (const auto t = w.table("table", Need::kRequired, 2)) {
        std::vector<double> times, changes;
        for (const auto& row : *t) {
          times.push_back(row[0]);
          changes.push_back(row[1]);
        }
        if (times.size() < 2) {
          w.error("table", "a winch table needs at least two rows");
        } else {
          winch = Winch::table(std::move(times), std::move(changes));
          winch_ok = true;
        }
      }
      w.finish();
    }
  }

  // the points
  std::vector<std::unique_ptr<Marker>> points;
  bool points_ok = pnode.IsDefined();
  if (pnode.IsDefined()) {
    if (!pnode.IsSequence() || pnode.size() < 2) {
      r.error("path", "expected a list of two or more markers (names or {body: ..., ...})");
      points_ok = false;
    } else {
      for (std::size_t k = 0; k < pnode.size(); ++k) {
        auto m = ctx.marker(pnode[k], fmt::format("{}[{}]", r.key_path("path"), k));
        points_ok = points_ok && m != nullptr;
        points.push_back(std::move(m));
      }
    }
  }
  // parts per segment
  std::vector<int> parts;
  bool parts_ok = true;
  if (const YAML::Node n = r.get("parts"); n.IsDefined()) {
    const std::size_t want = points_ok ? points.size() - 1 : 0;
    if (!n.IsSequence() || (points_ok && n.size() != want)) {
      r.error("parts", points_ok ? fmt::format("expected a list of {} whole number{} >= 1, one "
                                               "per segment of the path",
                                               want, want == 1 ? "" : "s")
                                 : std::string("expected a list of whole numbers >= 1, one per "
                                               "segment of the path"));
      parts_ok = false;
    } else {
      for (std::size_t k = 0; k < n.size(); ++k) {
        const auto v =
            read_integer(ctx.diag, n[k], fmt::format("{}[{}]", r.key_path("parts"), k), 1, 1000);
        parts_ok = parts_ok && v.has_value();
        parts.push_back(v.value_or(1));
      }
    }
  } else if (points_ok) {
    parts.assign(points.size() - 1, 1);
  }
  r.finish();
  if (!name || !ea || !damping || !(free_length || initial_tension) || !points_ok || !parts_ok ||
      !winch_ok)
    return;
  std::set<const Body*> bodies;
  for (const auto& m : points) bodies.insert(m->body());
  if (bodies.size() < 2) {
    r.error("path",
            fmt::format("every point of rope '{}' is on {}: its length cannot change", *name,
                        *bodies.begin() ? fmt::format("body '{}'", (*bodies.begin())->name())
                                        : std::string("ground")));
    return;
  }
  // segment k joins points k and k + 1; an inner point serves two segments, so its marker
  // is built twice
  std::vector<MarkerPair> segments;
  for (std::size_t k = 0; k + 1 < points.size(); ++k) {
    std::unique_ptr<Marker> a =
        k == 0 ? std::move(points[0])
               : ctx.marker(pnode[k], fmt::format("{}[{}]", r.key_path("path"), k));
    segments.emplace_back(std::move(a), std::move(points[k + 1]));
  }
  auto rope = std::make_unique<Rope>(*name, std::move(segments), parts, free_length.value_or(1.0),
                                     *ea, *damping);
  if (winch) rope->set_winch(std::move(*winch));
  Rope* rp = rope.get();
  ctx.connection_origin[*name] = {node.Mark(), path};
  ctx.system.add_force(std::move(rope));
  ctx.at_start.push_back([rp, mark = node.Mark(), path, initial_tension, &ctx](const State& s0) {
    if (const int k = rp->first_vanishing_segment(s0); k >= 0) {
      ctx.diag.error(mark, path,
                     fmt::format("points {} and {} of rope '{}' coincide at the start, so the "
                                 "direction of that segment is undefined; place them apart",
                                 k, k + 1, rp->name()));
      return;
    }
    // T0 = EA (L - L0) / L0  =>  L0 = L / (1 + T0 / EA)
    if (initial_tension)
      rp->set_free_length(rp->length(s0) / (1.0 + *initial_tension / rp->axial_stiffness()));
  });
}

void load_cylinder(MapReader& r, const YAML::Node& node, const std::string& path,
                   std::set<std::string>& names, LoadContext& ctx) {
  const auto entry = read_pair(r, names, "connection");
  GasSpringLaw gas;
  const auto area = r.number("piston_area", Need::kRequired, NumberRule::positive("m^2"));
  const auto p0 = r.number("gas_pressure", Need::kRequired, NumberRule::positive("Pa"));
  const auto v0 = r.number("gas_volume", Need::kRequired, NumberRule::positive("m^3"));
  const auto n = r.has("polytropic_exponent") ? r.number("polytropic_exponent", Need::kRequired,
                                                         NumberRule::range(1.0, 1.67, ""))
                                              : std::optional<double>(1.0);
  StribeckFriction fr;
  bool friction_ok = true;
  if (const YAML::Node fnode = r.get("friction"); fnode.IsDefined()) {
    MapReader f(ctx.diag, fnode, r.key_path("friction"));
    if (!f.valid()) {
      friction_ok = false;
    } else {
      auto value = [&](const char* key, double fallback, const NumberRule& rule) {
        if (!f.has(key)) return fallback;
        const auto v = f.number(key, Need::kRequired, rule);
        friction_ok = friction_ok && v.has_value();
        return v.value_or(fallback);
      };
      fr.coulomb = value("coulomb", 0.0, NumberRule::nonnegative("N"));
      fr.static_friction = value("static", fr.coulomb, NumberRule::nonnegative("N"));
      fr.stribeck_velocity = value("stribeck_velocity", 0.01, NumberRule::positive("m/s"));
      fr.viscous = value("viscous", 0.0, NumberRule::nonnegative("N s/m"));
      fr.pressure_coefficient = value("pressure_coefficient", 0.0, NumberRule::nonnegative("m^2"));
      fr.max_pressure_friction =
          value("max_pressure_friction", std::numeric_limits<double>::infinity(),
                NumberRule::nonnegative("N"));
      fr.regularization_velocity =
          value("regularization_velocity", 1e-3, NumberRule::range(1e-9, 1.0, "m/s"));
      if (friction_ok && fr.static_friction < fr.coulomb) {
        f.error("static", fmt::format("static friction {} N is below the Coulomb friction {} N: "
                                      "Stribeck friction falls from static to Coulomb",
                                      fr.static_friction, fr.coulomb));
        friction_ok = false;
      }
      f.finish();
    }
  }
  auto [from, to] = read_markers(r, entry, ctx);
  r.finish();
  if (!entry.name || !area || !p0 || !v0 || !n || !friction_ok || !from || !to) return;
  if (!check_ends(r, *entry.name, *from, *to)) return;
  gas.piston_area = *area;
  gas.pressure = *p0;
  gas.volume = *v0;
  gas.exponent = *n;
  auto cyl =
      std::make_unique<PneumaticCylinder>(*entry.name, std::move(from), std::move(to), gas, fr);
  PneumaticCylinder* cp = cyl.get();
  ctx.connection_origin[*entry.name] = {node.Mark(), path};
  ctx.system.add_force(std::move(cyl));
  ctx.at_start.push_back([cp, mark = node.Mark(), path, &ctx](const State& s0) {
    const double L = cp->length(s0);
    if (!(L > 0.0))
      ctx.diag.error(mark, path,
                     fmt::format("the end points of cylinder '{}' coincide at the start, so the "
                                 "direction of its force is undefined; place its ends apart",
                                 cp->name()));
    cp->set_reference_length(L);  // the gas holds gas_volume at gas_pressure at the start
  });
}

// stroke_limits: [s_min, s_max] in m with s_min < 0 < s_max
std::optional<std::pair<double, double>> read_stroke_limits(MapReader& r) {
  const YAML::Node n = r.get("stroke_limits");
  const std::string key = r.key_path("stroke_limits");
  if (!n.IsSequence() || n.size() != 2) {
    r.error("stroke_limits",
            fmt::format("expected a list of two numbers [s_min, s_max] in m with s_min < 0 < "
                        "s_max, got {}",
                        n.IsSequence() ? fmt::format("{} entries", n.size()) : describe(n)));
    return std::nullopt;
  }
  const auto lo = read_number(r.diagnostics(), n[0], key + "[0]", NumberRule::any("m"));
  const auto hi = read_number(r.diagnostics(), n[1], key + "[1]", NumberRule::any("m"));
  if (!lo || !hi) return std::nullopt;
  if (!(*lo < 0.0 && *hi > 0.0)) {
    r.error("stroke_limits",
            fmt::format("expected [s_min, s_max] with s_min < 0 < s_max (the stroke counts from "
                        "the reference length), got [{}, {}]",
                        *lo, *hi));
    return std::nullopt;
  }
  return std::make_pair(*lo, *hi);
}

void load_tensioner(MapReader& r, const YAML::Node& node, const std::string& path,
                    std::set<std::string>& names, LoadContext& ctx) {
  const auto entry = read_pair(r, names, "connection");
  TensionerLaw law;
  const auto t0 = r.number("tension", Need::kRequired, NumberRule::positive("N"));
  auto optional = [&](const char* key, const NumberRule& rule) {
    return r.has(key) ? r.number(key, Need::kRequired, rule) : std::optional<double>(0.0);
  };
  const auto k = optional("stiffness", NumberRule::nonnegative("N/m"));
  const auto c = optional("damping", NumberRule::nonnegative("N s/m"));
  std::optional<double> reference = 0.0;
  if (r.has("reference_length"))
    reference = r.number("reference_length", Need::kRequired, NumberRule::positive("m"));
  bool stops_ok = true;
  const bool limited = r.has("stroke_limits");
  if (limited) {
    const auto limits = read_stroke_limits(r);
    std::optional<double> k_stop;
    if (r.has("stop_stiffness"))
      k_stop = r.number("stop_stiffness", Need::kRequired, NumberRule::positive("N/m"));
    else
      r.error("stop_stiffness",
              "required key is missing with stroke_limits (a number in N/m > 0: the stiffness "
              "of the end stops)");
    stops_ok = limits && k_stop;
    if (stops_ok) {
      law.stroke_min = limits->first;
      law.stroke_max = limits->second;
      law.stop_stiffness = *k_stop;
    }
  } else if (r.has("stop_stiffness")) {
    r.error("stop_stiffness",
            "applies only with stroke_limits: without them the stroke is unlimited");
    stops_ok = false;
  }
  auto [from, to] = read_markers(r, entry, ctx);
  r.finish();
  if (!entry.name || !t0 || !k || !c || !reference || !stops_ok || !from || !to) return;
  if (!check_ends(r, *entry.name, *from, *to)) return;
  law.tension = *t0;
  law.stiffness = *k;
  law.damping = *c;
  auto tensioner =
      std::make_unique<ConstantTensioner>(*entry.name, std::move(from), std::move(to), law);
  ConstantTensioner* tp = tensioner.get();
  ctx.connection_origin[*entry.name] = {node.Mark(), path};
  ctx.system.add_force(std::move(tensioner));
  const double given = *reference;  // 0: the distance at the start
  ctx.at_start.push_back([tp, given, mark = node.Mark(), path, &ctx](const State& s0) {
    const double L = tp->length(s0);
    if (!(L > 0.0))
      ctx.diag.error(mark, path,
                     fmt::format("the end points of tensioner '{}' coincide at the start, so the "
                                 "direction of its force is undefined; place its ends apart",
                                 tp->name()));
    tp->set_reference_length(given > 0.0 ? given : L);
  });
}

}  // namespace

void load_connections(const YAML::Node& node, LoadContext& ctx) {
  if (!node.IsSequence()) {
    ctx.diag.error(node.Mark(), "connections",
                   fmt::format("expected a list of connections, got {}", describe(node)));
    return;
  }
  std::set<std::string>& names = ctx.joint_and_connection_names;
  for (std::size_t i = 0; i < node.size(); ++i) {
    const std::string path = fmt::format("connections[{}]", i);
    MapReader r(ctx.diag, node[i], path);
    if (!r.valid()) continue;
    const auto type =
        r.choice("type", Need::kRequired, {"spring", "rope", "pneumatic_cylinder", "tensioner"});
    if (!type) {
      read_entry_name(r, names, "connection");  // the name is taken; other keys are not judged
      continue;
    }
    if (*type == "spring") load_spring(r, node[i], path, names, ctx);
    if (*type == "rope") load_rope(r, node[i], path, names, ctx);
    if (*type == "pneumatic_cylinder") load_cylinder(r, node[i], path, names, ctx);
    if (*type == "tensioner") load_tensioner(r, node[i], path, names, ctx);
  }
}

}  // namespace seaflex::io
