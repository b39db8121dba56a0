// supports: a list of beam-node boundary conditions, each a CoordinateLock holding
// chosen node coordinates at their initial values.
#include <fmt/format.h>

#include <set>

#include "seaflex/constraints/coordinate_lock.hpp"
#include "seaflex/constraints/prescribed_coordinates.hpp"
#include "seaflex/io/load_context.hpp"

namespace seaflex::io {

namespace {
// component name -> local offset within a node (r: 0..2, r': 3..5)
const std::vector<std::string> kComponents{"x", "y", "z", "slope_x", "slope_y", "slope_z"};
}  // namespace

void load_supports(const YAML::Node& node, LoadContext& ctx) {
  if (!node.IsSequence()) {
    ctx.diag.error(node.Mark(), "supports",
                   fmt::format("expected a list of supports, got {}", describe(node)));
    return;
  }
  std::set<std::pair<std::string, Index>> held;  // (body, local coordinate)
  for (std::size_t i = 0; i < node.size(); ++i) {
    const std::string path = fmt::format("supports[{}]", i);
    MapReader r(ctx.diag, node[i], path);
    if (!r.valid()) continue;
    bool skip = false;
    if (const AncfPlate* plate = plate_of(node[i], ctx, &skip)) {
      load_plate_support(r, *plate, node[i], held, ctx);
      continue;
    }
    if (skip) continue;
    const AncfBeam* beam = ctx.beam_ref(r, "body");
    const auto type = r.choice("type", Need::kRequired, {"clamped", "pinned", "fixed"});
    std::optional<int> k;
    if (beam)
      k = ctx.node_ref(r, "node", *beam, Need::kRequired);
    else
      r.has("node");
    std::vector<int> components;
    if (type == "clamped") components = {0, 1, 2, 3, 4, 5};
    if (type == "pinned") components = {0, 1, 2};
    const YAML::Node fix = r.get("fix", type == "fixed" ? Need::kRequired : Need::kOptional,
                                 "a list of components from x, y, z, slope_x, slope_y, slope_z");
    if (fix.IsDefined() && type && *type != "fixed") {
      r.error("fix",
              fmt::format("only a support of type 'fixed' takes a component list; '{}' holds {}",
                          *type, *type == "clamped" ? "position and slope" : "the position"));
    } else if (fix.IsDefined()) {
      if (!fix.IsSequence() || fix.size() == 0) {
        r.error("fix", fmt::format("expected a non-empty list of components from {}, got {}",
                                   fmt::join(kComponents, ", "),
                                   fix.IsSequence() ? "an empty list" : describe(fix)));
      } else {
        for (std::size_t c = 0; c < fix.size(); ++c) {
          const std::string s = fix[c].IsScalar() ? fix[c].Scalar() : describe(fix[c]);
          const auto it = std::find(kComponents.begin(), kComponents.end(), s);
          if (it == kComponents.end()) {
            ctx.diag.error(
                fix[c].Mark(), fmt::format("{}.fix[{}]", path, c),
                fmt::format("unknown component '{}'; {}", s, suggestion(s, kComponents)));
            continue;
          }
          const int comp = static_cast<int>(it - kComponents.begin());
          if (std::find(components.begin(), components.end(), comp) != components.end())
            ctx.diag.error(fix[c].Mark(), fmt::format("{}.fix[{}]", path, c),
                           fmt::format("component '{}' is listed twice", s));
          else
            components.push_back(comp);
        }
      }
    }
    // a support that moves: the held components follow an imposed motion about the node
    std::optional<MotionEntry> motion = MotionEntry{};
    if (r.has("motion")) {
      Vec3 node_position = Vec3::Zero();
      if (beam && k) node_position = beam->initial_geometry().positions[*k];
      motion = read_motion(r, "motion", node_position, false, ctx);
    }
    r.finish();
    if (!beam || !k || !type || components.empty() || !motion) continue;
    std::vector<Index> locals;
    std::vector<double> values;
    std::vector<std::string> labels;
    const auto& g = beam->initial_geometry();
    std::vector<std::string> twice;
    for (int comp : components) {
      const Index local = 6 * *k + comp;
      if (!held.insert({beam->name(), local}).second) {
        twice.push_back(kComponents[comp]);
        continue;
      }
      locals.push_back(local);
      values.push_back(comp < 3 ? g.positions[*k][comp] : g.slopes[*k][comp - 3]);
      labels.push_back(kComponents[comp]);
    }
    if (!twice.empty())
      r.error("node", fmt::format("{}.n{} {} already held by an earlier support: a coordinate can "
                                  "be held only once",
                                  beam->name(), *k, fmt::join(twice, ", ")));
    if (locals.empty()) continue;
    if (motion->motion) {
      std::vector<PrescribedCoordinates::Row> rows;
      for (std::size_t j = 0; j < locals.size(); ++j) {
        const int comp = static_cast<int>(locals[j] - 6 * *k);
        rows.push_back(
            {locals[j], comp < 3, comp < 3 ? g.positions[*k] : g.slopes[*k], comp % 3, labels[j]});
      }
      const std::string cname = fmt::format("{}.n{}.support", beam->name(), *k);
      ctx.constraint_origin[cname] = {node[i].Mark(), path};
      ctx.system.add_constraint(std::make_unique<PrescribedCoordinates>(
          cname, *beam, std::move(rows), motion->motion, motion->origin));
      continue;
    }
    const std::string cname = fmt::format("support {}.n{}", beam->name(), *k);
    ctx.constraint_origin[cname] = {node[i].Mark(), path};
    ctx.system.add_constraint(
        std::make_unique<CoordinateLock>(cname, *beam, locals, values, labels));
  }
}

}  // namespace seaflex::io
