#include "seaflex/solvers/constraint_audit.hpp"

#include <Eigen/OrderingMethods>
#include <Eigen/SparseQR>
#include <algorithm>
#include <cmath>

namespace seaflex {

ConstraintAudit audit_constraints(const Dae& dae, const State& state, double violation_tolerance,
                                  double velocity_tolerance, double rank_tolerance) {
  ConstraintAudit audit;
  const Index n = dae.num_coordinates();
  const Index m = dae.num_constraints();
  if (m == 0) return audit;
  DaeEval eval = dae.make_eval();
  DaeRequest req;
  req.forces = false;
  req.constraints = true;
  req.matrix = true;
  req.scales = MatrixScales{0.0, 0.0, 0.0};
  dae.evaluate(state, req, eval);
  for (Index r = 0; r < m; ++r) {
    if (!(std::abs(eval.C[r]) <= violation_tolerance)) audit.violated.push_back({r, eval.C[r]});
    if (!(std::abs(eval.Cdot[r]) <= velocity_tolerance))
      audit.velocity_violated.push_back({r, eval.Cdot[r]});
  }

  // C_q^T as a sparse matrix, one column per constraint row, normalized
  const SpMat& K = eval.kkt.matrix();
  std::vector<std::vector<std::pair<Index, double>>> rows(m);  // row -> (coordinate, value)
  for (Index c = 0; c < n; ++c)
    for (SpMat::InnerIterator it(K, c); it; ++it)
      if (it.row() >= n && it.value() != 0.0) rows[it.row() - n].push_back({c, it.value()});
  std::vector<Eigen::Triplet<double>> triplets;
  std::vector<double> norms(m, 0.0);
  for (Index r = 0; r < m; ++r) {
    for (const auto& [c, v] : rows[r]) norms[r] += v * v;
    norms[r] = std::sqrt(norms[r]);
    for (const auto& [c, v] : rows[r]) triplets.emplace_back(c, r, v / norms[r]);
  }
  SpMat A(n, m);
  A.setFromTriplets(triplets.begin(), triplets.end());
  A.makeCompressed();

  // sparse Householder QR in the natural column order: a column whose part orthogonal to
  // the earlier columns is below the threshold is deferred to the end, so the columns past
  // the rank are exactly the rows that repeat earlier ones (as Gram-Schmidt in row order
  // would find, at the cost of a sparse factorization: a chain of bodies stays banded)
  Eigen::SparseQR<SpMat, Eigen::NaturalOrdering<int>> qr;
  qr.setPivotThreshold(rank_tolerance);
  qr.compute(A);
  std::vector<bool> dependent(m, false);
  if (qr.info() == Eigen::Success) {
    const auto& perm = qr.colsPermutation().indices();
    for (Index k = qr.rank(); k < m; ++k) dependent[perm[k]] = true;
  }
  for (Index r = 0; r < m; ++r)
    if (norms[r] == 0.0) dependent[r] = true;

  // the earlier rows of each combination (for the first few): least squares on the
  // independent earlier rows near the row, widened by rows sharing coordinates until the
  // combination closes
  int explained = 0;
  for (Index r = 0; r < m; ++r) {
    if (!dependent[r]) continue;
    RedundantRow red{r, {}};
    if (norms[r] > 0.0 && explained++ < 20) {
      std::vector<bool> in(m, false);
      std::vector<Index> near;
      std::vector<bool> column_seen(n, false);
      for (const auto& [c, v] : rows[r]) column_seen[c] = true;
      for (int hop = 0; hop < 64; ++hop) {
        bool grew = false;
        for (Index k = 0; k < r; ++k) {
          if (in[k] || dependent[k]) continue;
          bool touches = false;
          for (const auto& [c, v] : rows[k]) touches = touches || column_seen[c];
          if (!touches) continue;
          in[k] = true;
          near.push_back(k);
          grew = true;
        }
        for (Index k : near)
          for (const auto& [c, v] : rows[k]) column_seen[c] = true;
        if (near.empty() || !grew) break;
        // dense on the coordinates these rows touch only
        std::vector<Index> local(n, -1);
        Index nl = 0;
        for (Index k : near)
          for (const auto& [c, v] : rows[k])
            if (local[c] < 0) local[c] = nl++;
        for (const auto& [c, v] : rows[r])
          if (local[c] < 0) local[c] = nl++;
        MatX B = MatX::Zero(nl, static_cast<Index>(near.size()));
        for (std::size_t j = 0; j < near.size(); ++j)
          for (const auto& [c, v] : rows[near[j]]) B(local[c], static_cast<Index>(j)) = v;
        VecX target = VecX::Zero(nl);
        for (const auto& [c, v] : rows[r]) target[local[c]] = v;
        const VecX coef = B.colPivHouseholderQr().solve(target);
        if ((B * coef - target).norm() > 1e-8 * norms[r]) continue;  // widen
        for (std::size_t j = 0; j < near.size(); ++j)
          if (std::abs(coef[static_cast<Index>(j)]) > 1e-8 * coef.cwiseAbs().maxCoeff())
            red.depends_on.push_back(near[j]);
        std::sort(red.depends_on.begin(), red.depends_on.end());
        break;
      }
    }
    audit.redundant.push_back(std::move(red));
  }
  return audit;
}

}  // namespace seaflex
