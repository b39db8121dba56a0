#include "seaflex/solvers/kkt_solver.hpp"

#include <fmt/format.h>

#include <Eigen/KLUSupport>
#include <Eigen/SparseLU>
#include <Eigen/UmfPackSupport>
#include <algorithm>
#include <array>
#include <utility>
#include <vector>

namespace seaflex {

namespace detail {

/// One sparse LU library: analysis, numeric factorization, solve. On failure analyze()
/// and factorize() return false and leave the reason in message.
class KktBackend {
 public:
  virtual ~KktBackend() = default;
  virtual bool analyze(const SpMat& A, std::string& message) = 0;
  virtual bool factorize(const SpMat& A, std::string& message) = 0;
  virtual void solve(const VecX& b, VecX& x) const = 0;
  /// Numeric factorizations that reused an earlier one's pivot order.
  virtual int reused_pivots() const { return 0; }
  /// Lets factorize() reuse the last pivoting factorization's pivot order (KLU only).
  virtual void set_reuse_pivots(bool /*on*/) {}
  /// The current factors reused the pivot order of the factorization of these values (the
  /// matrix's entries in its stored order); empty when they were pivoted themselves.
  virtual const std::vector<double>& pivot_source() const {
    static const std::vector<double> none;
    return none;
  }
};

}  // namespace detail

namespace {

class SparseLuBackend final : public detail::KktBackend {
 public:
  bool analyze(const SpMat& A, std::string& message) override {
    lu_.analyzePattern(A);
    message.clear();
    return true;
  }
  bool factorize(const SpMat& A, std::string& message) override {
    lu_.factorize(A);
    if (lu_.info() == Eigen::Success) return true;
    message = "SparseLU: " + lu_.lastErrorMessage();
    return false;
  }
  void solve(const VecX& b, VecX& x) const override { x = lu_.solve(b); }

 private:
  Eigen::SparseLU<SpMat, Eigen::COLAMDOrdering<int>> lu_;
};

std::string klu_status(const klu_common& common) {
  switch (common.status) {
    case KLU_SINGULAR:
      return fmt::format("KLU: the matrix is singular (no pivot in column {})",
                         common.singular_col);
    case KLU_OUT_OF_MEMORY:
      return "KLU: out of memory";
    case KLU_INVALID:
      return "KLU: invalid matrix";
    case KLU_TOO_LARGE:
      return "KLU: integer overflow (matrix too large)";
    default:
      return fmt::format("KLU: failed with status {}", common.status);
  }
}

// KLU called directly (not through Eigen's wrapper, which frees the factors and calls
// klu_factor every time): the first factorization of a pattern pivots (klu_factor); with
// set_reuse_pivots(true), later ones with the same pattern reuse its pivot order
// (klu_refactor: no depth-first search, no pivot search, no allocation). A refactorization
// is kept only while its pivots stay sound: the crude reciprocal condition number
// (klu_rcond, min |u_ii| / max |u_ii|) and the reciprocal pivot growth (klu_rgrowth) both
// at least 1e-2 times those of the last pivoting factorization; otherwise, and when
// klu_refactor meets a zero pivot, the matrix is factored again with pivoting (KLU User
// Guide, Davis & Palamadai Natarajan: klu_refactor does not check the pivots, klu_rgrowth
// and klu_rcond tell when to pivot again).
// The solves do not call klu_solve: after each numeric factorization the factors are copied
// (klu_extract: (R \\ A)(P, Q) = L U + F, L and U block diagonal over KLU's BTF blocks, F
// the blocks above them) into compressed rows without their exact zeros, and solve() runs
// the same block back substitution as klu_solve, row by row: each row of L and U a
// gathered dot product instead of klu_solve's column updates, and none of the zeros KLU
// keeps in its fixed pattern (a riser bending in one plane couples none of its
// out-of-plane coordinates to the others). The same factors, the same operations on the
// nonzero entries, summed in another order: round-off only (test
// KktSolver.KluSolvesByBlocksWithoutTheFactorsZeros; docs/performance.md "KLU's factors
// solved by rows": the storm's solves in 2.2 times fewer instructions).
class KluBackend final : public detail::KktBackend {
 public:
  KluBackend() { klu_defaults(&common_); }
  ~KluBackend() override { release(); }
  KluBackend(const KluBackend&) = delete;
  KluBackend& operator=(const KluBackend&) = delete;

  bool analyze(const SpMat& matrix, std::string& message) override {
    release();
    const SpMat& A = compressed(matrix);
    n_ = static_cast<int>(A.rows());
    symbolic_ = klu_analyze(n_, const_cast<int*>(A.outerIndexPtr()),
                            const_cast<int*>(A.innerIndexPtr()), &common_);
    if (symbolic_ && common_.status == KLU_OK) {
      message.clear();
      return true;
    }
    message = klu_status(common_);
    return false;
  }
  bool factorize(const SpMat& matrix, std::string& message) override {
    if (!symbolic_) {
      message = "KLU: no symbolic analysis";
      return false;
    }
    const SpMat& A = compressed(matrix);
    int* ap = const_cast<int*>(A.outerIndexPtr());
    int* ai = const_cast<int*>(A.innerIndexPtr());
    double* ax = const_cast<double*>(A.valuePtr());
    if (reuse_ && numeric_ && same_pattern(A) &&
        klu_refactor(ap, ai, ax, symbolic_, numeric_, &common_) &&
        klu_rcond(symbolic_, numeric_, &common_) &&
        klu_rgrowth(ap, ai, ax, symbolic_, numeric_, &common_) && common_.rcond >= 1e-2 * rcond_ &&
        common_.rgrowth >= 1e-2 * rgrowth_) {
      ++refactorizations_;
      reused_ = true;
      return extract(message);
    }
    reused_ = false;
    if (numeric_) klu_free_numeric(&numeric_, &common_);
    // halt_if_singular (the default) makes klu_factor return no factors on a zero pivot
    numeric_ = klu_factor(ap, ai, ax, symbolic_, &common_);
    if (!numeric_ || common_.status != KLU_OK) {
      message = klu_status(common_);
      if (numeric_) klu_free_numeric(&numeric_, &common_);
      return false;
    }
    if (reuse_) {  // what a later refactorization is compared with
      klu_rcond(symbolic_, numeric_, &common_);
      klu_rgrowth(ap, ai, ax, symbolic_, numeric_, &common_);
      rcond_ = common_.rcond;
      rgrowth_ = common_.rgrowth;
      pattern_ap_.assign(ap, ap + n_ + 1);
      pattern_ai_.assign(ai, ai + A.nonZeros());
      source_.assign(ax, ax + A.nonZeros());
    }
    return extract(message);
  }
  void solve(const VecX& b, VecX& x) const override {
    // w = (R \ b)(P); the blocks from the last: L, U, then F's columns of the block feed
    // the rows of the blocks above (klu_solve.c, the same order of blocks); x(Q) = w
    double* w = work_.data();
    for (int k = 0; k < n_; ++k) w[k] = b[p_[k]] / rs_[k];  // klu_extract: Rs in pivot order
    for (int blk = nblocks_ - 1; blk >= 0; --blk) {
      const int k1 = r_[blk], k2 = r_[blk + 1];
      for (int i = k1; i < k2; ++i) {
        double sum = w[i];
        for (int e = l_.p[i]; e < l_.p[i + 1]; ++e) sum -= l_.x[e] * w[l_.i[e]];
        w[i] = sum;
      }
      for (int i = k2 - 1; i >= k1; --i) {
        double sum = w[i];
        for (int e = u_.p[i]; e < u_.p[i + 1]; ++e) sum -= u_.x[e] * w[u_.i[e]];
        w[i] = sum * inv_udiag_[i];
      }
      for (int j = k1; j < k2; ++j)
        for (int e = fp_[j]; e < fp_[j + 1]; ++e) w[fi_[e]] -= fx_[e] * w[j];
    }
    x.resize(n_);
    for (int k = 0; k < n_; ++k) x[q_[k]] = w[k];
  }
  int reused_pivots() const override { return refactorizations_; }
  void set_reuse_pivots(bool on) override { reuse_ = on; }
  const std::vector<double>& pivot_source() const override {
    return reused_ ? source_ : KktBackend::pivot_source();
  }

 private:
  // KLU reads the compressed column arrays: an uncompressed matrix is copied
  const SpMat& compressed(const SpMat& A) {
    if (A.isCompressed()) return A;
    copy_ = A;
    copy_.makeCompressed();
    return copy_;
  }
  bool same_pattern(const SpMat& A) const {
    return A.rows() == n_ && static_cast<std::size_t>(A.nonZeros()) == pattern_ai_.size() &&
           std::equal(pattern_ap_.begin(), pattern_ap_.end(), A.outerIndexPtr()) &&
           std::equal(pattern_ai_.begin(), pattern_ai_.end(), A.innerIndexPtr());
  }
  // the factors in compressed rows without their exact zeros (file header); the buffers
  // keep their size from one factorization to the next (no allocation in a refactorization)
  bool extract(std::string& message) {
    const int lnz = numeric_->lnz, unz = numeric_->unz, nzoff = numeric_->nzoff;
    nblocks_ = symbolic_->nblocks;
    cp_.resize(n_ + 1);
    ci_.resize(std::max(lnz, unz));
    cx_.resize(std::max(lnz, unz));
    fp_.resize(n_ + 1);
    fi_.resize(nzoff);
    fx_.resize(nzoff);
    p_.resize(n_);
    q_.resize(n_);
    rs_.resize(n_);
    r_.resize(nblocks_ + 1);
    work_.resize(n_);
    inv_udiag_.resize(n_);
    // L (with its unit diagonal, dropped here), then U (its diagonal kept apart)
    if (!klu_extract(numeric_, symbolic_, cp_.data(), ci_.data(), cx_.data(), nullptr, nullptr,
                     nullptr, fp_.data(), fi_.data(), fx_.data(), p_.data(), q_.data(), rs_.data(),
                     r_.data(), &common_)) {
      message = klu_status(common_);
      return false;
    }
    if (!(reused_ && l_.gather(cp_, cx_, nullptr))) l_.build(n_, cp_, ci_, cx_, nullptr);
    if (!klu_extract(numeric_, symbolic_, nullptr, nullptr, nullptr, cp_.data(), ci_.data(),
                     cx_.data(), nullptr, nullptr, nullptr, nullptr, nullptr, nullptr, nullptr,
                     &common_)) {
      message = klu_status(common_);
      return false;
    }
    if (!(reused_ && u_.gather(cp_, cx_, &inv_udiag_))) u_.build(n_, cp_, ci_, cx_, &inv_udiag_);
    // the back substitution multiplies by the inverse: a division's latency would lie on
    // its chain of dependent rows
    for (double& d : inv_udiag_) d = 1.0 / d;
    message.clear();
    return true;
  }
  // L or U without its diagonal by rows, from klu_extract's columns (cp, ci, cx)
  struct RowFactor {
    std::vector<int> p, i;  // row starts, column indices
    std::vector<double> x;
    std::vector<int> src, dropped, diag_src;  // the kept, dropped and diagonal column entries
    std::vector<int> next;                    // build's workspace
    bool built = false;
    // all rows again, without the diagonal (into diag when given) and the exact zeros
    void build(int n, const std::vector<int>& cp, const std::vector<int>& ci,
               const std::vector<double>& cx, std::vector<double>* diag) {
      p.assign(n + 1, 0);
      dropped.clear();
      diag_src.assign(n, -1);
      for (int j = 0; j < n; ++j)
        for (int e = cp[j]; e < cp[j + 1]; ++e) {
          if (ci[e] == j)
            diag_src[j] = e;
          else if (cx[e] != 0.0)
            ++p[ci[e] + 1];
          else
            dropped.push_back(e);
        }
      for (int r = 0; r < n; ++r) p[r + 1] += p[r];
      i.resize(p[n]);
      x.resize(p[n]);
      src.resize(p[n]);
      next.assign(p.begin(), p.end() - 1);
      for (int j = 0; j < n; ++j)
        for (int e = cp[j]; e < cp[j + 1]; ++e)
          if (ci[e] != j && cx[e] != 0.0) {
            const int k = next[ci[e]]++;
            i[k] = j;
            x[k] = cx[e];
            src[k] = e;
          }
      if (diag)
        for (int j = 0; j < n; ++j) (*diag)[j] = cx[diag_src[j]];
      built = true;
    }
    // after klu_refactor (the same pattern and pivots, so the same column entries): the new
    // values into the rows built before, unless an entry dropped as zero is no longer zero
    // (then false: build again)
    bool gather(const std::vector<int>& cp, const std::vector<double>& cx,
                std::vector<double>* diag) {
      if (!built || static_cast<int>(diag_src.size()) + 1 != static_cast<int>(cp.size()))
        return false;
      for (const int e : dropped)
        if (cx[e] != 0.0) return false;
      for (std::size_t k = 0; k < src.size(); ++k) x[k] = cx[src[k]];
      if (diag)
        for (std::size_t j = 0; j < diag_src.size(); ++j) (*diag)[j] = cx[diag_src[j]];
      return true;
    }
  };
  void release() {
    if (numeric_) klu_free_numeric(&numeric_, &common_);
    if (symbolic_) klu_free_symbolic(&symbolic_, &common_);
    l_.built = u_.built = false;
    pattern_ap_.clear();
    pattern_ai_.clear();
    reused_ = false;
  }

  mutable klu_common common_{};
  klu_symbolic* symbolic_ = nullptr;
  klu_numeric* numeric_ = nullptr;
  int n_ = 0;
  double rcond_ = 0.0, rgrowth_ = 0.0;  // of the last pivoting factorization
  std::vector<int> pattern_ap_, pattern_ai_;
  std::vector<double> source_;  // the values of the last pivoting factorization (with reuse_)
  SpMat copy_;                  // a compressed copy of an uncompressed matrix
  bool reuse_ = false, reused_ = false;
  int refactorizations_ = 0;
  // the factors for solve() (extract): L and U without their diagonals by rows, 1 / U's diagonal,
  // F by columns, the permutations, scale factors and block boundaries; cp_, ci_, cx_ are the
  // extraction's buffers, work_ the solve's
  int nblocks_ = 0;
  RowFactor l_, u_;
  std::vector<int> fp_, fi_, p_, q_, r_, cp_, ci_;
  std::vector<double> inv_udiag_, fx_, rs_, cx_;
  mutable std::vector<double> work_;
};

class UmfpackBackend final : public detail::KktBackend {
 public:
  UmfpackBackend() {
    // no iterative refinement: it would read the matrix of factorize() again in solve()
    umf_.umfpackControl()[UMFPACK_IRSTEP] = 0;
  }
  bool analyze(const SpMat& A, std::string& message) override {
    umf_.analyzePattern(A);
    if (umf_.info() == Eigen::Success) {
      analyzed_ = true;
      message.clear();
      return true;
    }
    analyzed_ = false;
    message = "UMFPACK: the symbolic analysis failed (invalid matrix or out of memory)";
    return false;
  }
  bool factorize(const SpMat& A, std::string& message) override {
    if (!analyzed_) {
      message = "UMFPACK: no symbolic analysis";
      return false;
    }
    umf_.factorize(A);
    if (umf_.info() == Eigen::Success) return true;
    // the wrapper asserts on its return code when there are no factors (out of memory),
    // so the status stays unnamed; a zero pivot is the case met in practice
    message = "UMFPACK: the matrix is singular (a zero pivot) or the factorization failed";
    return false;
  }
  void solve(const VecX& b, VecX& x) const override { x = umf_.solve(b); }

 private:
  Eigen::UmfPackLU<SpMat> umf_;
  bool analyzed_ = false;
};

std::unique_ptr<detail::KktBackend> make_backend(LinearSolverKind kind) {
  switch (kind) {
    case LinearSolverKind::kKlu:
      return std::make_unique<KluBackend>();
    case LinearSolverKind::kUmfpack:
      return std::make_unique<UmfpackBackend>();
    case LinearSolverKind::kSparseLU:
      break;
  }
  return std::make_unique<SparseLuBackend>();
}

constexpr std::array<std::pair<LinearSolverKind, std::string_view>, 3> kNames{{
    {LinearSolverKind::kSparseLU, "sparselu"},
    {LinearSolverKind::kKlu, "klu"},
    {LinearSolverKind::kUmfpack, "umfpack"},
}};

}  // namespace

KktSolver::KktSolver(LinearSolverKind kind) : kind_(kind), backend_(make_backend(kind)) {}
KktSolver::~KktSolver() = default;
KktSolver::KktSolver(KktSolver&&) noexcept = default;
KktSolver& KktSolver::operator=(KktSolver&&) noexcept = default;

namespace {
// f applied to A's compressed form: A itself, or a compressed copy (rare: the assembled
// matrices are compressed)
template <class F>
auto with_compressed(const SpMat& A, F f) {
  if (A.isCompressed()) return f(A);
  SpMat c = A;
  c.makeCompressed();
  return f(c);
}
}  // namespace

bool KktSolver::analyze(const SpMat& A) {
  factorized_ = false;
  analyzed_ = backend_->analyze(A, message_);
  analyzed_rows_ = A.rows();
  with_compressed(A, [&](const SpMat& c) {
    analyzed_outer_.assign(c.outerIndexPtr(), c.outerIndexPtr() + c.outerSize() + 1);
    analyzed_inner_.assign(c.innerIndexPtr(), c.innerIndexPtr() + c.nonZeros());
    return 0;
  });
  return analyzed_;
}

bool KktSolver::same_pattern(const SpMat& A) const {
  return A.rows() == analyzed_rows_ && with_compressed(A, [&](const SpMat& c) {
           return std::equal(analyzed_outer_.begin(), analyzed_outer_.end(), c.outerIndexPtr(),
                             c.outerIndexPtr() + c.outerSize() + 1) &&
                  std::equal(analyzed_inner_.begin(), analyzed_inner_.end(), c.innerIndexPtr(),
                             c.innerIndexPtr() + c.nonZeros());
         });
}

bool KktSolver::factorize(const SpMat& A) {
  // compared entry by entry (O(nonzeros), far below a factorization): a pattern analyzed for
  // other positions would leave entries outside KLU's blocks (a crash, not an error)
  const bool new_pattern = !analyzed_ || !same_pattern(A);
  if (new_pattern && !analyze(A)) return false;
  ++factorizations_;
  factorized_ = backend_->factorize(A, message_);
  if (factorized_) message_.clear();
  return factorized_;
}

int KktSolver::reused_pivots() const {
  return backend_->reused_pivots();
}

void KktSolver::set_reuse_pivots(bool on) {
  backend_->set_reuse_pivots(on);
}

const std::vector<double>& KktSolver::pivot_source() const {
  return backend_->pivot_source();
}

void KktSolver::solve(const VecX& b, VecX& x) const {
  backend_->solve(b, x);
}

std::optional<LinearSolverKind> KktSolver::parse(std::string_view name) {
  for (const auto& [kind, kind_name] : kNames) {
    if (kind_name == name) return kind;
  }
  return std::nullopt;
}

std::string_view KktSolver::to_string(LinearSolverKind kind) {
  for (const auto& [k, kind_name] : kNames) {
    if (k == kind) return kind_name;
  }
  return "unknown";
}

std::string_view KktSolver::names() {
  return "sparselu, klu, umfpack";
}

}  // namespace seaflex
