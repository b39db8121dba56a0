// loads: a list of external loads, each with a "type" from the registry. Time variation:
// a constant vector, optionally with a ramp or a factor table, or a table of vectors.
#include <fmt/format.h>

#include "seaflex/forces/distributed_load.hpp"
#include "seaflex/forces/point_load.hpp"
#include "seaflex/io/load_context.hpp"

namespace seaflex::io {

std::optional<TimeSignal> read_time_factor(MapReader& r) {
  const bool ramp = r.has("ramp"), factor = r.has("factor_table");
  if (ramp && factor) {
    r.error("factor_table", "give either ramp or factor_table, not both");
    return std::nullopt;
  }
  TimeSignal signal = TimeSignal::constant(1.0);
  bool ok = true;
  if (ramp) {
    MapReader rr(r.diagnostics(), r.get("ramp"), r.key_path("ramp"));
    const auto start = rr.number("start", Need::kOptional, NumberRule::nonnegative("s"));
    const auto duration = rr.number("duration", Need::kRequired, NumberRule::nonnegative("s"));
    rr.finish();
    if (rr.valid() && duration)
      signal = TimeSignal::ramp(start.value_or(0.0), *duration);
    else
      ok = false;
  }
  if (factor) {
    const auto rows = r.table("factor_table", Need::kRequired, 2);
    if (rows) {
      std::vector<double> times, values;
      for (const auto& row : *rows) {
        times.push_back(row[0]);
        values.push_back(row[1]);
      }
      signal = TimeSignal::table(std::move(times), std::move(values));
    } else {
      ok = false;
    }
  }
  if (!ok) return std::nullopt;
  return signal;
}

namespace {

// `key`: [x, y, z] with optional `ramp` / `factor_table`; or `key_table`: [[t, x, y, z], ...]
std::optional<VectorSignal> read_vector_signal(MapReader& r, const std::string& key,
                                               const std::string& unit) {
  const std::string table_key = key + "_table";
  const bool constant = r.has(key), tabled = r.has(table_key);
  const bool ramp = r.has("ramp"), factor = r.has("factor_table");
  if (constant && tabled) {
    r.error(table_key, fmt::format("give either {} or {}, not both", key, table_key));
    return std::nullopt;
  }
  if (tabled) {
    if (ramp || factor)
      r.error(ramp ? "ramp" : "factor_table",
              fmt::format("a ramp or factor table applies to {}, not to {}", key, table_key));
    const auto rows = r.table(table_key, Need::kRequired, 4);
    if (!rows) return std::nullopt;
    std::vector<double> times;
    std::vector<Vec3> values;
    for (const auto& row : *rows) {
      times.push_back(row[0]);
      values.emplace_back(row[1], row[2], row[3]);
    }
    return VectorSignal::table(std::move(times), std::move(values));
  }
  if (!constant) {
    r.error(key, fmt::format("required key is missing (give {} as [x, y, z] in {}, or {} as "
                             "[[t, x, y, z], ...])",
                             key, unit, table_key));
    return std::nullopt;
  }
  const auto value = r.vec3(key, Need::kRequired, unit);
  const auto signal = read_time_factor(r);
  if (!value || !signal) return std::nullopt;
  return VectorSignal(*value, std::move(*signal));
}

// at a beam node or arc length (body + node | arc_length), or at any marker (at: a marker
// name or an inline marker); a force and/or a moment, both in world axes
std::unique_ptr<Force> build_point_force(MapReader& r, const std::string& name, LoadContext& ctx) {
  std::unique_ptr<Marker> point;
  if (r.has("at")) {
    for (const char* k : {"body", "node", "arc_length"})
      if (r.has(k)) r.error(k, "give the point either by at or by body and node/arc_length");
    point = ctx.marker(r.get("at"), r.key_path("at"));
    if (point && point->body() == nullptr) {
      r.error("at", "a load at a ground marker would act on nothing; give a marker on a body");
      point.reset();
    }
  } else {
    const AncfBeam* beam = ctx.beam_ref(r, "body");
    const bool at_node = r.has("node"), at_s = r.has("arc_length");
    if (at_node && at_s) {
      r.error("arc_length", "give either node or arc_length, not both");
    } else if (beam && at_s) {
      if (const auto s =
              r.number("arc_length", Need::kRequired, NumberRule::range(0.0, beam->length(), "m")))
        point = std::make_unique<BeamMarker>(*beam, *s);
    } else if (beam) {
      if (const auto k = ctx.node_ref(r, "node", *beam, Need::kRequired))
        point = BeamMarker::at_node(*beam, *k);
    }
  }
  const bool has_moment = r.has("moment") || r.has("moment_table");
  const bool has_force = r.has("force") || r.has("force_table");
  std::optional<VectorSignal> force = VectorSignal(Vec3::Zero(), TimeSignal::constant(1.0));
  if (has_force || !has_moment) force = read_vector_signal(r, "force", "N");
  std::optional<VectorSignal> moment;
  if (has_moment) {
    moment = read_vector_signal(r, "moment", "N m");
    if (!moment) return nullptr;
  }
  if (!point || !force) return nullptr;
  return std::make_unique<PointLoad>(name, std::move(point), std::move(*force), std::move(moment));
}

std::unique_ptr<Force> build_distributed_load(MapReader& r, const std::string& name,
                                              LoadContext& ctx) {
  const AncfBeam* beam = ctx.beam_ref(r, "body");
  int first = 0, last = beam ? beam->num_elements() - 1 : 0;
  bool ok = true;
  if (const YAML::Node el = r.get("elements"); el.IsDefined() && beam) {
    if (!el.IsSequence() || el.size() != 2) {
      r.error("elements", fmt::format("expected [first, last] element numbers (0..{}), got {}",
                                      beam->num_elements() - 1, describe(el)));
      ok = false;
    } else {
      const auto a = read_integer(r.diagnostics(), el[0], r.key_path("elements") + "[0]", 0,
                                  beam->num_elements() - 1);
      const auto b = read_integer(r.diagnostics(), el[1], r.key_path("elements") + "[1]", 0,
                                  beam->num_elements() - 1);
      if (a && b && *a > *b) {
        r.error("elements", fmt::format("first element {} follows last element {}", *a, *b));
        ok = false;
      } else if (a && b) {
        first = *a;
        last = *b;
      } else {
        ok = false;
      }
    }
  }
  auto load = read_vector_signal(r, "load", "N/m");
  if (!beam || !load || !ok) return nullptr;
  return std::make_unique<DistributedLoad>(name, *beam, first, last, std::move(*load));
}

}  // namespace

const std::map<std::string, ForceBuilder>& load_builders() {
  static const std::map<std::string, ForceBuilder> builders{
      {"point_force", build_point_force},           {"distributed_load", build_distributed_load},
      {"plate_pressure", build_plate_pressure},     {"clump", build_clump},
      {"buoyancy_modules", build_buoyancy_modules},
  };
  return builders;
}

void load_loads(const YAML::Node& node, LoadContext& ctx) {
  if (!node.IsSequence()) {
    ctx.diag.error(node.Mark(), "loads",
                   fmt::format("expected a list of loads, got {}", describe(node)));
    return;
  }
  for (std::size_t i = 0; i < node.size(); ++i) {
    const std::string path = fmt::format("loads[{}]", i);
    MapReader r(ctx.diag, node[i], path);
    if (!r.valid()) continue;
    const auto type = r.choice("type", Need::kRequired, keys_of(load_builders()));
    const std::string name = r.text("name", Need::kOptional).value_or(path);
    if (!type) continue;
    auto force = load_builders().at(*type)(r, name, ctx);
    r.finish();
    if (force) ctx.system.add_force(std::move(force));
  }
}

}  // namespace seaflex::io
