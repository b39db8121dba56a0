#include "seaflex/elements/rigid_body.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

namespace seaflex {

namespace {

using math::Mat34;
using math::Mat4;
using math::Vec4;

constexpr double kDeg = 180.0 / std::numbers::pi;

// B(w) a = Gbar(a)^T w for every a (Gbar is linear in its argument)
Mat4 gbar_transpose_times(const Vec3& w) {
  Mat4 B;
  B(0, 0) = 0.0;
  B.block<1, 3>(0, 1) = -w.transpose();
  B.block<3, 1>(1, 0) = w;
  B.block<3, 3>(1, 1) = -math::skew(w);
  return B;
}

}  // namespace

RigidBody::RigidBody(std::string name, double mass, const Mat3& inertia,
                     const RigidBodyInitial& initial)
    : Body(std::move(name)), mass_(mass), inertia_(inertia), initial_(initial) {}

void RigidBody::write_initial_state(VecX& q, VecX& v) const {
  const Vec4 p = math::euler_parameters_from_rotation(initial_.orientation);
  q.segment<3>(offset()) = initial_.position;
  q.segment<4>(offset() + 3) = p;
  v.segment<3>(offset()) = initial_.velocity;
  // w = 2 G p' and G G^T = I, G p = 0: p' = 1/2 G^T w also satisfies p . p' = 0
  v.segment<4>(offset() + 3) = 0.5 * math::euler_g(p).transpose() * initial_.angular_velocity;
}

void RigidBody::declare_blocks(math::SparseBlockAssembler& matrix) {
  std::vector<Index> dofs(7);
  for (Index i = 0; i < 7; ++i) dofs[i] = offset() + i;
  block_ = matrix.declare_block(dofs, dofs);
}

void RigidBody::assemble(const State& state, AssemblyTarget& target) const {
  const Vec4 p = state.q.segment<4>(offset() + 3);
  const Vec4 pd = state.v.segment<4>(offset() + 3);
  const Mat34 Gb = math::euler_gbar(p);
  const Mat34 Gbd = math::euler_gbar(pd);
  const Vec3 w = inertia_ * (Gb * pd);  // J' w' / 2
  if (target.forces) {
    // quadratic velocity force, Nikravesh eq. (11.31): -8 Gbar'^T J' Gbar p'
    target.forces->segment<4>(offset() + 3) += -8.0 * Gbd.transpose() * w;
  }
  if (!target.matrix) return;
  const MatrixScales& k = target.scales;
  Eigen::Matrix<double, 7, 7> A = Eigen::Matrix<double, 7, 7>::Zero();
  if (k.km != 0.0) {
    A.topLeftCorner<3, 3>().diagonal().setConstant(k.km * mass_);
    A.bottomRightCorner<4, 4>() += k.km * 4.0 * Gb.transpose() * inertia_ * Gb;
  }
  // dQ_v/dp = 8 Gbar(p')^T J' Gbar(p'), since Gbar(p) p' = -Gbar(p') p
  if (k.kq != 0.0) A.bottomRightCorner<4, 4>() -= k.kq * 8.0 * Gbd.transpose() * inertia_ * Gbd;
  // dQ_v/dp' = -8 (B(J' Gbar p') + Gbar(p')^T J' Gbar(p))
  if (k.kv != 0.0)
    A.bottomRightCorner<4, 4>() +=
        k.kv * 8.0 * (gbar_transpose_times(w) + Gbd.transpose() * inertia_ * Gb);
  if (k.kq != 0.0 && target.acceleration) {
    // d(M a)/dp of M_pp = 4 Gbar(p)^T J' Gbar(p): with Gbar(p) a_p = -Gbar(a_p) p and
    // Gbar(p)^T x = B(x) p, d(M a)/dp = 4 (B(J' Gbar(p) a_p) - Gbar(p)^T J' Gbar(a_p))
    const Vec4 ap = target.acceleration->segment<4>(offset() + 3);
    A.bottomRightCorner<4, 4>() += k.kq * 4.0 *
                                   (gbar_transpose_times(inertia_ * (Gb * ap)) -
                                    Gb.transpose() * inertia_ * math::euler_gbar(ap));
  }
  target.matrix->add(block_, A);
}

void RigidBody::add_gravity(const Vec3& g, const State&, AssemblyTarget& target) const {
  if (target.forces) target.forces->segment<3>(offset()) += mass_ * g;
}

double RigidBody::gravity_potential(const Vec3& g, const State& state) const {
  return -mass_ * g.dot(position(state));
}

double RigidBody::kinetic_energy(const State& state) const {
  const Vec3 wb =
      2.0 * math::euler_gbar(state.q.segment<4>(offset() + 3)) * state.v.segment<4>(offset() + 3);
  return 0.5 * mass_ * velocity(state).squaredNorm() + 0.5 * wb.dot(inertia_ * wb);
}

std::string RigidBody::coordinate_name(Index local) const {
  static const char* names[] = {"x", "y", "z", "e0", "e1", "e2", "e3"};
  return local >= 0 && local < 7 ? fmt::format("{}.{}", name(), names[local])
                                 : fmt::format("{}.q{}", name(), local);
}

std::string RigidBody::summary() const {
  const Eigen::SelfAdjointEigenSolver<Mat3> eig(inertia_);
  const Vec3 I = eig.eigenvalues();
  return fmt::format(
      "rigid body, mass {:g} kg, principal inertias {:.6g}, {:.6g}, {:.6g} kg m^2, 7 "
      "coordinates (Euler parameters)",
      mass_, I[0], I[1], I[2]);
}

Vec3 RigidBody::position(const State& state) const {
  return state.q.segment<3>(offset());
}

Vec4 RigidBody::euler_parameters(const State& state) const {
  return state.q.segment<4>(offset() + 3).normalized();
}

Mat3 RigidBody::orientation(const State& state) const {
  return math::rotation_from_euler_parameters(euler_parameters(state));
}

Vec3 RigidBody::velocity(const State& state) const {
  return state.v.segment<3>(offset());
}

Vec3 RigidBody::angular_velocity(const State& state) const {
  return 2.0 * math::euler_g(euler_parameters(state)) * state.v.segment<4>(offset() + 3);
}

Vec3 RigidBody::angular_momentum(const State& state) const {
  const Vec4 p = euler_parameters(state);
  const Vec3 wb = 2.0 * math::euler_gbar(p) * state.v.segment<4>(offset() + 3);
  return math::rotation_from_euler_parameters(p) * (inertia_ * wb);
}

void RigidBody::add_channels(ChannelList& channels) const {
  const std::string& n = name();
  for (int i = 0; i < 3; ++i) {
    channels.push_back(
        {fmt::format("{}.{}", n, "xyz"[i]), [this, i](const State& s) { return position(s)[i]; }});
  }
  static const char* angles[] = {"roll", "pitch", "yaw"};
  for (int i = 0; i < 3; ++i) {
    channels.push_back({fmt::format("{}.{}", n, angles[i]), [this, i](const State& s) {
                          return kDeg * math::roll_pitch_yaw_from_rotation(orientation(s))[i];
                        }});
  }
  for (int i = 0; i < 3; ++i) {
    channels.push_back(
        {fmt::format("{}.v{}", n, "xyz"[i]), [this, i](const State& s) { return velocity(s)[i]; }});
  }
  for (int i = 0; i < 3; ++i) {
    channels.push_back({fmt::format("{}.w{}", n, "xyz"[i]),
                        [this, i](const State& s) { return kDeg * angular_velocity(s)[i]; }});
  }
}

double RigidBody::step_scale(const State&, const VecX& dq) const {
  const double dp = dq.segment<4>(offset() + 3).norm();
  return dp > 0.25 ? 0.25 / dp : 1.0;
}

std::vector<std::unique_ptr<Constraint>> RigidBody::internal_constraints() const {
  std::vector<std::unique_ptr<Constraint>> list;
  list.push_back(std::make_unique<EulerParameterNormalization>(*this));
  return list;
}

// ---------------------------------------------------------------------------------------

RigidBodyMarker::RigidBodyMarker(const RigidBody& body, const Vec3& local_position,
                                 const Mat3& local_frame)
    : body_(body), local_position_(local_position) {
  forms_[0] = math::rotation_quadratic_forms(local_position);
  for (int k = 0; k < 3; ++k) forms_[k + 1] = math::rotation_quadratic_forms(local_frame.col(k));
}

std::string RigidBodyMarker::describe() const {
  return fmt::format("{}@({:g}, {:g}, {:g})", body_.name(), local_position_.x(),
                     local_position_.y(), local_position_.z());
}

std::vector<Index> RigidBodyMarker::coordinates() const {
  std::vector<Index> dofs(7);
  for (Index i = 0; i < 7; ++i) dofs[i] = body_.offset() + i;
  return dofs;
}

void RigidBodyMarker::evaluate(MarkerVector which, const State& state,
                               MarkerVectorEval& out) const {
  const int k = static_cast<int>(which);
  const auto& S = forms_[k];
  const Vec4 p = state.q.segment<4>(body_.offset() + 3);
  const Vec4 pd = state.v.segment<4>(body_.offset() + 3);
  out.J.setZero(3, 7);
  out.Jv.setZero(3, 7);
  for (int i = 0; i < 3; ++i) {
    // x_i = p^T S_i p: J = 2 p^T S_i, J' v = 2 p'^T S_i p', d(J v)/dp = 2 p'^T S_i
    out.value[i] = p.dot(S[i] * p);
    out.J.block<1, 4>(i, 3) = 2.0 * (S[i] * p).transpose();
    out.Jv.block<1, 4>(i, 3) = 2.0 * (S[i] * pd).transpose();
    out.bias[i] = 2.0 * pd.dot(S[i] * pd);
  }
  if (which == MarkerVector::kPoint) {
    out.value += body_.position(state);
    out.J.leftCols<3>().setIdentity();
  }
  out.rate = out.J * state.v.segment<7>(body_.offset());
}

void RigidBodyMarker::add_hessian(MarkerVector which, const State&, const Vec3& F,
                                  Eigen::Ref<MatX> H) const {
  const auto& S = forms_[static_cast<int>(which)];
  H.block<4, 4>(3, 3) += 2.0 * (F[0] * S[0] + F[1] * S[1] + F[2] * S[2]);
}

// ---------------------------------------------------------------------------------------

EulerParameterNormalization::EulerParameterNormalization(const RigidBody& body)
    : Constraint(body.name() + " Euler parameters"), body_(body) {}

std::vector<Index> EulerParameterNormalization::coordinates() const {
  return {body_.offset() + 3, body_.offset() + 4, body_.offset() + 5, body_.offset() + 6};
}

void EulerParameterNormalization::evaluate(const State& state, ConstraintEval& out) const {
  const Vec4 p = state.q.segment<4>(body_.offset() + 3);
  const Vec4 pd = state.v.segment<4>(body_.offset() + 3);
  out.C[0] = p.squaredNorm() - 1.0;
  out.Cq.row(0) = 2.0 * p.transpose();
  out.Ct[0] = 0.0;
  out.gamma[0] = -2.0 * pd.squaredNorm();  // eq. (133): -(C_q q')_q q'
}

void EulerParameterNormalization::add_multiplier_hessian(const State&,
                                                         const Eigen::Ref<const VecX>& mu,
                                                         Eigen::Ref<MatX> H) const {
  H.diagonal().array() += 2.0 * mu[0];
}

std::string EulerParameterNormalization::row_name(Index) const {
  return fmt::format("{}: |p|^2 = 1", name());
}

}  // namespace seaflex
