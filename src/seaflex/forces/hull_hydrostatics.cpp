#include "seaflex/forces/hull_hydrostatics.hpp"

#include <fmt/format.h>

namespace seaflex {

HullHydrostatics::HullHydrostatics(std::string name, const RigidBody& body,
                                   std::vector<hydro::ConvexPolyhedron> pieces, double rho,
                                   double g)
    : RigidBodyLoad(std::move(name), body), pieces_(std::move(pieces)), rho_(rho), g_(g) {}

hydro::Displacement HullHydrostatics::displacement_of(const RigidBodyMotion& m) const {
  hydro::Displacement total;
  Vec3 moment = Vec3::Zero();
  for (const auto& piece : pieces_) {
    const hydro::Displacement d = hydro::submerged_part(piece, m.r, m.R);
    total.volume += d.volume;
    total.waterplane_area += d.waterplane_area;
    moment += d.volume * d.centroid;
  }
  if (total.volume > 0.0) total.centroid = moment / total.volume;
  return total;
}

hydro::Displacement HullHydrostatics::displacement(const State& state) const {
  return displacement_of(motion(state));
}

Wrench HullHydrostatics::wrench(const RigidBodyMotion& m) const {
  Wrench W;
  const hydro::Displacement d = displacement_of(m);
  if (d.volume > 0.0) W.add_at(Vec3(0, 0, rho_ * g_ * d.volume), d.centroid, m.r);  // eq. (172)
  return W;
}

void HullHydrostatics::add_channels(ChannelList& channels) const {
  channels.push_back({fmt::format("{}.volume", name()),
                      [this](const State& s) { return displacement(s).volume; }});
  channels.push_back({fmt::format("{}.buoyancy", name()),
                      [this](const State& s) { return rho_ * g_ * displacement(s).volume; }});
}

}  // namespace seaflex
