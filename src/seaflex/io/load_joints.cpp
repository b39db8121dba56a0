// joints: constraints between two markers (ball, universal, revolute, cylindrical,
// prismatic, fixed, and flex = ball + rotational spring-damper);
// the entries (name, from, to) that joints and connections share.
#include <fmt/format.h>

#include <algorithm>
#include <numbers>
#include <set>

#include "seaflex/constraints/joint.hpp"
#include "seaflex/forces/rotational_spring.hpp"
#include "seaflex/io/load_context.hpp"

namespace seaflex::io {

namespace {

// flex joint stiffness as riser flex joints are specified: kN m/deg -> N m/rad
constexpr double kKnmPerDeg = 1000.0 * 180.0 / std::numbers::pi;

const std::vector<std::string> kJointTypes{"ball",      "universal", "revolute", "cylindrical",
                                           "prismatic", "fixed",     "flex"};

JointType joint_type(const std::string& t) {
  if (t == "universal") return JointType::kUniversal;
  if (t == "revolute") return JointType::kRevolute;
  if (t == "cylindrical") return JointType::kCylindrical;
  if (t == "prismatic") return JointType::kPrismatic;
  if (t == "fixed") return JointType::kFixed;
  return JointType::kBall;  // ball and flex
}

}  // namespace

namespace {
bool printable(const std::string& s) {
  return std::none_of(s.begin(), s.end(),
                      [](char c) { return static_cast<unsigned char>(c) < 32; });
}
}  // namespace

std::string name_problem(const std::string& name, std::string_view what, std::string_view channel) {
  if (name.empty() ||
      name.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-") !=
          std::string::npos)
    return fmt::format(
        "{} names may use letters, digits, '_' and '-' only (they become output channel names "
        "such as {}){}",
        what, channel,
        printable(name) && name.size() <= kMaxNameLength ? "" : fmt::format(", got {:?}", name));
  if (name.size() > kMaxNameLength)
    return fmt::format(
        "{} names may have at most {} characters (they become output channel and file names, "
        "such as {}), got {} characters",
        what, kMaxNameLength, channel, name.size());
  return "";
}

std::string name_key(std::string_view parent, const std::string& name) {
  if (!printable(name) || name.size() > kMaxNameLength) return std::string(parent);
  return fmt::format("{}.{}", parent, name);
}

std::optional<std::string> read_entry_name(MapReader& r, std::set<std::string>& names,
                                           const char* what) {
  const auto name = r.text("name", Need::kRequired);
  if (!name) return std::nullopt;
  if (const std::string problem = name_problem(*name, what, "<name>.fx"); !problem.empty()) {
    r.error("name", problem);
    return std::nullopt;
  }
  if (!names.insert(*name).second) {
    r.error("name", fmt::format("a {} named '{}' repeats the name of an earlier joint or "
                                "connection: names must be unique (they name output channels)",
                                what, *name));
    return std::nullopt;
  }
  return name;
}

PairEntry read_pair(MapReader& r, std::set<std::string>& names, const char* what) {
  PairEntry e;
  e.name = read_entry_name(r, names, what);
  e.from = r.get("from", Need::kRequired, "a marker name or {body: ..., ...}");
  e.to = r.get("to", Need::kRequired, "a marker name or {body: ..., ...}");
  return e;
}

std::pair<std::unique_ptr<Marker>, std::unique_ptr<Marker>> read_markers(MapReader& r,
                                                                         const PairEntry& e,
                                                                         LoadContext& ctx) {
  std::unique_ptr<Marker> from, to;
  if (e.from.IsDefined()) from = ctx.marker(e.from, r.key_path("from"));
  if (e.to.IsDefined()) to = ctx.marker(e.to, r.key_path("to"));
  return {std::move(from), std::move(to)};
}

std::optional<bool> read_bool(MapReader& r, std::string_view key) {
  const YAML::Node n = r.get(key);
  if (!n.IsDefined()) return false;
  // true or false only, as everywhere in the model file (not yes, no, on, True, ...)
  if (n.IsScalar() && (n.Scalar() == "true" || n.Scalar() == "false")) return n.Scalar() == "true";
  r.error(key, fmt::format("expected true or false, got {}", describe(n)));
  return std::nullopt;
}

void load_joints(const YAML::Node& node, LoadContext& ctx) {
  if (!node.IsSequence()) {
    ctx.diag.error(node.Mark(), "joints",
                   fmt::format("expected a list of joints, got {}", describe(node)));
    return;
  }
  std::set<std::string>& names = ctx.joint_and_connection_names;
  for (std::size_t i = 0; i < node.size(); ++i) {
    const std::string path = fmt::format("joints[{}]", i);
    MapReader r(ctx.diag, node[i], path);
    if (!r.valid()) continue;
    const auto entry = read_pair(r, names, "joint");
    const auto type = r.choice("type", Need::kRequired, kJointTypes);
    std::optional<double> stiffness = 0.0, damping = 0.0;
    if (type == "flex") {
      stiffness = r.number("stiffness", Need::kRequired, NumberRule::nonnegative("kN m/deg"));
      if (r.has("damping"))
        damping = r.number("damping", Need::kRequired, NumberRule::nonnegative("kN m s/deg"));
    } else if (type) {
      for (const char* k : {"stiffness", "damping"})
        if (r.has(k))
          r.error(k, fmt::format("only a flex joint takes {}; a {} joint is rigid", k, *type));
    } else {
      r.has("stiffness");  // not judged without a valid type
      r.has("damping");
    }
    auto [from, to] = read_markers(r, entry, ctx);
    r.finish();
    if (!entry.name || !type || !from || !to || !stiffness || !damping) continue;
    if (from->body() != nullptr && from->body() == to->body()) {
      r.error("to", fmt::format("joint '{}' connects body '{}' to itself", *entry.name,
                                from->body()->name()));
      continue;
    }
    if (from->body() == nullptr && to->body() == nullptr) {
      r.error("to", fmt::format("joint '{}' connects ground to ground", *entry.name));
      continue;
    }
    std::unique_ptr<Joint> joint;
    try {
      joint =
          std::make_unique<Joint>(*entry.name, joint_type(*type), std::move(from), std::move(to));
    } catch (const std::invalid_argument& e) {
      r.error("type", fmt::format("joint '{}': {}", *entry.name, e.what()));
      continue;
    }
    if (*type == "flex") {
      auto spring = std::make_unique<RotationalSpring>(
          *entry.name + ".spring", ctx.marker(entry.from, r.key_path("from")),
          ctx.marker(entry.to, r.key_path("to")), *stiffness * kKnmPerDeg, *damping * kKnmPerDeg);
      const RotationalSpring* s = spring.get();
      joint->set_extra_moment([s](const State& st) { return s->moment_on_b(st); });
      ctx.system.add_force(std::move(spring));
    }
    ctx.constraint_origin[*entry.name] = {node[i].Mark(), path};
    ctx.system.add_constraint(std::move(joint));
  }
}

}  // namespace seaflex::io
