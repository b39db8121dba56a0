#include "seaflex/forces/line_force.hpp"

#include <fmt/format.h>

#include "seaflex/core/errors.hpp"

namespace seaflex {

LineForce::LineForce(std::string name, std::unique_ptr<Marker> a, std::unique_ptr<Marker> b)
    : Force(std::move(name)), pair_(std::move(a), std::move(b)) {}

void LineForce::declare_blocks(math::SparseBlockAssembler& matrix) {
  const auto& dofs = pair_.bind();
  block_ = dofs.empty() ? -1 : matrix.declare_block(dofs, dofs);
}

double LineForce::length(const State& state) const {
  return (pair_.b().position(state) - pair_.a().position(state)).norm();
}

LineState LineForce::line(const State& state) const {
  LineState s;
  pair_.evaluate(MarkerVector::kPoint, -1.0, 1.0, state, s.d);
  s.length = s.d.value.norm();
  s.rate = s.length > 0.0 ? s.d.value.dot(s.d.rate) / s.length : 0.0;
  return s;
}

LineState LineForce::line_for_assembly(const State& state, const char* what) const {
  LineState s = line(state);
  if (!(s.length > 0.0))
    throw SolverError(fmt::format("t = {:.6g} s: the end points of {} {} met, so its line of "
                                  "action is undefined",
                                  state.t, what, name()),
                      state.t);
  return s;
}

void LineForce::assemble_line(const LineState& line, const LineTension& t, const State& state,
                              AssemblyTarget& target) const {
  const PairVectorEval& d = line.d;
  const auto& dofs = pair_.dofs();
  const double L = line.length;
  const Vec3 n = d.value / L;
  const Vec3 f = t.T * n;  // force on a; -f on b: Q = -J_d^T f
  const Index m = static_cast<Index>(dofs.size());
  if (target.forces)
    for (Index i = 0; i < m; ++i) (*target.forces)[dofs[i]] -= d.J.col(i).dot(f);
  if (!target.matrix) return;
  const MatrixScales& k = target.scales;
  PairSquare A = PairSquare::Zero(m, m);
  if (k.kq != 0.0) {
    const Mat3 P = Mat3::Identity() - n * n.transpose();
    // df/dd with d' held; L' = n . d' depends on d through n
    const Mat3 dfdd =
        t.dT_dL * n * n.transpose() + (t.T / L) * P + t.dT_dLd * n * (P * d.rate).transpose() / L;
    const Mat3 dfdrate = t.dT_dLd * n * n.transpose();
    // dQ/dq = -(J^T df/dd J + d(J^T f)/dq + J^T df/dd' d(d')/dq)
    PairSquare dQ = -(d.J.transpose() * dfdd * d.J + d.J.transpose() * dfdrate * d.Jv);
    pair_.add_hessian(MarkerVector::kPoint, -1.0, 1.0, state, -f, dQ);
    A -= k.kq * dQ;
  }
  if (k.kv != 0.0 && t.dT_dLd != 0.0)
    A += k.kv * t.dT_dLd * d.J.transpose() * n * n.transpose() * d.J;  // -kv dQ/dv
  target.matrix->add(block_, A);
}

}  // namespace seaflex
