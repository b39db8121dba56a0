// Sparse direct solution of the KKT (augmented) systems of thesis eq. (132),
//   [H  C_q^T; C_q  0] x = b,   H = km M - kq dQ/dq - kv dQ/dv,
// with one of three sparse LU backends behind one interface: Eigen's SparseLU with a
// COLAMD ordering, KLU and UMFPACK (SuiteSparse, through Eigen 3.4's KLUSupport and
// UmfPackSupport wrappers). The symbolic analysis (fill-reducing ordering) is done once
// per sparsity pattern, the numeric factorization whenever the values change.
//
// Only LU applies: the KKT matrix is indefinite (the zero block of the multipliers) and
// H is unsymmetric in general (follower loads, Morison drag, the multiplier Hessian), so
// Cholesky (CHOLMOD, SimplicialLDLT) and symmetric indefinite LDL^T are ruled out.
//
// Default: KLU, the fastest at N = 1000 (bench/bench_kkt_solver.cpp, docs/performance.md
// "Sparse KKT backends": the Newton matrix of a 1000-element ANCF riser, 6011 rows). Its
// numeric factorization takes about half the time of SparseLU's and 40 % of UMFPACK's,
// and a Newton iteration or an implicit step is dominated by the factorization (one
// factorization costs 13 to 17 KLU solves). The KKT matrices of this engine are banded
// with little fill: KLU's left-looking Gilbert-Peierls LU, with no BLAS and no supernodes
// or frontal matrices to set up, suits them. UMFPACK's solve is about 15 % faster than
// KLU's here because it drops the exact zeros of the fixed pattern from its factors (the
// riser bends in one plane); SparseLU's solve is about 35 % slower than KLU's. (Measured
// with klu_solve; KLU's factors are now solved by rows without those zeros, kkt_solver.cpp.)
//
// KLU is called directly (kkt_solver.cpp): the first factorization of a pattern pivots
// (klu_factor), later ones reuse its pivot order (klu_refactor, no allocation, about half
// the time) while the pivots stay sound (klu_rcond and klu_rgrowth against the last
// pivoting factorization), and pivot again otherwise. Its factors are copied after each
// factorization (klu_extract) and solved by rows without their exact zeros.
// Limitations: UMFPACK allocates twice in every solve (Eigen's wrapper calls
// umfpack_di_solve, not umfpack_di_wsolve), against the "no time step allocates" rule of
// DESIGN.md; KLU and SparseLU do not allocate in solve(). A pivoting numeric factorization
// allocates (SparseLU 10, KLU 20, UMFPACK 30 mallocs for examples/riser_in_current.yaml).
// Iterative refinement of UMFPACK is switched off: it would read the matrix
// passed to factorize() again at solve() time, and the caller may have changed or freed it.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "seaflex/core/types.hpp"

namespace seaflex {

namespace detail {
class KktBackend;  // kkt_solver.cpp: keeps the SuiteSparse headers out of this one
}

/// Sparse LU backend of KktSolver; names in a model file: "sparselu", "klu", "umfpack".
enum class LinearSolverKind {
  kSparseLU,  ///< Eigen::SparseLU with COLAMD ordering (no external library)
  kKlu,       ///< SuiteSparse KLU (BTF + AMD ordering, Gilbert-Peierls LU)
  kUmfpack,   ///< SuiteSparse UMFPACK (multifrontal, BLAS fronts)
};

/// KLU: the fastest factorization on the benchmark of docs/performance.md (file header).
inline constexpr LinearSolverKind kDefaultLinearSolver = LinearSolverKind::kKlu;

class KktSolver {
 public:
  explicit KktSolver(LinearSolverKind kind = kDefaultLinearSolver);
  ~KktSolver();
  KktSolver(KktSolver&&) noexcept;
  KktSolver& operator=(KktSolver&&) noexcept;
  KktSolver(const KktSolver&) = delete;
  KktSolver& operator=(const KktSolver&) = delete;

  /// Symbolic analysis (ordering) of A's sparsity pattern; factorize() calls it itself
  /// the first time and whenever A's pattern changes (its size, or the positions of its
  /// stored entries). Returns false when the analysis fails; message() says why. A must be
  /// square.
  bool analyze(const SpMat& A);
  /// Factorizes A (analyzing its pattern when it is new). Returns false when A is
  /// singular; message() says why.
  bool factorize(const SpMat& A);
  /// x = A^-1 b with the last factorization. Precondition: factorized().
  void solve(const VecX& b, VecX& x) const;
  const std::string& message() const { return message_; }
  bool factorized() const { return factorized_; }
  int factorizations() const { return factorizations_; }
  /// Of those, the ones that reused the pivot order of an earlier one (KLU's klu_refactor;
  /// 0 for the other backends).
  int reused_pivots() const;
  /// Off by default: factorize() pivots every matrix, so the factors depend on that matrix
  /// alone. On (KLU; the others ignore it): a matrix of the pattern last factored reuses
  /// that factorization's pivot order while it stays sound (file header). The factors then
  /// depend on the matrix that set the order too: pivot_source() holds its values, so that
  /// a restart can factor it first and get the same factors (generalized-alpha's
  /// checkpoints).
  void set_reuse_pivots(bool on);
  /// The values (in the stored order of the current pattern) of the matrix whose pivot order
  /// the current factors reused; empty when they pivoted themselves.
  const std::vector<double>& pivot_source() const;
  LinearSolverKind kind() const { return kind_; }

  /// "sparselu", "klu", "umfpack"; nullopt for any other name.
  static std::optional<LinearSolverKind> parse(std::string_view name);
  static std::string_view to_string(LinearSolverKind kind);
  /// The valid names, for messages: "sparselu, klu, umfpack".
  static std::string_view names();

 private:
  LinearSolverKind kind_;
  std::unique_ptr<detail::KktBackend> backend_;
  bool analyzed_ = false;
  Index analyzed_rows_ = 0;
  // the analyzed pattern (compressed column starts and row indices): a matrix with another
  // pattern is analyzed again, even with the same size and number of entries
  std::vector<int> analyzed_outer_, analyzed_inner_;
  bool same_pattern(const SpMat& A) const;
  bool factorized_ = false;
  int factorizations_ = 0;
  std::string message_;
};

}  // namespace seaflex
