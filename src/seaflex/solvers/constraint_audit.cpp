#include "seaflex/solvers/constraint_audit.hpp"

#include <cmath>
#include <map>

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

  // dense C_q on the touched columns only (a riser of 1000 coordinates with joints at its
  // ends touches a few dozen)
  const SpMat& K = eval.kkt.matrix();
  std::map<Index, Index> column;
  std::vector<std::vector<std::pair<Index, double>>> rows(m);
  for (Index c = 0; c < n; ++c)
    for (SpMat::InnerIterator it(K, c); it; ++it)
      if (it.row() >= n && it.value() != 0.0) {
        const auto [pos, added] = column.emplace(c, static_cast<Index>(column.size()));
        rows[it.row() - n].push_back({pos->second, it.value()});
      }
  const Index nt = static_cast<Index>(column.size());
  MatX Cq = MatX::Zero(m, nt);
  for (Index r = 0; r < m; ++r)
    for (const auto& [c, v] : rows[r]) Cq(r, c) = v;

  // modified Gram-Schmidt in row order (twice, for orthogonality to round-off)
  std::vector<VecX> basis;
  std::vector<Index> independent;
  for (Index r = 0; r < m; ++r) {
    VecX x = Cq.row(r).transpose();
    const double norm = x.norm();
    for (int pass = 0; pass < 2; ++pass)
      for (const VecX& b : basis) x -= b.dot(x) * b;
    if (norm == 0.0 || x.norm() <= rank_tolerance * norm) {
      RedundantRow red{r, {}};
      if (!independent.empty() && norm > 0.0) {
        // which earlier rows: least squares on the independent rows so far
        MatX B(nt, static_cast<Index>(independent.size()));
        for (std::size_t k = 0; k < independent.size(); ++k) B.col(k) = Cq.row(independent[k]);
        const VecX c = B.colPivHouseholderQr().solve(VecX(Cq.row(r).transpose()));
        for (std::size_t k = 0; k < independent.size(); ++k)
          if (std::abs(c[k]) > 1e-8 * c.cwiseAbs().maxCoeff())
            red.depends_on.push_back(independent[k]);
      }
      audit.redundant.push_back(std::move(red));
      continue;
    }
    basis.push_back(x / x.norm());
    independent.push_back(r);
  }
  return audit;
}

}  // namespace seaflex
