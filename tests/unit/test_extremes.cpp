// post/extremes: the Weibull and Gumbel fits recover the parameters of samples drawn from
// known distributions, and the storm extremes follow the closed forms.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "seaflex/post/extremes.hpp"

using namespace seaflex::post;

// n = 20000 draws of Weibull(scale 3, shape 1.7). Maximum likelihood's asymptotic standard
// errors (Cohen 1965; JKB 1994 eq. (21.80)): se(shape)/shape = 0.780/sqrt(n) = 0.55 %,
// se(scale)/scale = 1.053/(shape sqrt(n)) = 0.44 %. Tolerance: 4 standard errors.
TEST(Extremes, WeibullFitRecoversParameters) {
  const double scale = 3.0, shape = 1.7;
  const int n = 20000;
  std::mt19937_64 rng(2024);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> x(n);
  // inverse transform (the same numbers with every standard library)
  for (double& v : x) v = scale * std::pow(-std::log1p(-u(rng)), 1.0 / shape);
  const WeibullFit fit = fit_weibull(x);
  EXPECT_NEAR(fit.shape, shape, 4 * 0.780 / std::sqrt(n) * shape);
  EXPECT_NEAR(fit.scale, scale, 4 * 1.053 / (shape * std::sqrt(n)) * scale);
  EXPECT_THROW(fit_weibull(std::vector<double>{1.0}), std::invalid_argument);
  EXPECT_THROW(fit_weibull(std::vector<double>{2.0, 2.0, 2.0}), std::invalid_argument);
}

// n = 20000 draws of Gumbel(location 10, scale 2). Method of moments: se(scale)/scale =
// sqrt((kurtosis - 1) / (4 n)) = sqrt(4.4 / 4n) = 0.74 % (the Gumbel's kurtosis is 5.4),
// se(location) about sqrt(1.1) scale / sqrt(n) (Gumbel 1958) = 0.015. Tolerance: 4 se.
TEST(Extremes, GumbelFitRecoversParameters) {
  const double mu = 10.0, b = 2.0;
  const int n = 20000;
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> x(n);
  for (double& v : x) v = mu - b * std::log(-std::log(u(rng)));
  const GumbelFit fit = fit_gumbel(x);
  EXPECT_NEAR(fit.scale, b, 4 * 0.0074 * b);
  EXPECT_NEAR(fit.location, mu, 4 * std::sqrt(1.1) * b / std::sqrt(n));
  EXPECT_THROW(fit_gumbel(std::vector<double>{1.0}), std::invalid_argument);
}

// the closed forms of the storm extremes (exact to round-off)
TEST(Extremes, ClosedForms) {
  // Rayleigh: N = 10800 / 9 = 1200 peaks; MPM = mean + sigma sqrt(2 ln N); P(max > y) =
  // 1 - (1 - exp(-y^2 / 2 sigma^2))^N = p at the value
  const ExtremeEstimate r = rayleigh_extreme(1.0, 2.0, 9.0, 10800.0, 0.1);
  EXPECT_DOUBLE_EQ(r.storm_count, 1200.0);
  EXPECT_NEAR(r.most_probable_maximum, 1.0 + 2.0 * std::sqrt(2.0 * std::log(1200.0)), 1e-12);
  const double y = r.value_at_exceedance - 1.0;
  EXPECT_NEAR(1.0 - std::pow(1.0 - std::exp(-y * y / 8.0), 1200.0), 0.1, 1e-12);
  // Gumbel: the largest of k = 6 blocks has location mu + b ln 6; at exceedance p:
  // exp(-exp(-(x - mu_k) / b)) = 1 - p
  const std::vector<double> m = {1.0, 2.0, 3.0, 4.0};
  const GumbelFit g = fit_gumbel(m);
  const ExtremeEstimate e = gumbel_extreme(m, 100.0, 600.0, 0.1);
  EXPECT_NEAR(e.most_probable_maximum, g.location + g.scale * std::log(6.0), 1e-12);
  EXPECT_NEAR(std::exp(-std::exp(-(e.value_at_exceedance - e.most_probable_maximum) / g.scale)),
              0.9, 1e-12);
  // Gumbel moments of {1, 2, 3, 4}: s = sqrt(5/3), b = s sqrt(6) / pi
  EXPECT_NEAR(g.scale, std::sqrt(5.0 / 3.0) * std::sqrt(6.0) / std::numbers::pi, 1e-14);
  EXPECT_NEAR(g.location, 2.5 - std::numbers::egamma * g.scale, 1e-14);
}
