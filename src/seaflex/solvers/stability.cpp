#include "seaflex/solvers/stability.hpp"

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <vector>

#include <fmt/format.h>

namespace seaflex {

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
  // a shift of 1e-8: no exact zero pivot stops the factorization (a mode without any
  // stiffness, a diagonal missing from K)
  for (Index i = 0; i < n; ++i) entries.emplace_back(i, i, 1e-8);
  if (m > 0) {
    // the constraint rows in the scaled coordinates, each of unit length (the same null
    // space), penalized by rho = 1e9. A finite rho biases the null space's zero modes
    // negative (with rho = 1e6 the free spin of examples/tip_body.yaml came out at a pivot
    // of -0.012; at 1e9 it stays below the threshold) and round-off is about rho eps ~ 2e-7
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
  Index pivot = -1;  // the most negative pivot below -threshold
  double most_negative = 0.0;
  for (Index k = 0; k < n; ++k) {
    if (!(D[k] < -threshold)) continue;
    ++report.negative;
    if (D[k] < most_negative) {
      most_negative = D[k];
      pivot = k;
    }
  }
  if (pivot >= 0) {
    // a direction of negative stiffness: with P A P^T = L D L^T, x = P^T L^-T e_k gives
    // x^T A x = D_k < 0; in the model's coordinates d = S x. The warning names its largest
    // position (worst_position): the pivot's own row is often a slope, and any coordinate
    // of the fold (Euler's column at 1.2 P_cr: its mid node, where mode 1 moves most)
    VecX y = VecX::Zero(n);
    y[pivot] = 1.0;
    ldlt.matrixU().solveInPlace(y);
    report.direction = s.asDiagonal() * (ldlt.permutationPinv() * y);
  }
  return report;
}

Index worst_position(const Dae& dae, const VecX& direction) {
  // the coordinates by |d|, largest first; the first position (a name ending in .x, .y or
  // .z that is neither a slope r' nor a plate gradient r_p...), else the largest of all
  if (direction.size() != dae.num_coordinates() || direction.size() == 0) return -1;
  std::vector<Index> order(static_cast<std::size_t>(direction.size()));
  for (Index i = 0; i < direction.size(); ++i) order[static_cast<std::size_t>(i)] = i;
  std::sort(order.begin(), order.end(),
            [&](Index a, Index b) { return std::abs(direction[a]) > std::abs(direction[b]); });
  for (const Index i : order) {
    const std::string name = dae.coordinate_name(i);
    const auto dot = name.rfind('.');
    const std::string last = dot == std::string::npos ? name : name.substr(dot + 1);
    if ((last == "x" || last == "y" || last == "z") && name.find('\'') == std::string::npos &&
        name.find("r_p") == std::string::npos)
      return i;
  }
  return order.front();
}

std::string describe_instability(const Dae& dae, const StabilityReport& report) {
  if (report.negative == 0) return {};
  const Index at = worst_position(dae, report.direction);
  return fmt::format(
      "the equilibrium found is unstable: {} direction{} of negative stiffness, the most "
      "negative moving {} most (a line folded or kinked by the first guess or the load "
      "steps, or in compression far beyond its buckling load); a dynamic run started from it "
      "will leave it (the line buckles or snaps). Try a different statics.load_steps, start "
      "the line nearer its equilibrium (a beam's length with start and end starts it as its "
      "catenary), or check the effective tension for compression; seaflex modes lists the "
      "unstable modes",
      report.negative, report.negative == 1 ? "" : "s",
      at >= 0 ? dae.coordinate_name(at) : std::string("?"));
}

std::string describe_unstable_modes(int unstable, double lowest_omega2) {
  if (unstable == 0) return {};
  return fmt::format(
      "{} mode{} with negative stiffness (omega^2 down to {:.3g} rad^2/s^2), listed as 0 Hz: "
      "the state is not a stable equilibrium",
      unstable, unstable == 1 ? "" : "s", lowest_omega2);
}

}  // namespace seaflex
