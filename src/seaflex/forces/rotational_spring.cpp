#include "seaflex/forces/rotational_spring.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

namespace seaflex {

namespace {

using Mat6 = Eigen::Matrix<double, 6, 6>;
using Vec6 = Eigen::Matrix<double, 6, 1>;

double angle_between(const Vec3& a, const Vec3& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

// g(w) = theta^2: g' = 2 theta / sin(theta), g'' = 2 (sin - theta cos) / sin^3
void angle_square_derivatives(double theta, double& g1, double& g2) {
  const double t2 = theta * theta;
  if (theta < 1e-4) {  // series, error below 1e-16
    g1 = 2.0 * (1.0 + t2 / 6.0);
    g2 = 2.0 * (1.0 / 3.0 + 2.0 * t2 / 15.0);
    return;
  }
  const double s = std::sin(theta), c = std::cos(theta);
  g1 = 2.0 * theta / s;
  g2 = 2.0 * (s - theta * c) / (s * s * s);
}

// f = a^ . b^: gradient (6) and Hessian (6x6) with respect to (a, b)
void cosine_derivatives(const Vec3& a, const Vec3& b, Vec6& grad, Mat6& hess) {
  const double la = a.norm(), lb = b.norm();
  const Vec3 ah = a / la, bh = b / lb;
  const double f = ah.dot(bh);
  const Vec3 ga = (bh - f * ah) / la, gb = (ah - f * bh) / lb;
  const Mat3 I = Mat3::Identity();
  const Mat3 Pa = I - ah * ah.transpose(), Pb = I - bh * bh.transpose();
  grad << ga, gb;
  hess.block<3, 3>(0, 0) = -(ah * ga.transpose() + ga * ah.transpose() + f * Pa / la) / la;
  hess.block<3, 3>(3, 3) = -(bh * gb.transpose() + gb * bh.transpose() + f * Pb / lb) / lb;
  hess.block<3, 3>(0, 3) = Pb / (la * lb) - ah * gb.transpose() / la;
  hess.block<3, 3>(3, 0) = hess.block<3, 3>(0, 3).transpose();
}

}  // namespace

RotationalSpring::RotationalSpring(std::string name, std::unique_ptr<Marker> a,
                                   std::unique_ptr<Marker> b, double stiffness, double damping)
    : Force(std::move(name)),
      pair_(std::move(a), std::move(b)),
      stiffness_(stiffness),
      damping_(damping) {}

void RotationalSpring::declare_blocks(math::SparseBlockAssembler& matrix) {
  const auto& dofs = pair_.bind();
  block_ = dofs.empty() ? -1 : matrix.declare_block(dofs, dofs);
}

double RotationalSpring::angle(const State& state) const {
  PairVectorEval a, b;
  pair_.evaluate(MarkerVector::kAxisZ, 1.0, 0.0, state, a);
  pair_.evaluate(MarkerVector::kAxisZ, 0.0, 1.0, state, b);
  return angle_between(a.value, b.value);
}

Vec3 RotationalSpring::moment_on_b(const State& state) const {
  PairVectorEval a, b;
  pair_.evaluate(MarkerVector::kAxisZ, 1.0, 0.0, state, a);
  pair_.evaluate(MarkerVector::kAxisZ, 0.0, 1.0, state, b);
  const Vec3 n = a.value.cross(b.value);
  const double theta = angle_between(a.value, b.value);
  Vec3 M = Vec3::Zero();
  if (n.norm() > 0.0) M = -stiffness_ * theta * n.normalized();
  if (damping_ != 0.0) {
    const double la = a.value.norm(), lb = b.value.norm();
    const Vec3 ah = a.value / la, bh = b.value / lb;
    const Vec3 rdot = (b.rate - bh * bh.dot(b.rate)) / lb - (a.rate - ah * ah.dot(a.rate)) / la;
    M += bh.cross(-damping_ * rdot);
  }
  return M;
}

void RotationalSpring::assemble(const State& state, double, AssemblyTarget& target) const {
  const auto& dofs = pair_.dofs();
  if (dofs.empty()) return;
  const Index m = static_cast<Index>(dofs.size());
  PairVectorEval a, b;
  pair_.evaluate(MarkerVector::kAxisZ, 1.0, 0.0, state, a);
  pair_.evaluate(MarkerVector::kAxisZ, 0.0, 1.0, state, b);
  // stacked Jacobian of (a, b)
  Eigen::Matrix<double, 6, Eigen::Dynamic, Eigen::ColMajor, 6, kMaxPairCoordinates> J(6, m);
  J.topRows<3>() = a.J;
  J.bottomRows<3>() = b.J;
  Vec6 grad;
  Mat6 hess;
  cosine_derivatives(a.value, b.value, grad, hess);
  const double theta = angle_between(a.value, b.value);
  double g1 = 0.0, g2 = 0.0;
  angle_square_derivatives(theta, g1, g2);
  // V = k/2 g(1 - f): dV = -k/2 g' df, d2V = k/2 (g'' df df^T - g' d2f)
  const Vec6 dV = -0.5 * stiffness_ * g1 * grad;
  PairVector Q = -J.transpose() * dV;
  // damping on r = b^ - a^
  const double la = a.value.norm(), lb = b.value.norm();
  const Vec3 ah = a.value / la, bh = b.value / lb;
  const PairJacobian Jr = (Mat3::Identity() - bh * bh.transpose()) * b.J / lb -
                          (Mat3::Identity() - ah * ah.transpose()) * a.J / la;
  if (damping_ != 0.0) {
    PairVector v(m);  // gathered without a temporary index copy (no allocation per stage)
    for (Index i = 0; i < m; ++i) v[i] = state.v[dofs[i]];
    const Vec3 rdot = Jr * v;
    Q -= damping_ * Jr.transpose() * rdot;
  }
  if (target.forces)
    for (Index i = 0; i < m; ++i) (*target.forces)[dofs[i]] += Q[i];
  if (!target.matrix) return;
  const MatrixScales& k = target.scales;
  PairSquare A = PairSquare::Zero(m, m);
  if (k.kq != 0.0) {
    const Mat6 d2V = 0.5 * stiffness_ * (g2 * grad * grad.transpose() - g1 * hess);
    PairSquare dQ = -J.transpose() * d2V * J;
    pair_.add_hessian(MarkerVector::kAxisZ, 1.0, 0.0, state, -dV.head<3>(), dQ);
    pair_.add_hessian(MarkerVector::kAxisZ, 0.0, 1.0, state, -dV.tail<3>(), dQ);
    A -= k.kq * dQ;
  }
  if (k.kv != 0.0 && damping_ != 0.0) A += k.kv * damping_ * Jr.transpose() * Jr;
  target.matrix->add(block_, A);
}

double RotationalSpring::potential_energy(const State& state) const {
  const double theta = angle(state);
  return 0.5 * stiffness_ * theta * theta;
}

void RotationalSpring::add_channels(ChannelList& channels) const {
  channels.push_back({fmt::format("{}.angle", name()),
                      [this](const State& s) { return angle(s) * 180.0 / std::numbers::pi; }});
}

}  // namespace seaflex
