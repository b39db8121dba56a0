#include "seaflex/solvers/stability.hpp"

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <vector>

#include <fmt/format.h>

namespace seaflex {

StabilityReport check_stability(const Dae& dae, const State& state, double load_factor,
                                double threshold) {
  DaeEval eval = dae.make_eval();
  DaeRequest req;
  req.forces = false;
  req.matrix = true;
  req.multiplier_hessian = true;
  req.scales.kq = 1.0;
  req.load_factor = load_factor;
  dae.evaluate(state, req, eval);
  return check_stability(eval.kkt.matrix(), dae.num_coordinates(), dae.num_constraints(),
                         threshold);
}

StabilityReport check_stability(const SpMat& kkt, Index n, Index m, double threshold) {
  // the lower triangle of A = S sym(K) S + rho (C S)^T (C S) + 1e-8 I, in one pass over the
  // KKT matrix's entries (SimplicialLDLT reads the lower triangle only; no copies of K)
  // Jacobi scaling S = diag(s): s_i = 1 / sqrt of the largest |K| in row and column i
  // (units differ between positions, slopes and rotations): the scaled entries of sym(K)
  // are then at most one
  VecX big = VecX::Zero(n);
  for (Index j = 0; j < n; ++j)
    for (SpMat::InnerIterator it(kkt, j); it && it.row() < n; ++it) {
      const double a = std::abs(it.value());
      big[it.row()] = std::max(big[it.row()], a);
      big[j] = std::max(big[j], a);
    }
  VecX s(n);
  for (Index i = 0; i < n; ++i) s[i] = big[i] > 0.0 ? 1.0 / std::sqrt(big[i]) : 1.0;
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<std::size_t>(kkt.nonZeros()) + static_cast<std::size_t>(n));
  for (Index j = 0; j < n; ++j)
    for (SpMat::InnerIterator it(kkt, j); it && it.row() < n; ++it) {
      const Index i = it.row();
      const double v = it.value() * s[i] * s[j];
      if (i == j)
        entries.emplace_back(i, i, v);
      else  // each of K_ij and K_ji gives half of the symmetric part's lower entry
        entries.emplace_back(std::max(i, j), std::min(i, j), 0.5 * v);
    }
  // a shift of 1e-8: a mode without any stiffness is then a small positive pivot,
  // not a zero one that would stop the factorization (a diagonal missing from K included)
  for (Index i = 0; i < n; ++i) entries.emplace_back(i, i, 1e-8);
  if (m > 0) {
    // the constraint rows in the scaled coordinates, each of unit length (the same null
    // space), penalized by rho = 1e9: the null space's pivots then differ from those of
    // Z^T K Z by about |K_zc|^2 / rho ~ 1e-9 (entries of order one) and carry round-off of
    // about rho eps ~ 2e-7, both far below the threshold (with rho = 1e6 the zero-stiffness
    // spin of examples/tip_body.yaml came out at -0.012: Finsler's rho* was not reached)
    const SpMat C = SpMat(kkt.bottomLeftCorner(m, n).transpose());  // n x m: rows by column
    for (Index r = 0; r < m; ++r) {
      double norm2 = 0.0;
      for (SpMat::InnerIterator a(C, r); a; ++a) norm2 += std::pow(a.value() * s[a.row()], 2);
      if (!(norm2 > 0.0)) continue;
      const double w = 1e9 / norm2;
      for (SpMat::InnerIterator a(C, r); a; ++a)
        for (SpMat::InnerIterator b(C, r); b; ++b)
          if (a.row() >= b.row())
            entries.emplace_back(a.row(), b.row(),
                                 w * a.value() * s[a.row()] * b.value() * s[b.row()]);
    }
  }
  SpMat A(n, n);
  A.setFromTriplets(entries.begin(), entries.end());
  entries = {};
  StabilityReport report;
  // AMD's fill-reducing order. The pivots' sizes depend on the order, and with them which
  // near-zero ones pass the threshold: in the model's own numbering the free yaw of
  // barge_riser's barge (its Euler parameter e3, eliminated first) came out at -0.021 and
  // counted, where AMD leaves it at round-off; the modes' dense count is the exact one.
  // Memory: a 50,000-element riser's statics peaks at 970 MB with this check, 585 MB
  // without it (docs/performance.md)
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
      report.worst = perm.size() == n ? perm.indices()[k] : k;  // empty: no permutation
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
