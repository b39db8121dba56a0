#include "seaflex/forces/rigid_body_load.hpp"

#include <algorithm>
#include <cmath>

#include "seaflex/math/rotation.hpp"

namespace seaflex {

namespace {
using Vec7 = Eigen::Matrix<double, 7, 1>;
using Mat7 = Eigen::Matrix<double, 7, 7>;
}  // namespace

Mat6 point_transform(const Vec3& rho) {
  Mat6 T = Mat6::Identity();
  T.block<3, 3>(0, 3) = -math::skew(rho);
  return T;
}

Vec6 body_velocity_at(const RigidBodyMotion& m, const Vec3& u) {
  Vec6 v;
  v.head<3>() = m.R.transpose() * m.point_velocity(u);
  v.tail<3>() = m.R.transpose() * m.w;
  return v;
}

void add_body_wrench(Wrench& W, const RigidBodyMotion& m, const Vec3& u, const Vec6& f_body) {
  const Vec3 f = m.R * f_body.head<3>();
  W.force += f;
  W.moment += m.R * f_body.tail<3>() + (m.R * u).cross(f);
}

RigidBodyLoad::RigidBodyLoad(std::string name, const RigidBody& body)
    : Force(std::move(name)), body_(body) {}

void RigidBodyLoad::declare_blocks(math::SparseBlockAssembler& matrix) {
  std::vector<Index> dofs(7);
  for (Index i = 0; i < 7; ++i) dofs[i] = body_.offset() + i;
  block_ = matrix.declare_block(dofs, dofs);
}

RigidBodyMotion RigidBodyLoad::motion_of(const Vec7& q, const Vec7& v, double t) const {
  const math::Vec4 p = q.tail<4>();
  const math::Vec4 pd = v.tail<4>();
  RigidBodyMotion m;
  m.r = q.head<3>();
  m.R = math::rotation_from_euler_parameters(p);
  m.v = v.head<3>();
  m.w = 2.0 * math::euler_g(p) * pd;  // world angular velocity, Nikravesh eq. 6.98
  m.t = t;
  return m;
}

RigidBodyMotion RigidBodyLoad::motion(const State& state) const {
  return motion_of(state.q.segment<7>(body_.offset()), state.v.segment<7>(body_.offset()), state.t);
}

void RigidBodyLoad::assemble(const State& state, double load_factor, AssemblyTarget& target) const {
  const Index o = body_.offset();
  const Vec7 q = state.q.segment<7>(o);
  const Vec7 v = state.v.segment<7>(o);
  // Q = J^T (F, N): F on r, 2 G^T N on p
  auto generalized_force = [&](const Vec7& qq, const Vec7& vv) {
    const Wrench W = wrench(motion_of(qq, vv, state.t));
    Vec7 Q;
    Q.head<3>() = W.force;
    Q.tail<4>() = 2.0 * math::euler_g(qq.tail<4>()).transpose() * W.moment;
    return Q;
  };
  if (target.forces) target.forces->segment<7>(o) += load_factor * generalized_force(q, v);
  if (!target.matrix) return;
  const MatrixScales& s = target.scales;
  Mat7 A = Mat7::Zero();
  if (s.km != 0.0 && has_added_mass()) {
    Eigen::Matrix<double, 6, 7> J = Eigen::Matrix<double, 6, 7>::Zero();
    J.block<3, 3>(0, 0).setIdentity();
    J.block<3, 4>(3, 3) = 2.0 * math::euler_g(q.tail<4>());
    A += s.km * J.transpose() * added_mass(motion_of(q, v, state.t)) * J;
  }
  if (s.kq != 0.0 && has_added_mass() && target.acceleration) {
    // the added mass turns with the body: d(M_a(q) a)/dq by central differences
    const Vec7 a = target.acceleration->segment<7>(o);
    auto mass_times = [&](const Vec7& qq) {
      Eigen::Matrix<double, 6, 7> J = Eigen::Matrix<double, 6, 7>::Zero();
      J.block<3, 3>(0, 0).setIdentity();
      J.block<3, 4>(3, 3) = 2.0 * math::euler_g(qq.tail<4>());
      return Vec7(J.transpose() * (added_mass(motion_of(qq, v, state.t)) * (J * a)));
    };
    const double hr = 1e-6 * std::max(1.0, q.head<3>().lpNorm<Eigen::Infinity>());
    for (int i = 0; i < 7; ++i) {
      const double h = i < 3 ? hr : 1e-7;
      Vec7 qp = q, qm = q;
      qp[i] += h;
      qm[i] -= h;
      A.col(i) += s.kq * (mass_times(qp) - mass_times(qm)) / (2.0 * h);
    }
  }
  // central differences of Q over the body's coordinates and velocities
  const double hr = 1e-6 * std::max(1.0, q.head<3>().lpNorm<Eigen::Infinity>());
  if (s.kq != 0.0) {
    for (int i = 0; i < 7; ++i) {
      const double h = i < 3 ? hr : 1e-7;
      Vec7 qp = q, qm = q;
      qp[i] += h;
      qm[i] -= h;
      A.col(i) -=
          s.kq * load_factor * (generalized_force(qp, v) - generalized_force(qm, v)) / (2.0 * h);
    }
  }
  if (s.kv != 0.0 && velocity_dependent()) {
    const double hv = 1e-6 * std::max(1.0, v.head<3>().lpNorm<Eigen::Infinity>());
    for (int i = 0; i < 7; ++i) {
      const double h = i < 3 ? hv : 1e-7;
      Vec7 vp = v, vm = v;
      vp[i] += h;
      vm[i] -= h;
      A.col(i) -=
          s.kv * load_factor * (generalized_force(q, vp) - generalized_force(q, vm)) / (2.0 * h);
    }
  }
  target.matrix->add(block_, A);
}

}  // namespace seaflex
