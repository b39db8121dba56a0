#include "seaflex/solvers/stability.hpp"

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace seaflex {

StabilityReport check_stability(const Dae& dae, const State& state, double load_factor,
                                double threshold) {
  const Index n = dae.num_coordinates(), m = dae.num_constraints();
  DaeEval eval = dae.make_eval();
  DaeRequest req;
  req.forces = false;
  req.matrix = true;
  req.multiplier_hessian = true;
  req.scales.kq = 1.0;
  req.load_factor = load_factor;
  dae.evaluate(state, req, eval);
  const SpMat& kkt = eval.kkt.matrix();
  const SpMat K = kkt.topLeftCorner(n, n);
  SpMat A = 0.5 * (SpMat(K.transpose()) + K);
  // Jacobi scaling by each row's largest entry (units differ between positions, slopes
  // and rotations): the scaled matrix has entries of order one at most
  VecX s = VecX::Zero(n);
  for (Index j = 0; j < A.outerSize(); ++j)
    for (SpMat::InnerIterator it(A, j); it; ++it)
      s[it.row()] = std::max(s[it.row()], std::abs(it.value()));
  for (Index i = 0; i < n; ++i) s[i] = s[i] > 0.0 ? 1.0 / std::sqrt(s[i]) : 1.0;
  A = s.asDiagonal() * A * s.asDiagonal();
  if (m > 0) {
    // the constraint rows in the scaled coordinates, each of unit length (the same null
    // space), penalized by rho = 1e9: the null space's pivots then differ from those of
    // Z^T K Z by about |K_zc|^2 / rho ~ 1e-9 (entries of order one) and carry round-off of
    // about rho eps ~ 2e-7, both far below the threshold (with rho = 1e6 the zero-stiffness
    // spin of examples/tip_body.yaml came out at -0.012: Finsler's rho* was not reached)
    SpMat C = SpMat(kkt.bottomLeftCorner(m, n)) * s.asDiagonal();
    VecX norm = VecX::Zero(m);
    for (Index j = 0; j < C.outerSize(); ++j)
      for (SpMat::InnerIterator it(C, j); it; ++it) norm[it.row()] += it.value() * it.value();
    for (Index r = 0; r < m; ++r) norm[r] = norm[r] > 0.0 ? 1.0 / std::sqrt(norm[r]) : 0.0;
    C = norm.asDiagonal() * C;
    A += 1e9 * SpMat(SpMat(C.transpose()) * C);
  }
  // a shift of 1e-8 (scaled): a mode without any stiffness is then a small positive pivot,
  // not a zero one that would stop the factorization
  SpMat shift(n, n);
  shift.setIdentity();
  A += 1e-8 * shift;
  A.makeCompressed();
  StabilityReport report;
  Eigen::SimplicialLDLT<SpMat, Eigen::Lower> ldlt(A);
  if (ldlt.info() != Eigen::Success) {
    report.factored = false;
    return report;
  }
  const VecX D = ldlt.vectorD();
  // P A P^T = L D L^T: pivot k belongs to coordinate Pinv(k)
  const auto& perm = ldlt.permutationPinv();
  for (Index k = 0; k < n; ++k) {
    if (!(D[k] < -threshold)) continue;
    ++report.negative;
    if (D[k] < report.most_negative) {
      report.most_negative = D[k];
      report.worst = perm.indices()[k];
    }
  }
  return report;
}

std::string describe_instability(const Dae& dae, const StabilityReport& report) {
  if (report.negative == 0) return {};
  return fmt::format(
      "the equilibrium found is unstable: {} direction{} of negative stiffness, the largest at "
      "{} (a line folded or kinked by the first guess or the load steps, or in compression "
      "far beyond its buckling load); dynamics from it moves away. Try other statics."
      "load_steps, a first guess nearer the equilibrium (length: starts a line as its "
      "catenary), or check the effective tension for compression; seaflex modes lists the "
      "unstable modes",
      report.negative, report.negative == 1 ? "" : "s", dae.coordinate_name(report.worst));
}

}  // namespace seaflex
