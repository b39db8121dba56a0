// Extreme values of a response in a storm whose duration may differ from the simulated
// one, by three methods (maxima only; for minima analyse the negated record):
//
// Rayleigh (narrow-band Gaussian): the amplitudes a = x_peak - mean of N = T_s / Tz peaks
//   are Rayleigh, P(a > y) = exp(-y^2 / (2 sigma^2)) (Rice 1944; DNV-RP-C205 (2010)
//   eq. (3.5.11)); the storm maximum has P(max <= y) = (1 - exp(-y^2 / 2 sigma^2))^N.
// Weibull of the peaks: the amplitudes above the mean fitted by a 2-parameter Weibull
//   F(y) = 1 - exp(-(y / alpha)^beta) by maximum likelihood (Johnson, Kotz & Balakrishnan,
//   Continuous Univariate Distributions vol. 1 (1994), eq. (21.73)-(21.74): beta solves
//   sum y^b ln y / sum y^b - 1/b - mean(ln y) = 0, alpha = (mean y^beta)^(1/beta)); the
//   storm holds N = T_s * (peaks per second of the record) peaks.
// Gumbel of block maxima: the maxima of equal blocks of duration T_b fitted by
//   F(x) = exp(-exp(-(x - mu) / b)) by the method of moments (b = s sqrt(6) / pi,
//   mu = mean - gamma_E b; Gumbel 1958, s the sample standard deviation with n - 1); the
//   storm maximum is the maximum of k = T_s / T_b blocks: F^k, a Gumbel with mu + b ln k.
//
// Most probable maximum (MPM): for Rayleigh and Weibull the characteristic largest value
// F(y_N) = 1 - 1/N, the mode of the distribution of the largest of N to O(1/ln N) (Ochi,
// Ocean Waves (1998) sec. 9.3; for Rayleigh sigma sqrt(2 ln N)); for Gumbel the mode of the
// storm maximum, mu + b ln k. Value at exceedance probability p: the y with
// P(storm max > y) = p, from F^N = 1 - p.
#pragma once

#include <span>
#include <string>
#include <vector>

namespace seaflex::post {

struct WeibullFit {
  double scale = 0.0;  ///< alpha, units of the data
  double shape = 0.0;  ///< beta
};
/// 2-parameter Weibull by maximum likelihood; values <= 0 are left out. Throws
/// std::invalid_argument with fewer than 2 positive values or no spread.
WeibullFit fit_weibull(std::span<const double> values);

struct GumbelFit {
  double location = 0.0;  ///< mu
  double scale = 0.0;     ///< b
};
/// Gumbel (largest values) by the method of moments. Throws std::invalid_argument with
/// fewer than 2 values.
GumbelFit fit_gumbel(std::span<const double> values);

/// One extreme-value estimate: the method, what it was fitted to and its results.
struct ExtremeEstimate {
  std::string method;           ///< rayleigh, weibull, gumbel
  std::string input;            ///< what the fit used, for the output file
  std::string parameters;       ///< "name=value;..." of the fitted distribution
  double storm_duration = 0.0;  ///< T_s (s)
  double storm_count = 0.0;     ///< N peaks (Rayleigh, Weibull) or k blocks (Gumbel)
  double most_probable_maximum = 0.0;
  double exceedance_probability = 0.0;
  double value_at_exceedance = 0.0;
};

/// Rayleigh: mean, sigma and Tz of the record; storm of storm_duration seconds.
ExtremeEstimate rayleigh_extreme(double mean, double sigma, double tz, double storm_duration,
                                 double exceedance_probability);
/// Weibull of the peak amplitudes above the mean; peaks over record_duration seconds.
ExtremeEstimate weibull_extreme(double mean, std::span<const double> peaks, double record_duration,
                                double storm_duration, double exceedance_probability);
/// Gumbel of the maxima of blocks of block_duration seconds.
ExtremeEstimate gumbel_extreme(std::span<const double> block_maxima, double block_duration,
                               double storm_duration, double exceedance_probability);

}  // namespace seaflex::post
