#include "seaflex/solvers/kkt_solver.hpp"

#include <fmt/format.h>

#include <Eigen/KLUSupport>
#include <Eigen/SparseLU>
#include <Eigen/UmfPackSupport>
#include <array>
#include <utility>

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

class KluBackend final : public detail::KktBackend {
 public:
  bool analyze(const SpMat& A, std::string& message) override {
    klu_.analyzePattern(A);
    // the wrapper's info() asserts after a failed analysis; KLU's own status does not
    if (klu_.kluCommon().status == KLU_OK) {
      analyzed_ = true;
      message.clear();
      return true;
    }
    analyzed_ = false;
    message = klu_status(klu_.kluCommon());
    return false;
  }
  bool factorize(const SpMat& A, std::string& message) override {
    if (!analyzed_) {
      message = "KLU: no symbolic analysis";
      return false;
    }
    klu_.factorize(A);
    // halt_if_singular (the default) makes klu_factor return no factors on a zero pivot
    if (klu_.kluCommon().status == KLU_OK) return true;
    message = klu_status(klu_.kluCommon());
    return false;
  }
  void solve(const VecX& b, VecX& x) const override { x = klu_.solve(b); }

 private:
  Eigen::KLU<SpMat> klu_;
  bool analyzed_ = false;
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

bool KktSolver::analyze(const SpMat& A) {
  factorized_ = false;
  analyzed_ = backend_->analyze(A, message_);
  analyzed_rows_ = A.rows();
  analyzed_nonzeros_ = A.nonZeros();
  return analyzed_;
}

bool KktSolver::factorize(const SpMat& A) {
  const bool new_pattern =
      !analyzed_ || A.rows() != analyzed_rows_ || A.nonZeros() != analyzed_nonzeros_;
  if (new_pattern && !analyze(A)) return false;
  ++factorizations_;
  factorized_ = backend_->factorize(A, message_);
  if (factorized_) message_.clear();
  return factorized_;
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
