// Sparse direct solution of the KKT (augmented) systems of thesis eq. (132):
// the symbolic analysis (fill-reducing ordering) is done once per pattern, the numeric
// factorization whenever the values change.
#pragma once

#include <Eigen/SparseLU>
#include <string>

#include "seaflex/core/types.hpp"

namespace seaflex {

class KktSolver {
 public:
  /// Factorizes A (analyzing its pattern the first time). Returns false when A is
  /// singular; message() says why.
  bool factorize(const SpMat& A);
  /// x = A^-1 b with the last factorization.
  void solve(const VecX& b, VecX& x) const;
  const std::string& message() const { return message_; }
  bool factorized() const { return factorized_; }
  int factorizations() const { return factorizations_; }

 private:
  Eigen::SparseLU<SpMat, Eigen::COLAMDOrdering<int>> lu_;
  bool analyzed_ = false;
  bool factorized_ = false;
  int factorizations_ = 0;
  std::string message_;
};

}  // namespace seaflex
