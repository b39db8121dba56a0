// Linear(ized) hydrodynamic matrices of a floating rigid body at a reference point u
// (body axes from the centre of gravity; for BEM data, the origin of the panel model),
// in the six modes of linear seakeeping (surge, sway, heave, roll, pitch, yaw: body-axis
// velocity of the point and angular velocity):
//   added mass A (kg, kg m, kg m^2): -A (a_u, alpha) moves to the mass matrix (thesis
//     eq. 173: M + A_inf in the Cummins equation);
//   linear damping B1 and quadratic damping B2: f_i = -B1_ij v_j - B2_ij |v_j| v_j;
//   hydrostatic restoring C with displaced volume V (e.g. from a WAMIT .hst file):
//     f = rho g V e_z - C xi, xi = (displacement of u from its still-water position, roll,
//     pitch, yaw) in the axes of the body's initial heading (linear theory; the matrix
//     must hold the hydrostatic part only: gravity acts at the centre of gravity).
#pragma once

#include "seaflex/forces/rigid_body_load.hpp"

namespace seaflex {

struct HydroMatrixSet {
  Vec3 reference = Vec3::Zero();  ///< u: body axes from the centre of gravity (m)
  Mat6 added_mass = Mat6::Zero();
  Mat6 linear_damping = Mat6::Zero();
  Mat6 quadratic_damping = Mat6::Zero();
  bool has_stiffness = false;
  Mat6 stiffness = Mat6::Zero();
  double displaced_volume = 0.0;             ///< V (m^3), with the stiffness
  Vec3 still_water_position = Vec3::Zero();  ///< world position of u at rest (m)
  double heading = 0.0;                      ///< the body's heading at rest (rad)
  double rho = 1025.0;
  double g = kStandardGravity;
};

class HydroMatrices : public RigidBodyLoad {
 public:
  HydroMatrices(std::string name, const RigidBody& body, HydroMatrixSet set);
  const HydroMatrixSet& set() const { return set_; }

 protected:
  Wrench wrench(const RigidBodyMotion& m) const override;
  bool has_added_mass() const override { return !set_.added_mass.isZero(0.0); }
  Mat6 added_mass(const RigidBodyMotion& m) const override;

 private:
  HydroMatrixSet set_;
};

}  // namespace seaflex
