#include "seaflex/io/model_loader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <numbers>
#include <set>
#include <sstream>

#include "seaflex/constraints/joint.hpp"
#include "seaflex/constraints/prescribed_coordinates.hpp"
#include "seaflex/core/input_file.hpp"
#include "seaflex/forces/gravity.hpp"
#include "seaflex/forces/rotational_spring.hpp"
#include "seaflex/forces/spring_damper.hpp"
#include "seaflex/io/load_context.hpp"
#include "seaflex/io/optional_channels.hpp"
#include "seaflex/solvers/constraint_audit.hpp"

namespace seaflex::io {

const AncfBeam* LoadContext::beam_ref(MapReader& reader, std::string_view key) {
  const auto name = reader.text(key, Need::kRequired);
  if (!name) return nullptr;
  const Body* body = system.find_body(*name);
  if (!body && std::find(failed_bodies.begin(), failed_bodies.end(), *name) != failed_bodies.end())
    return nullptr;  // already reported where the body is defined
  if (!body) {
    std::vector<std::string> names;
    for (const auto& b : system.bodies()) names.push_back(b->name());
    reader.error(key, names.empty()
                          ? fmt::format("no body named '{}': the model has no valid bodies", *name)
                          : fmt::format("no body named '{}'; {}", *name, suggestion(*name, names)));
    return nullptr;
  }
  const auto* beam = dynamic_cast<const AncfBeam*>(body);
  if (!beam)
    reader.error(key, fmt::format("body '{}' is a {}; only ancf_beam bodies are accepted here",
                                  *name, body->kind()));
  return beam;
}

std::optional<int> LoadContext::node_ref(MapReader& reader, std::string_view key,
                                         const AncfBeam& beam, Need need) {
  const YAML::Node n = reader.get(key, need, "a node number, start or end");
  if (!n.IsDefined()) return std::nullopt;
  if (n.IsScalar() && n.Scalar() == "start") return 0;
  if (n.IsScalar() && n.Scalar() == "end") return beam.num_nodes() - 1;
  const int last = beam.num_nodes() - 1;
  if (!n.IsScalar()) {
    reader.error(key, fmt::format("expected a node number (0..{}), start or end; got {}", last,
                                  describe(n)));
    return std::nullopt;
  }
  {
    const std::string& s = n.Scalar();
    const bool digits = !s.empty() && s.find_first_not_of("0123456789") == std::string::npos;
    if (!digits) {
      reader.error(key,
                   fmt::format("expected a node number (0..{}), start or end; got '{}'", last, s));
      return std::nullopt;
    }
  }
  return read_integer(diag, n, reader.key_path(key), 0, last);
}

namespace {

// The model check of constraints at the initial state: redundant rows (over-constrained
// assemblies) and rows not satisfied (markers that do not meet), reported by constraint
// name at the line that defines it.
void check_constraints(LoadContext& ctx) {
  const System& sys = ctx.system;
  const State s0 = sys.initial_state();
  // the input is rounded: positions must close to 1e-6 of the model's size, velocities to
  // 1e-4 of the largest velocity; smaller gaps are closed by the first projection (RK4)
  // or Newton step (statics)
  const double position_tolerance = 1e-6 * std::max(1.0, s0.q.lpNorm<Eigen::Infinity>());
  const double velocity_tolerance = 1e-4 * std::max(1.0, s0.v.lpNorm<Eigen::Infinity>());
  const ConstraintAudit audit = audit_constraints(sys, s0, position_tolerance, velocity_tolerance);
  auto origin = [&](const Constraint* c) -> std::pair<YAML::Mark, std::string> {
    if (const auto it = ctx.constraint_origin.find(c->name()); it != ctx.constraint_origin.end())
      return it->second;
    return {YAML::Mark::null_mark(), ""};
  };
  auto label = [&](Index row) {
    const std::string full = sys.constraint_name(row);
    const auto colon = full.find(": ");
    return colon == std::string::npos ? full : full.substr(colon + 2);
  };
  // a constraint that follows an imposed motion: the motion at t = 0 must meet the model's
  // initial positions and velocities, which a ramp from rest guarantees
  auto moving_hint = [](const Constraint* c) -> std::string {
    const auto* j = dynamic_cast<const Joint*>(c);
    if (dynamic_cast<const PrescribedCoordinates*>(c) ||
        (j && (j->from().moving() || j->to().moving())))
      return "; it follows an imposed motion, which must start where the model starts: give "
             "the motion a ramp (it then starts from rest at zero displacement)";
    return "";
  };
  std::set<const Constraint*> reported;
  for (const RedundantRow& red : audit.redundant) {
    const Constraint* c = sys.constraint_at_row(red.row);
    if (!reported.insert(c).second) continue;
    std::vector<std::string> others;
    for (Index r : red.depends_on) {
      const Constraint* o = sys.constraint_at_row(r);
      const std::string n = fmt::format("'{}'", o->name());
      if (o != c && std::find(others.begin(), others.end(), n) == others.end()) others.push_back(n);
    }
    const auto [mark, path] = origin(c);
    // a body with an imposed motion is held in all six degrees of freedom
    bool prescribed = moving_hint(c) != "";
    for (Index r : red.depends_on)
      prescribed = prescribed || moving_hint(sys.constraint_at_row(r)) != "";
    ctx.diag.error(
        mark, path,
        fmt::format("'{}' over-constrains the assembly: its condition '{}' repeats what {} "
                    "already impose{}; {}",
                    c->name(), label(red.row),
                    others.empty() ? std::string("earlier constraints")
                                   : fmt::format("{}", fmt::join(others, ", ")),
                    others.size() == 1 ? "s" : "",
                    prescribed ? "an imposed motion holds its body or point in every degree of "
                                 "freedom it moves, so nothing else may hold it there: remove the "
                                 "joint or support, or set the body's motion: free"
                               : "remove it or use a joint with fewer conditions (a closed loop of "
                                 "parallel revolute joints, such as a four-bar, needs a ball and a "
                                 "universal joint in place of two of its revolutes)"));
  }
  for (const ViolatedRow& v : audit.violated) {
    const Constraint* c = sys.constraint_at_row(v.row);
    if (!reported.insert(c).second) continue;
    std::string detail;
    if (const auto* j = dynamic_cast<const Joint*>(c)) {
      const Vec3 a = j->from().position(s0), b = j->to().position(s0);
      detail = fmt::format(
          " ({} is at ({:.6g}, {:.6g}, {:.6g}) m, {} at ({:.6g}, {:.6g}, {:.6g}) m)",
          j->from().describe(), a.x(), a.y(), a.z(), j->to().describe(), b.x(), b.y(), b.z());
    }
    const auto [mark, path] = origin(c);
    ctx.diag.error(mark, path,
                   fmt::format("'{}' is not satisfied by the initial positions: condition '{}' is "
                               "off by {:.6g}{}; place the bodies so that the joint closes{}",
                               c->name(), label(v.row), std::abs(v.value), detail, moving_hint(c)));
  }
  for (const ViolatedRow& v : audit.velocity_violated) {
    const Constraint* c = sys.constraint_at_row(v.row);
    if (!reported.insert(c).second) continue;
    const auto [mark, path] = origin(c);
    ctx.diag.error(
        mark, path,
        fmt::format("'{}' is not satisfied by the initial velocities: condition '{}' changes at "
                    "{:.6g} per second; give the bodies velocities that the joint allows{}",
                    c->name(), label(v.row), std::abs(v.value), moving_hint(c)));
  }
}

// Springs whose end points coincide at the start: the line of action of the force is
// undefined there, and every analysis would stop at its first evaluation.
void check_springs(LoadContext& ctx) {
  const State s0 = ctx.system.initial_state();
  for (const auto& f : ctx.system.forces()) {
    const auto* spring = dynamic_cast<const SpringDamper*>(f.get());
    if (!spring || spring->length(s0) > 0.0) continue;
    const auto it = ctx.connection_origin.find(spring->name());
    const auto [mark, path] = it != ctx.connection_origin.end()
                                  ? it->second
                                  : std::pair(YAML::Mark::null_mark(), std::string());
    ctx.diag.error(mark, path,
                   fmt::format("the end points of spring '{}' coincide at the start, so the "
                               "direction of its force is undefined; place its ends apart",
                               spring->name()));
  }
  // a flex joint is neutral with its axes parallel: a start far from that (often a beam
  // slope, which points from the beam's start to its end, against a marker axis) would
  // pre-bend the joint by the spring's full moment
  for (const auto& f : ctx.system.forces()) {
    const auto* flex = dynamic_cast<const RotationalSpring*>(f.get());
    if (!flex) continue;
    const double angle = flex->angle(s0) * 180.0 / std::numbers::pi;
    if (angle <= 1.0) continue;
    std::string joint = flex->name();
    joint = joint.substr(0, joint.size() - std::string(".spring").size());
    const auto it = ctx.constraint_origin.find(joint);
    const auto [mark, path] = it != ctx.constraint_origin.end()
                                  ? it->second
                                  : std::pair(YAML::Mark::null_mark(), std::string());
    ctx.diag.error(mark, path,
                   fmt::format("flex joint '{}' starts bent by {:.4g} deg: it is neutral when the "
                               "z axes of its markers are parallel (a beam marker's axis is the "
                               "beam's slope, from its start towards its end); give the "
                               "rigid-body or ground marker an axis along the beam",
                               joint, angle));
  }
}

Model load(const YAML::Node& root, const std::string& name) {
  Diagnostics diag(name);
  Model model;
  model.file = name;
  model.system = std::make_unique<System>();
  LoadContext ctx{diag, *model.system, model, {}, {}, {}, {}, {}, {}, {}, {}, {}, {}, {}};

  MapReader top(diag, root, "");
  if (!top.valid()) diag.throw_if_any();
  if (const auto title = top.text("title", Need::kOptional)) model.title = *title;

  // environment: gravity magnitude along -z, or a vector
  model.gravity = Vec3(0, 0, -kStandardGravity);
  if (const YAML::Node env = top.get("environment"); env.IsDefined()) {
    MapReader r(diag, env, "environment");
    if (const YAML::Node g = r.get("gravity"); g.IsDefined()) {
      if (g.IsSequence()) {
        if (const auto v = read_vec3(diag, g, "environment.gravity", "m/s^2")) model.gravity = *v;
      } else if (const auto m = read_number(diag, g, "environment.gravity",
                                            NumberRule::range(0.0, 100.0, "m/s^2"))) {
        model.gravity = Vec3(0, 0, *m > 0.0 ? -*m : 0.0);
      }
    }
    load_water(r, ctx, model.gravity.norm());
    load_seabed(r, ctx);
    r.finish();
  }

  const YAML::Node bodies = top.get("bodies", Need::kRequired, "a mapping of body names to bodies");
  if (bodies.IsDefined()) load_bodies(bodies, ctx);
  if (const YAML::Node n = top.get("markers"); n.IsDefined()) load_markers(n, ctx);
  if (const YAML::Node n = top.get("supports"); n.IsDefined()) load_supports(n, ctx);
  if (const YAML::Node n = top.get("joints"); n.IsDefined()) load_joints(n, ctx);
  if (const YAML::Node n = top.get("connections"); n.IsDefined()) load_connections(n, ctx);
  if (const YAML::Node n = top.get("loads"); n.IsDefined()) load_loads(n, ctx);
  if (const YAML::Node n = top.get("hydrodynamics"); n.IsDefined()) load_hydrodynamics(n, ctx);
  for (const auto& f : ctx.after_bodies) f(ctx);
  if (model.gravity.norm() > 0.0) {
    std::vector<const Body*> all;
    for (const auto& b : model.system->bodies()) all.push_back(b.get());
    model.system->add_force(std::make_unique<Gravity>(model.gravity, all));
  }
  if (const YAML::Node n = top.get("statics"); n.IsDefined()) load_statics(n, ctx);
  if (const YAML::Node n = top.get("dynamics"); n.IsDefined()) load_dynamics(n, ctx);
  if (const YAML::Node n = top.get("output"); n.IsDefined()) load_output(n, ctx);
  if (const YAML::Node n = top.get("statistics"); n.IsDefined()) load_statistics(n, ctx);
  if (const YAML::Node n = top.get("fatigue"); n.IsDefined()) load_fatigue(n, ctx);
  if (const YAML::Node n = top.get("code_check"); n.IsDefined()) load_code_check(n, ctx);
  top.finish();
  diag.throw_if_any();
  model.system->finalize();
  check_constraints(ctx);
  check_springs(ctx);
  const State s0 = model.system->initial_state();
  for (const auto& f : ctx.at_start) f(s0);
  check_output(ctx);
  diag.throw_if_any();
  return model;
}

}  // namespace

ChannelList model_channels(const Model& model) {
  ChannelList list = model.system->channels();
  if (model.ocean)
    for (const auto& probe : model.wave_probes)  // (name, point)
      list.push_back({probe.first, [ocean = model.ocean, p = probe.second](const State& s) {
                        return ocean->elevation(p.x(), p.y(), s.t);
                      }});
  add_optional_channels(model, list);
  return list;
}

Model load_model_text(const std::string& text, const std::string& name) {
  const YAML::Node root = parse_document(text, name);
  if (!root.IsDefined() || root.IsNull()) {
    Diagnostics diag(name);
    diag.error(YAML::Mark::null_mark(), "", "the model file is empty");
    diag.throw_if_any();
  }
  return load(root, name);
}

Model load_model_file(const std::string& path) {
  // a regular file of at most kMaxModelFileBytes; InputError "model.yaml: cannot read the
  // model file: it is a directory" otherwise
  return load_model_text(read_input_file(path, "model file", kMaxModelFileBytes), path);
}

}  // namespace seaflex::io
