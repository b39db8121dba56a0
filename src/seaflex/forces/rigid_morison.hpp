// Morison strip theory on cylindrical members of a rigid body (thesis eq. 176 applied
// strip by strip; DNV-RP-C205 6.2): per unit length of the wet part of a member,
//   f = 1/2 rho Cd D |u_n| u_n  +  1/2 rho Cd_ax pi D |u_a| u_a t      (drag)
//     + rho Cm A a_n                                                     (fluid inertia)
//     - rho Ca A (I - t t^T) a_s                                         (added mass)
// and, with end effects, the wave (dynamic) pressure on each wet end face, p_d A along the
// inward normal (the Froude-Krylov axial force of a column or pontoon end).
// with u = fluid velocity (waves + current) minus the member's velocity, u_n and u_a its
// normal and axial parts, a_n the normal part of the fluid acceleration, a_s the
// member's acceleration, t the member's axis, A = pi D^2/4. The added mass enters the
// body's mass matrix. The wet part ends at the instantaneous surface; it is integrated
// by Gauss-Legendre quadrature. Buoyancy (the hydrostatic pressure) is the hull's
// (HullHydrostatics), not this load's. The axial added mass of member ends is not
// modelled.
#pragma once

#include <memory>
#include <vector>

#include "seaflex/forces/rigid_body_load.hpp"
#include "seaflex/hydro/ocean.hpp"
#include "seaflex/math/gauss_legendre.hpp"

namespace seaflex {

struct MorisonMember {
  Vec3 a = Vec3::Zero();     ///< end point, body axes from the centre of gravity (m)
  Vec3 b = Vec3::Zero();     ///< other end point (m)
  double diameter = 0.0;     ///< D (m)
  double cd = 0.0;           ///< normal drag coefficient
  double cd_axial = 0.0;     ///< axial (skin) drag coefficient, on the perimeter pi D
  double ca = 0.0;           ///< normal added mass coefficient
  double cm = 0.0;           ///< inertia coefficient on the fluid acceleration (usually 1 + Ca)
  int strips = 10;           ///< Gauss points over the wet length
  bool end_effects = false;  ///< wave pressure on the wet end faces
};

class RigidMorison : public RigidBodyLoad {
 public:
  RigidMorison(std::string name, const RigidBody& body, std::vector<MorisonMember> members,
               std::shared_ptr<const hydro::Ocean> ocean);

 protected:
  Wrench wrench(const RigidBodyMotion& m) const override;
  bool has_added_mass() const override { return has_added_mass_; }
  Mat6 added_mass(const RigidBodyMotion& m) const override;

 private:
  /// Wet part [s0, s1] of member k (fractions of its length); s1 <= s0 when dry.
  std::pair<double, double> wet_interval(const MorisonMember& mem, const RigidBodyMotion& m) const;

  std::vector<MorisonMember> members_;
  std::vector<math::QuadratureRule> rules_;  // per member
  std::shared_ptr<const hydro::Ocean> ocean_;
  bool has_added_mass_ = false;
};

}  // namespace seaflex
