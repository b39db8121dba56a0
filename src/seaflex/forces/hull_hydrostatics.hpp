// Hydrostatic force on a rigid hull built of boxes and cylinders: buoyancy rho g V
// acting upward at the centre of buoyancy of the volume below the mean free surface
// z = 0, recomputed at every evaluation from the body's position and attitude (thesis
// eq. 172). The restoring moments follow from the centre of buoyancy moving with the
// waterplane; nothing is linearized. Wave pressure (Froude-Krylov) is not included here:
// it comes from the RAO excitation or from the Morison inertia term.
#pragma once

#include <vector>

#include "seaflex/forces/rigid_body_load.hpp"
#include "seaflex/hydro/displaced_volume.hpp"

namespace seaflex {

class HullHydrostatics : public RigidBodyLoad {
 public:
  /// pieces: convex hull pieces in body axes relative to the centre of gravity (m);
  /// pieces must not overlap (their volumes add). rho (kg/m^3), g (m/s^2).
  HullHydrostatics(std::string name, const RigidBody& body,
                   std::vector<hydro::ConvexPolyhedron> pieces, double rho, double g);

  /// Displaced volume and centre of buoyancy in the state.
  hydro::Displacement displacement(const State& state) const;
  void add_channels(ChannelList& channels) const override;

 protected:
  Wrench wrench(const RigidBodyMotion& m) const override;
  bool velocity_dependent() const override { return false; }

 private:
  hydro::Displacement displacement_of(const RigidBodyMotion& m) const;
  std::vector<hydro::ConvexPolyhedron> pieces_;
  double rho_, g_;
};

}  // namespace seaflex
