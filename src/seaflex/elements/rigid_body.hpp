// A rigid body with Euler parameters (Nikravesh 1988, ch. 6 and 11; Haug 1989, ch. 11):
// q = (r, p), r the centre of gravity in the world, p = (e0, e1, e2, e3) with |p| = 1
// held by a normalization constraint, v = q'. No singular attitude exists, unlike the
// thesis's Z-X-Z angles of eq. (136), which are accepted only as input.
//   M = diag(m I, 4 Gbar^T J' Gbar),  Q_v = -8 Gbar(p')^T J' Gbar(p) p'  (gyroscopic),
//   T = 1/2 m r'.r' + 1/2 w'^T J' w',  w' = 2 Gbar(p) p'  (body axes).
#pragma once

#include <memory>

#include "seaflex/math/rotation.hpp"
#include "seaflex/math/sparse_block_assembler.hpp"
#include "seaflex/model/body.hpp"
#include "seaflex/model/marker.hpp"

namespace seaflex {

struct RigidBodyInitial {
  Vec3 position = Vec3::Zero();          ///< centre of gravity (m)
  Mat3 orientation = Mat3::Identity();   ///< body axes in the world (columns)
  Vec3 velocity = Vec3::Zero();          ///< of the centre of gravity (m/s)
  Vec3 angular_velocity = Vec3::Zero();  ///< world axes (rad/s)
};

class RigidBody : public Body {
 public:
  /// inertia: about the centre of gravity in body axes (kg m^2), symmetric positive
  /// definite (checked by the model loader, which reports the offending entry).
  RigidBody(std::string name, double mass, const Mat3& inertia, const RigidBodyInitial& initial);

  std::string_view kind() const override { return "rigid_body"; }
  Index num_coordinates() const override { return 7; }
  void write_initial_state(VecX& q, VecX& v) const override;
  void declare_blocks(math::SparseBlockAssembler& matrix) override;
  void assemble(const State& state, AssemblyTarget& target) const override;
  bool constant_mass() const override { return false; }
  void add_gravity(const Vec3& g, const State& state, AssemblyTarget& target) const override;
  double gravity_potential(const Vec3& g, const State& state) const override;
  double kinetic_energy(const State& state) const override;
  double strain_energy(const State&) const override { return 0.0; }
  std::string coordinate_name(Index local) const override;
  std::string summary() const override;
  void add_channels(ChannelList& channels) const override;
  std::vector<std::unique_ptr<Constraint>> internal_constraints() const override;
  /// |dp| <= 0.25 per Newton iteration (a turn of about 30 degrees): a full step can carry
  /// the body onto the mirror branch of its joint conditions (upside down).
  double step_scale(const State& state, const VecX& dq) const override;

  double mass() const { return mass_; }
  /// The initial position, attitude and velocities, as built.
  const RigidBodyInitial& initial() const { return initial_; }
  const Mat3& inertia() const { return inertia_; }

  Vec3 position(const State& state) const;
  math::Vec4 euler_parameters(const State& state) const;  ///< normalized
  Mat3 orientation(const State& state) const;             ///< body axes in the world
  Vec3 velocity(const State& state) const;
  Vec3 angular_velocity(const State& state) const;  ///< world axes (rad/s)
  Vec3 angular_momentum(const State& state) const;  ///< about the centre of gravity, world axes

 private:
  double mass_;
  Mat3 inertia_;
  RigidBodyInitial initial_;
  math::BlockId block_ = -1;
};

/// A point and frame fixed on a rigid body: the point r + A(p) u and the axes A(p) f_k,
/// with u and the columns f_k of frame in body axes relative to the centre of gravity.
class RigidBodyMarker : public Marker {
 public:
  RigidBodyMarker(const RigidBody& body, const Vec3& local_position,
                  const Mat3& local_frame = Mat3::Identity());
  std::string describe() const override;
  const Body* body() const override { return &body_; }
  std::vector<Index> coordinates() const override;
  bool has(MarkerVector) const override { return true; }
  void evaluate(MarkerVector which, const State& state, MarkerVectorEval& out) const override;
  void add_hessian(MarkerVector which, const State& state, const Vec3& F,
                   Eigen::Ref<MatX> H) const override;
  bool linear() const override { return false; }

 private:
  const RigidBody& body_;
  Vec3 local_position_;
  std::array<std::array<math::Mat4, 3>, 4> forms_;  // per MarkerVector: S_i
};

/// |p|^2 - 1 = 0 for the Euler parameters of a rigid body (Nikravesh eq. 6.25).
class EulerParameterNormalization : public Constraint {
 public:
  explicit EulerParameterNormalization(const RigidBody& body);
  Index num_rows() const override { return 1; }
  std::vector<Index> coordinates() const override;
  bool is_linear() const override { return false; }
  void evaluate(const State& state, ConstraintEval& out) const override;
  void add_multiplier_hessian(const State& state, const Eigen::Ref<const VecX>& mu,
                              Eigen::Ref<MatX> H) const override;
  std::string row_name(Index) const override;

 private:
  const RigidBody& body_;
};

}  // namespace seaflex
