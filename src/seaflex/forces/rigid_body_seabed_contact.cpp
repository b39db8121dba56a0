#include "seaflex/forces/rigid_body_seabed_contact.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace seaflex {

namespace {
using Mat7 = Eigen::Matrix<double, 7, 7>;
using Mat37 = Eigen::Matrix<double, 3, 7>;
}  // namespace

RigidBodySeabedContact::RigidBodySeabedContact(std::string name, const RigidBody& body,
                                               std::shared_ptr<const hydro::Seabed> seabed,
                                               std::vector<SeabedContactPoint> points,
                                               PointContactProperties properties)
    : Force(std::move(name)),
      body_(body),
      seabed_(std::move(seabed)),
      points_(std::move(points)),
      properties_(properties) {
  if (points_.empty())
    throw std::invalid_argument("RigidBodySeabedContact: needs at least one point");
  double K = 0.0;
  for (const auto& p : points_) {
    if (!(p.stiffness > 0.0) || !std::isfinite(p.stiffness))
      throw std::invalid_argument("RigidBodySeabedContact: every stiffness must be > 0");
    K += p.stiffness;
    markers_.emplace_back(body_, p.position);
  }
  // the points share 2 zeta sqrt(K m) in proportion to their stiffness
  for (const auto& p : points_)
    c_.push_back(2.0 * properties_.damping * p.stiffness * std::sqrt(body_.mass() / K));
}

void RigidBodySeabedContact::declare_blocks(math::SparseBlockAssembler& matrix) {
  std::vector<Index> dofs(7);
  for (Index i = 0; i < 7; ++i) dofs[i] = body_.offset() + i;
  block_ = matrix.declare_block(dofs, dofs);
}

RigidBodySeabedContact::Eval RigidBodySeabedContact::evaluate(int i, const Vec3& x, const Vec3& xd,
                                                              bool derivatives) const {
  Eval out;
  const hydro::SeabedPoint sp = seabed_->at(x.x(), x.y());
  const Vec3 n = sp.normal();
  const double d = sp.penetration(x);
  out.f.penetration = d;
  const double k = points_[i].stiffness, c = c_[i];
  const double F = k * d - c * n.dot(xd);  // k d + c d', d' = -n . x'
  // no contact, or separating: no suction; at d = 0 exactly the point is in contact with
  // zero force (the one-sided tangent, as in the beam contact)
  if (!(d >= 0.0) || !(F >= 0.0)) return out;
  const double mu = properties_.friction, vs = properties_.slip_velocity;
  const Vec3 vt = xd - n * n.dot(xd);  // P x'
  const double s = std::sqrt(vt.squaredNorm() + vs * vs);
  out.f.normal = F * n;
  out.f.friction = -(mu * F / s) * vt;
  if (!derivatives) return out;
  // f = F (n - mu P x'/s): F carries the dependence on x (n is constant on a plane)
  const Vec3 g = n - (mu / s) * vt;
  out.df_dx = g * (-k * n.transpose());
  out.df_dxd = g * (-c * n.transpose());
  if (mu > 0.0) {
    const Mat3 P = Mat3::Identity() - n * n.transpose();
    out.df_dxd -= (mu * F) * (P / s - vt * vt.transpose() / (s * s * s));
  }
  return out;
}

void RigidBodySeabedContact::assemble(const State& state, double, AssemblyTarget& target) const {
  const MatrixScales& sc = target.scales;
  const bool want_matrix = target.matrix != nullptr && (sc.kq != 0.0 || sc.kv != 0.0);
  const Index o = body_.offset();
  // fixed-size scratch: no allocation per evaluation
  Mat7 A = Mat7::Zero();
  bool touched = false;
  MarkerVectorEval ev;
  for (int i = 0; i < num_points(); ++i) {
    markers_[i].evaluate(MarkerVector::kPoint, state, ev);
    const Eval e = evaluate(i, ev.value, ev.rate, want_matrix);
    const Vec3 f = e.f.normal + e.f.friction;
    if (f.isZero(0.0) && e.df_dx.isZero(0.0) && e.df_dxd.isZero(0.0)) continue;
    touched = true;
    const Mat37 J = ev.J;
    if (target.forces) target.forces->segment<7>(o) += J.transpose() * f;  // Q = J^T f
    if (!want_matrix) continue;
    if (sc.kq != 0.0) {
      Mat7 dQ = J.transpose() * (e.df_dx * J + e.df_dxd * Mat37(ev.Jv));
      markers_[i].add_hessian(MarkerVector::kPoint, state, f, dQ);  // d(J^T f)/dq, f held
      A -= sc.kq * dQ;
    }
    if (sc.kv != 0.0) A -= sc.kv * J.transpose() * e.df_dxd * J;
  }
  if (want_matrix && touched) target.matrix->add(block_, A);
}

RigidBodySeabedContact::PointForce RigidBodySeabedContact::point_force(const State& state,
                                                                       int i) const {
  MarkerVectorEval ev;
  markers_[i].evaluate(MarkerVector::kPoint, state, ev);
  return evaluate(i, ev.value, ev.rate, false).f;
}

double RigidBodySeabedContact::potential_energy(const State& state) const {
  double energy = 0.0;
  for (int i = 0; i < num_points(); ++i) {
    const Vec3 x = markers_[i].position(state);
    const double d = seabed_->at(x.x(), x.y()).penetration(x);
    if (d > 0.0) energy += 0.5 * points_[i].stiffness * d * d;
  }
  return energy;
}

void RigidBodySeabedContact::add_channels(ChannelList& channels) const {
  channels.push_back({name() + ".force", [this](const State& s) {
                        Vec3 total = Vec3::Zero();
                        for (int i = 0; i < num_points(); ++i) total += point_force(s, i).normal;
                        return total.norm();
                      }});
  channels.push_back({name() + ".friction", [this](const State& s) {
                        Vec3 total = Vec3::Zero();
                        for (int i = 0; i < num_points(); ++i) total += point_force(s, i).friction;
                        return total.norm();
                      }});
  for (int i = 0; i < num_points(); ++i)
    channels.push_back({fmt::format("{}.p{}.force", name(), i),
                        [this, i](const State& s) { return point_force(s, i).normal.norm(); }});
}

}  // namespace seaflex
