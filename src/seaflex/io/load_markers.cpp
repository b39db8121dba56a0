// markers: named points (with axes) on bodies or ground, referenced by joints,
// connections and loads; a reference may also be an inline mapping. Orientation input
// (roll, pitch, yaw; Z-X-Z; an axis) is read here for bodies and markers alike.
#include <fmt/format.h>

#include <numbers>

#include "seaflex/elements/rigid_body.hpp"
#include "seaflex/io/load_context.hpp"
#include "seaflex/math/rotation.hpp"
#include "seaflex/model/moving_marker.hpp"

namespace seaflex::io {

namespace {
constexpr double kRad = std::numbers::pi / 180.0;
}

std::optional<Mat3> read_orientation(MapReader& r, bool allow_axis) {
  const bool rpy = r.has("orientation"), zxz = r.has("euler_zxz");
  const bool axis = allow_axis && r.has("axis");
  if (int(rpy) + int(zxz) + int(axis) > 1) {
    r.error(zxz ? "euler_zxz" : "axis", allow_axis
                                            ? "give one of orientation, euler_zxz or axis"
                                            : "give either orientation or euler_zxz, not both");
    return std::nullopt;
  }
  if (rpy) {
    const auto a = r.vec3("orientation", Need::kRequired, "deg (roll, pitch, yaw)");
    if (!a) return std::nullopt;
    return math::rotation_from_roll_pitch_yaw(kRad * a->x(), kRad * a->y(), kRad * a->z());
  }
  if (zxz) {
    const auto a = r.vec3("euler_zxz", Need::kRequired, "deg (phi, theta, psi)");
    if (!a) return std::nullopt;
    return math::rotation_from_euler_zxz(kRad * a->x(), kRad * a->y(), kRad * a->z());
  }
  if (axis) {
    const auto a = r.vec3("axis", Need::kRequired, "(a direction)");
    if (!a) return std::nullopt;
    if (!(a->norm() > 0.0)) {
      r.error("axis", "the axis must be a non-zero vector");
      return std::nullopt;
    }
    return math::frame_from_axis(*a);
  }
  return Mat3::Identity();
}

const Body* LoadContext::body_ref(MapReader& reader, std::string_view key, bool allow_ground,
                                  bool* ground) {
  if (ground) *ground = false;
  const auto name = reader.text(key, Need::kRequired);
  if (!name) return nullptr;
  if (allow_ground && *name == kGroundName) {
    if (ground) *ground = true;
    return nullptr;
  }
  const Body* body = system.find_body(*name);
  if (body) return body;
  if (std::find(failed_bodies.begin(), failed_bodies.end(), *name) != failed_bodies.end())
    return nullptr;  // already reported where the body is defined
  std::vector<std::string> names;
  for (const auto& b : system.bodies()) names.push_back(b->name());
  if (allow_ground) names.emplace_back(kGroundName);
  reader.error(key, fmt::format("no body named '{}'; {}", *name, suggestion(*name, names)));
  return nullptr;
}

std::unique_ptr<Marker> LoadContext::marker(const YAML::Node& node, const std::string& path) {
  if (node.IsScalar()) {
    const std::string& name = node.Scalar();
    if (const auto it = markers.find(name); it != markers.end()) return marker(it->second, path);
    if (std::find(failed_markers.begin(), failed_markers.end(), name) != failed_markers.end())
      return nullptr;  // reported where the marker is defined
    std::vector<std::string> names;
    for (const auto& kv : markers) names.push_back(kv.first);
    diag.error(node.Mark(), path,
               names.empty()
                   ? fmt::format("no marker named '{}': the model defines no markers (give the "
                                 "marker inline as {{body: ..., ...}})",
                                 name)
                   : fmt::format("no marker named '{}'; {}", name, suggestion(name, names)));
    return nullptr;
  }
  MapReader r(diag, node, path);
  if (!r.valid()) return nullptr;
  // a marker with any problem is not built: a named one is then reported once, where it
  // is defined, not again at every reference
  const std::size_t errors_before = diag.count();
  bool ground = false;
  const Body* body = body_ref(r, "body", true, &ground);
  std::unique_ptr<Marker> m;
  if (ground) {
    const auto p = r.vec3("position", Need::kRequired, "m (world)");
    const auto frame = read_orientation(r, true);
    // a ground marker may move: its point and axes follow an imposed motion
    const auto motion = read_motion(r, "motion", p.value_or(Vec3::Zero()), false, *this);
    if (p && frame && motion && motion->motion)
      m = std::make_unique<MovingMarker>(motion->motion, motion->origin, *p, *frame);
    else if (p && frame && motion)
      m = std::make_unique<GroundMarker>(*p, *frame);
  } else if (const auto* beam = dynamic_cast<const AncfBeam*>(body)) {
    for (const char* k : {"position", "orientation", "axis", "euler_zxz"})
      if (r.has(k))
        r.error(k, fmt::format("a marker on beam '{}' is placed by node or arc_length; its only "
                               "axis is the beam's slope",
                               beam->name()));
    const bool at_node = r.has("node"), at_s = r.has("arc_length");
    if (at_node && at_s) {
      r.error("arc_length", "give either node or arc_length, not both");
    } else if (at_s) {
      if (const auto s =
              r.number("arc_length", Need::kRequired, NumberRule::range(0.0, beam->length(), "m")))
        m = std::make_unique<BeamMarker>(*beam, *s);
    } else if (const auto k = node_ref(r, "node", *beam, Need::kRequired)) {
      m = BeamMarker::at_node(*beam, *k);
    }
  } else if (const auto* rigid = dynamic_cast<const RigidBody*>(body)) {
    if (r.has("node") || r.has("arc_length"))
      r.error(r.has("node") ? "node" : "arc_length",
              fmt::format("rigid body '{}' has no nodes: place the marker by position (body axes, "
                          "relative to the centre of gravity)",
                          rigid->name()));
    Vec3 p = Vec3::Zero();
    bool ok = true;
    if (r.has("position")) {
      if (const auto v = r.vec3("position", Need::kRequired, "m (body axes)"))
        p = *v;
      else
        ok = false;
    }
    const auto frame = read_orientation(r, true);
    if (ok && frame) m = std::make_unique<RigidBodyMarker>(*rigid, p, *frame);
  } else if (const auto* plate = dynamic_cast<const AncfPlate*>(body)) {
    m = plate_marker(r, *plate);
  } else {
    for (const char* k :
         {"position", "orientation", "axis", "euler_zxz", "node", "arc_length", "motion"})
      r.has(k);
  }
  r.finish();
  if (diag.count() != errors_before) return nullptr;
  return m;
}

void load_markers(const YAML::Node& node, LoadContext& ctx) {
  MapReader all(ctx.diag, node, "markers");
  if (!all.valid()) return;
  for (const auto& kv : node) {
    const std::string name = kv.first.Scalar();
    all.has(name);
    // read once to report problems; joints rebuild it from the node
    if (ctx.marker(kv.second, "markers." + name))
      ctx.markers[name] = kv.second;
    else
      ctx.failed_markers.push_back(name);
  }
}

}  // namespace seaflex::io
