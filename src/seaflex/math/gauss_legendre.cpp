#include "seaflex/math/gauss_legendre.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace seaflex::math {

QuadratureRule gauss_legendre_unit(int n) {
  if (n < 1 || n > 64) throw std::invalid_argument("gauss_legendre_unit: n must be in [1, 64]");
  QuadratureRule rule;
  rule.points.resize(n);
  rule.weights.resize(n);
  for (int i = 0; i < n; ++i) {
    // initial guess for the i-th root of P_n on [-1, 1] (Numerical Recipes eq. 4.6.?)
    double x = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5));
    double dp = 0.0;
    for (int iter = 0; iter < 100; ++iter) {
      // three-term recurrence for P_n(x) and its derivative
      double p0 = 1.0, p1 = x;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      const double pn = (n == 1) ? x : p1;
      const double pnm1 = (n == 1) ? 1.0 : p0;
      dp = n * (x * pn - pnm1) / (x * x - 1.0);
      const double dx = pn / dp;
      x -= dx;
      if (std::abs(dx) < 1e-16) break;
    }
    // map [-1, 1] -> [0, 1]: weights halve
    rule.points[i] = 0.5 * (1.0 - x);
    rule.weights[i] = 1.0 / ((1.0 - x * x) * dp * dp);
  }
  return rule;
}

}  // namespace seaflex::math
