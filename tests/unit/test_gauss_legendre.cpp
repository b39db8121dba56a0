#include "seaflex/math/gauss_legendre.hpp"

#include <gtest/gtest.h>

#include <cmath>

using seaflex::math::gauss_legendre_unit;

// n points integrate x^k exactly on [0, 1] for k <= 2n - 1: int_0^1 x^k dx = 1/(k+1).
TEST(GaussLegendre, IntegratesPolynomialsExactly) {
  for (int n = 1; n <= 12; ++n) {
    const auto rule = gauss_legendre_unit(n);
    for (int k = 0; k <= 2 * n - 1; ++k) {
      double sum = 0.0;
      for (int i = 0; i < n; ++i) sum += rule.weights[i] * std::pow(rule.points[i], k);
      EXPECT_NEAR(sum, 1.0 / (k + 1.0), 1e-14) << "n=" << n << " k=" << k;
    }
  }
}

// degree 2n is not integrated exactly: the rule is no better than advertised
TEST(GaussLegendre, DegreeTwoNIsNotExact) {
  const auto rule = gauss_legendre_unit(3);
  double sum = 0.0;
  for (int i = 0; i < 3; ++i) sum += rule.weights[i] * std::pow(rule.points[i], 6);
  EXPECT_GT(std::abs(sum - 1.0 / 7.0), 1e-6);
}

TEST(GaussLegendre, RejectsBadCount) {
  EXPECT_THROW(gauss_legendre_unit(0), std::invalid_argument);
  EXPECT_THROW(gauss_legendre_unit(65), std::invalid_argument);
}
