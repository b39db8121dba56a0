// Statistics and extremes of a synthetic narrow-band Gaussian record (post/statistics,
// post/extremes): 10^6 cycles of white Gaussian noise e_k through two identical sampled
// resonators in series, each an AR(2) filter (Box & Jenkins, Time Series Analysis (1976)
// sec. 3.2.4)
//   y_k = a1 y_{k-1} + a2 y_{k-2} + e_k,   x_k = a1 x_{k-1} + a2 x_{k-2} + y_k,
//   a1 = 2 r cos(theta), a2 = -r^2,
// Gaussian (a linear filter of Gaussian noise) with the variance sigma^2 = sum h_k^2 of its
// impulse response h (Parseval; computed here by running the filter on an impulse). The
// spectrum peaks at theta = 2 pi / 20 rad per sample (20 samples a cycle) with a
// half-width of about 1 - r = 0.005 rad, 1.6 % of the centre; two stages make it fall as
// the fourth power away from the peak, so the record is smooth from sample to sample (one
// stage leaves a white innovation of 4 % of sigma in every sample). Narrow-banded, its peaks
// are Rayleigh and the most probable maximum of N cycles is sigma sqrt(2 ln N)
// (DNV-RP-C205 (2010) 3.5.11).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "seaflex/post/extremes.hpp"
#include "seaflex/post/statistics.hpp"

using namespace seaflex::post;

TEST(NarrowBandExtremes, MostProbableMaximumOfGaussianRecord) {
  const double r = 0.995, theta = 2.0 * std::numbers::pi / 20.0, dt = 0.05;  // 1 s cycles
  const double a1 = 2.0 * r * std::cos(theta), a2 = -r * r;
  // the two-stage filter, one sample
  struct Filter {
    double a1, a2, y1 = 0, y2 = 0, x1 = 0, x2 = 0;
    double operator()(double e) {
      const double y = a1 * y1 + a2 * y2 + e;
      y2 = y1, y1 = y;
      const double x = a1 * x1 + a2 * x2 + y;
      x2 = x1, x1 = x;
      return x;
    }
  };
  double variance = 0.0;  // Parseval: the sum of the squared impulse response
  {
    Filter impulse{a1, a2};
    for (int k = 0; k < 40000; ++k) {  // 200 correlation lengths: the tail is below 1e-80
      const double h = impulse(k == 0 ? 1.0 : 0.0);
      variance += h * h;
    }
  }
  const double sigma = std::sqrt(variance);
  const long cycles = 1000000, samples = 20 * cycles;
  const int blocks = 1000;
  const double duration = samples * dt;
  StatisticsAccumulator acc(blocks, duration / blocks);
  std::mt19937_64 rng(12345);
  std::normal_distribution<double> e(0.0, 1.0);
  Filter filter{a1, a2};
  for (int k = 0; k < 8000; ++k) filter(e(rng));  // 40 correlation lengths: stationary
  for (long k = 0; k < samples; ++k) acc.add(k * dt, filter(e(rng)));
  const RecordStatistics s = acc.result();
  // sigma: 10^6 cycles of ~20-cycle correlation give ~5 10^4 independent stretches: se 0.3 %
  EXPECT_NEAR(s.std, sigma, 0.01 * sigma);
  EXPECT_NEAR(s.skewness, 0.0, 0.02);
  EXPECT_NEAR(s.kurtosis, 3.0, 0.03);
  // the spectral centre is one cycle a second; Rice's Tz of the narrow band lies within
  // its half-width (0.5 %) of it
  EXPECT_NEAR(s.period, 1.0, 0.01);
  const double expected = sigma * std::sqrt(2.0 * std::log(static_cast<double>(cycles)));
  const ExtremeEstimate ray = rayleigh_extreme(s.mean, s.std, s.period, s.duration, 0.1);
  // within 2 % (the tolerance; sigma is within 0.3 % and ln N within 0.1 %)
  EXPECT_NEAR(ray.most_probable_maximum - s.mean, expected, 0.02 * expected);
  // Weibull of the 10^6 peaks: shape 2 and scale sigma sqrt(2) for Rayleigh peaks; the
  // peaks are sampled 20 times a cycle, which lowers them by 1 - cos(pi/20 u), 0.4 % on
  // average; the fit's own error is below 0.1 %. Tolerance 2 % (observed 0.4 % low).
  const ExtremeEstimate wei = weibull_extreme(s.mean, acc.peaks(), s.duration, s.duration, 0.1);
  EXPECT_NEAR(wei.most_probable_maximum - s.mean, expected, 0.02 * expected);
  const WeibullFit wf = fit_weibull(acc.peaks());
  EXPECT_NEAR(wf.shape, 2.0, 0.1);
  // Gumbel of 1000 block maxima, each of 1000 cycles, extrapolated to 1000 blocks: the
  // standard error of b ln k is ln(1000) * 1.05 / sqrt(1000) * b = 0.065 sigma, 1.2 % of
  // the MPM; the maximum of 1000 Rayleigh peaks is not yet Gumbel (its scale still falls
  // as 1 / sqrt(2 ln n)), a bias of the order of 1 % over three decades, plus the 0.4 %
  // sampling loss. Tolerance 4 %: three standard errors plus those (observed 0.9 % low).
  const ExtremeEstimate gum =
      gumbel_extreme(acc.block_maxima(), acc.block_length(), s.duration, 0.1);
  EXPECT_NEAR(gum.most_probable_maximum - s.mean, expected, 0.04 * expected);
  std::printf(
      "sigma %.6f (exact %.6f), Tz %.6f s, MPM/expected: rayleigh %.4f weibull %.4f "
      "gumbel %.4f, Weibull shape %.4f\n",
      s.std, sigma, s.period, (ray.most_probable_maximum - s.mean) / expected,
      (wei.most_probable_maximum - s.mean) / expected,
      (gum.most_probable_maximum - s.mean) / expected, wf.shape);
}
