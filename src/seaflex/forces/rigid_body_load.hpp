// Base of the loads that act on one rigid body as a wrench (force and moment) that
// depends on the body's position, attitude, velocities and time: hydrostatics, Morison
// members, wave excitation, radiation and damping matrices.
//
// The body's q = (r, p) (centre of gravity, Euler parameters); its world velocity and
// angular velocity are (v, w) = J q', J = [I 0; 0 2 G(p)] (Nikravesh eq. 6.98), so a
// world wrench (F, N about the centre of gravity) gives Q = J^T (F, N).
// An added mass M6 on (a, alpha) (world, at the centre of gravity) enters the mass matrix
// as J^T M6 J; since G(p') p' = 0, alpha = 2 G p'' exactly and J' q' = 0: no bias term.
// Tangents dQ/dq and dQ/dv are central finite differences of the wrench over the body's
// 7 coordinates (documented in docs/model-format.md): the wrench is smooth and costs
// little, and these tangents serve only statics and implicit integration.
#pragma once

#include "seaflex/elements/rigid_body.hpp"
#include "seaflex/model/force.hpp"

namespace seaflex {

using Vec6 = Eigen::Matrix<double, 6, 1>;
using Mat6 = Eigen::Matrix<double, 6, 6>;

/// The body's motion as the wrench functions see it (world axes).
struct RigidBodyMotion {
  Vec3 r;  ///< centre of gravity (m)
  Mat3 R;  ///< body axes in the world, R = A(p) of the (not renormalized) p
  Vec3 v;  ///< velocity of the centre of gravity (m/s)
  Vec3 w;  ///< angular velocity (rad/s)
  double t;
  /// World position and velocity of a body-fixed point u (body axes, from the CG).
  Vec3 point(const Vec3& u) const { return r + R * u; }
  Vec3 point_velocity(const Vec3& u) const { return v + w.cross(R * u); }
};

/// Force and moment about the centre of gravity, world axes (N, N m).
struct Wrench {
  Vec3 force = Vec3::Zero();
  Vec3 moment = Vec3::Zero();
  /// Adds a force f acting at world point x (the body's CG at r).
  void add_at(const Vec3& f, const Vec3& x, const Vec3& r) {
    force += f;
    moment += (x - r).cross(f);
  }
};

class RigidBodyLoad : public Force {
 public:
  RigidBodyLoad(std::string name, const RigidBody& body);

  const RigidBody& body() const { return body_; }
  void declare_blocks(math::SparseBlockAssembler& matrix) override;
  void assemble(const State& state, double load_factor, AssemblyTarget& target) const override;
  double potential_energy(const State&) const override { return 0.0; }
  bool constant_mass() const override { return !has_added_mass(); }

  /// The body's motion in the state.
  RigidBodyMotion motion(const State& state) const;
  /// The wrench of this load in the state (load factor 1).
  Wrench wrench_at(const State& state) const { return wrench(motion(state)); }

 protected:
  /// The load at the given motion (world axes, moment about the CG).
  virtual Wrench wrench(const RigidBodyMotion& m) const = 0;
  /// True when added_mass() is not zero.
  virtual bool has_added_mass() const { return false; }
  /// Added mass on (a_cg, alpha), world axes (kg, kg m, kg m^2).
  virtual Mat6 added_mass(const RigidBodyMotion&) const { return Mat6::Zero(); }
  /// True when the wrench depends on the velocities (drag, damping, radiation).
  virtual bool velocity_dependent() const { return true; }

 private:
  RigidBodyMotion motion_of(const Eigen::Matrix<double, 7, 1>& q,
                            const Eigen::Matrix<double, 7, 1>& v, double t) const;

  const RigidBody& body_;
  math::BlockId block_ = -1;
};

/// Velocity and angular velocity of the body-fixed point u (body axes from the CG), both
/// in body axes: the 6 generalized velocities of linear seakeeping (WAMIT's modes 1-6).
Vec6 body_velocity_at(const RigidBodyMotion& m, const Vec3& u);
/// Adds a force and moment (6-vector in body axes, moment about the body-fixed point u).
void add_body_wrench(Wrench& W, const RigidBodyMotion& m, const Vec3& u, const Vec6& f_body);

/// Maps a 6-vector (force, moment about a point rho from the CG) to a wrench about the
/// CG, and the rigid-body transformation of a 6x6 matrix given at that point.
/// T = [I, -skew(rho); 0, I] maps (v_cg, w) to (v_point, w).
Mat6 point_transform(const Vec3& rho);

}  // namespace seaflex
