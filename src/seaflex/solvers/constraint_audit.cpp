// Constraint audit: violated rows, and redundant rows by a rank-revealing sparse QR of
// C_q^T in the natural column (= constraint row) order (SuiteSparseQR, T. A. Davis,
// "Algorithm 915, SuiteSparseQR: multifrontal multithreaded rank-revealing sparse QR
// factorization", ACM TOMS 38(1), 2011). With a fixed column order SuiteSparseQR's rank
// detection (Heath 1982, "Some extensions of an algorithm for sparse linear least squares
// problems", SIAM J. Sci. Stat. Comput. 3(2)) declares a column dead when its part
// orthogonal to the earlier live columns has a 2-norm <= tol: with unit columns that is
// Gram-Schmidt in row order. The multifrontal factorization orders the rows of C_q^T (the
// coordinates) itself, so a chain of bodies, whose C_q C_q^T is banded, costs O(m) time
// and memory (Eigen's SparseQR, which does not reorder rows, filled a 2,000-body chain's
// factor to 838 MB).
#include "seaflex/solvers/constraint_audit.hpp"

#include <SuiteSparseQR.hpp>
#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace seaflex {

namespace {

using SsLong = SuiteSparse_long;

// cholmod_common started and finished with its owner
class CholmodCommon {
 public:
  CholmodCommon() { cholmod_l_start(&cc_); }
  ~CholmodCommon() { cholmod_l_finish(&cc_); }
  CholmodCommon(const CholmodCommon&) = delete;
  CholmodCommon& operator=(const CholmodCommon&) = delete;
  cholmod_common* get() { return &cc_; }

 private:
  cholmod_common cc_;
};

// The columns of A (n x m, unit columns) that depend on earlier columns, by SuiteSparseQR
// with the fixed ordering and Heath's tolerance tol. R comes back "squeezed": the live
// columns form a staircase (a live column's last entry is on the next row of R), a dead
// column has entries only above it.
std::vector<bool> dead_columns(const std::vector<std::vector<std::pair<Index, double>>>& rows,
                               const std::vector<double>& norms, Index n, double tol) {
  const auto m = static_cast<Index>(rows.size());
  std::size_t nnz = 0;
  for (const auto& r : rows) nnz += r.size();
  CholmodCommon common;
  cholmod_common* cc = common.get();
  cholmod_sparse* A =
      cholmod_l_allocate_sparse(static_cast<std::size_t>(n), static_cast<std::size_t>(m), nnz,
                                /*sorted*/ 1, /*packed*/ 1, /*stype*/ 0, CHOLMOD_REAL, cc);
  if (A == nullptr) throw std::runtime_error("constraint audit: out of memory (CHOLMOD)");
  auto* Ap = static_cast<SsLong*>(A->p);
  auto* Ai = static_cast<SsLong*>(A->i);
  auto* Ax = static_cast<double*>(A->x);
  SsLong k = 0;
  for (Index r = 0; r < m; ++r) {
    Ap[r] = k;
    for (const auto& [c, v] : rows[static_cast<std::size_t>(r)]) {
      Ai[k] = c;
      Ax[k] = v / norms[static_cast<std::size_t>(r)];
      ++k;
    }
  }
  Ap[m] = k;
  cholmod_sparse* R = nullptr;
  SsLong* E = nullptr;
  const SsLong rank = SuiteSparseQR<double>(SPQR_ORDERING_FIXED, tol, /*econ*/ 0, A, &R, &E, cc);
  cholmod_l_free_sparse(&A, cc);
  if (rank < 0 || R == nullptr) {
    cholmod_l_free_sparse(&R, cc);
    throw std::runtime_error("constraint audit: the sparse QR of C_q failed (out of memory)");
  }
  std::vector<bool> dead(static_cast<std::size_t>(m), false);
  const auto* Rp = static_cast<const SsLong*>(R->p);
  const auto* Ri = static_cast<const SsLong*>(R->i);
  const auto* Rx = static_cast<const double*>(R->x);
  SsLong live = 0;
  for (Index j = 0; j < m; ++j) {
    // R = Q^T A E: column j of R is column E[j] of A (E = identity when null)
    const Index col = E != nullptr ? static_cast<Index>(E[j]) : j;
    bool pivot = false;
    for (SsLong p = Rp[j]; p < Rp[j + 1]; ++p)
      if (Ri[p] == live && std::abs(Rx[p]) > tol) pivot = true;
    if (pivot)
      ++live;
    else
      dead[static_cast<std::size_t>(col)] = true;
  }
  cholmod_l_free_sparse(&R, cc);
  if (E != nullptr) cholmod_l_free(static_cast<std::size_t>(m), sizeof(SsLong), E, cc);
  return dead;
}

// Joint neighbourhoods larger than this (rows x coordinates of the dense least-squares
// problem) are not searched for the rows a redundant row repeats: the message then names
// "earlier constraints" only.
constexpr double kMaxNeighbourhoodEntries = 4e6;

}  // namespace

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

  // the rows of C_q, read off the KKT matrix (coordinates in increasing order), and the
  // rows touching each coordinate
  const SpMat& K = eval.kkt.matrix();
  std::vector<std::vector<std::pair<Index, double>>> rows(static_cast<std::size_t>(m));
  std::vector<std::vector<Index>> coordinate_rows(static_cast<std::size_t>(n));
  for (Index c = 0; c < n; ++c)
    for (SpMat::InnerIterator it(K, c); it; ++it)
      if (it.row() >= n && it.value() != 0.0) {
        rows[static_cast<std::size_t>(it.row() - n)].push_back({c, it.value()});
        coordinate_rows[static_cast<std::size_t>(c)].push_back(it.row() - n);
      }
  std::vector<double> norms(static_cast<std::size_t>(m), 0.0);
  for (Index r = 0; r < m; ++r) {
    double& norm = norms[static_cast<std::size_t>(r)];
    for (const auto& [c, v] : rows[static_cast<std::size_t>(r)]) norm += v * v;
    norm = std::sqrt(norm);
  }
  std::vector<bool> dependent = dead_columns(rows, norms, n, rank_tolerance);
  for (Index r = 0; r < m; ++r)
    if (norms[static_cast<std::size_t>(r)] == 0.0) dependent[static_cast<std::size_t>(r)] = true;

  // the earlier rows of each combination (for the first few): least squares on the
  // independent earlier rows near the row, widened hop by hop through shared coordinates
  // until the combination closes. The marks are reset through the lists of what was set,
  // so a search costs its neighbourhood, not the model.
  std::vector<bool> in(static_cast<std::size_t>(m), false);
  std::vector<bool> seen(static_cast<std::size_t>(n), false);
  std::vector<Index> local(static_cast<std::size_t>(n), -1);
  int explained = 0;
  for (Index r = 0; r < m; ++r) {
    if (!dependent[static_cast<std::size_t>(r)]) continue;
    RedundantRow red{r, {}};
    const auto& row_r = rows[static_cast<std::size_t>(r)];
    if (norms[static_cast<std::size_t>(r)] > 0.0 && explained++ < 20) {
      std::vector<Index> near, seen_list, frontier;
      for (const auto& [c, v] : row_r) {
        seen[static_cast<std::size_t>(c)] = true;
        seen_list.push_back(c);
        frontier.push_back(c);
      }
      for (int hop = 0; hop < 64 && !frontier.empty(); ++hop) {
        std::vector<Index> next;
        const std::size_t before = near.size();
        for (Index c : frontier)
          for (Index k : coordinate_rows[static_cast<std::size_t>(c)]) {
            if (k >= r || in[static_cast<std::size_t>(k)] || dependent[static_cast<std::size_t>(k)])
              continue;
            in[static_cast<std::size_t>(k)] = true;
            near.push_back(k);
          }
        if (near.size() == before) break;
        std::sort(near.begin() + static_cast<std::ptrdiff_t>(before), near.end());
        for (std::size_t j = before; j < near.size(); ++j)
          for (const auto& [c, v] : rows[static_cast<std::size_t>(near[j])])
            if (!seen[static_cast<std::size_t>(c)]) {
              seen[static_cast<std::size_t>(c)] = true;
              seen_list.push_back(c);
              next.push_back(c);
            }
        frontier.swap(next);
        // dense on the coordinates these rows touch only
        const auto nl = static_cast<Index>(seen_list.size());
        if (static_cast<double>(nl) * static_cast<double>(near.size()) > kMaxNeighbourhoodEntries)
          break;
        for (Index i = 0; i < nl; ++i) local[static_cast<std::size_t>(seen_list[i])] = i;
        MatX B = MatX::Zero(nl, static_cast<Index>(near.size()));
        for (std::size_t j = 0; j < near.size(); ++j)
          for (const auto& [c, v] : rows[static_cast<std::size_t>(near[j])])
            B(local[static_cast<std::size_t>(c)], static_cast<Index>(j)) = v;
        VecX target = VecX::Zero(nl);
        for (const auto& [c, v] : row_r) target[local[static_cast<std::size_t>(c)]] = v;
        const VecX coef = B.colPivHouseholderQr().solve(target);
        if ((B * coef - target).norm() > 1e-8 * norms[static_cast<std::size_t>(r)]) continue;
        for (std::size_t j = 0; j < near.size(); ++j)
          if (std::abs(coef[static_cast<Index>(j)]) > 1e-8 * coef.cwiseAbs().maxCoeff())
            red.depends_on.push_back(near[j]);
        std::sort(red.depends_on.begin(), red.depends_on.end());
        break;
      }
      for (Index k : near) in[static_cast<std::size_t>(k)] = false;
      for (Index c : seen_list) {
        seen[static_cast<std::size_t>(c)] = false;
        local[static_cast<std::size_t>(c)] = -1;
      }
    }
    audit.redundant.push_back(std::move(red));
  }
  return audit;
}

}  // namespace seaflex
