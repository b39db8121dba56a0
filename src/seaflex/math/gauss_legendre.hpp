// Gauss-Legendre quadrature on [0, 1]: n points integrate polynomials of degree 2n-1 exactly.
// Nodes are the roots of the Legendre polynomial P_n found by Newton iteration
// (Press et al., Numerical Recipes, 3rd ed., section 4.6).
#pragma once

#include <vector>

namespace seaflex::math {

struct QuadratureRule {
  std::vector<double> points;   ///< abscissae in [0, 1]
  std::vector<double> weights;  ///< weights summing to 1
};

/// Gauss-Legendre rule with n points on [0, 1]. Precondition: 1 <= n <= 64.
QuadratureRule gauss_legendre_unit(int n);

}  // namespace seaflex::math
