#include "seaflex/solvers/kkt_solver.hpp"

namespace seaflex {

bool KktSolver::factorize(const SpMat& A) {
  if (!analyzed_) {
    lu_.analyzePattern(A);
    analyzed_ = true;
  }
  lu_.factorize(A);
  ++factorizations_;
  factorized_ = lu_.info() == Eigen::Success;
  message_ = factorized_ ? std::string() : lu_.lastErrorMessage();
  return factorized_;
}

void KktSolver::solve(const VecX& b, VecX& x) const {
  x = lu_.solve(b);
}

}  // namespace seaflex
