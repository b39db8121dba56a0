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
      return true;
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
    return true;
  }
  void solve(const VecX& b, VecX& x) const override {
    x = b;
    klu_solve(symbolic_, numeric_, n_, 1, x.data(), &common_);
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
  void release() {
    if (numeric_) klu_free_numeric(&numeric_, &common_);
    if (symbolic_) klu_free_symbolic(&symbolic_, &common_);
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
