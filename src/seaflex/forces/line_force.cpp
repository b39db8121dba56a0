#include "seaflex/forces/line_force.hpp"

namespace seaflex {

void assemble_line_force(const MarkerPair& pair, const PairVectorEval& d, const LineTension& t,
                         const State& state, math::BlockId block, AssemblyTarget& target) {
  const auto& dofs = pair.dofs();
  const double L = d.value.norm();
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
    pair.add_hessian(MarkerVector::kPoint, -1.0, 1.0, state, -f, dQ);
    A -= k.kq * dQ;
  }
  if (k.kv != 0.0 && t.dT_dLd != 0.0)
    A += k.kv * t.dT_dLd * d.J.transpose() * n * n.transpose() * d.J;  // -kv dQ/dv
  target.matrix->add(block, A);
}

}  // namespace seaflex
