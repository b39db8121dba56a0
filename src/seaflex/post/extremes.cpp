#include "seaflex/post/extremes.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace seaflex::post {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// -ln(1 - q) with q = (1 - p)^(1/N): the reduced variate of a per-peak probability whose
// N-th power is 1 - p, without the cancellation of 1 - q for large N
double tail_variate(double p, double N) {
  const double one_minus_q = -std::expm1(std::log1p(-p) / N);
  return -std::log(one_minus_q);
}

}  // namespace

WeibullFit fit_weibull(std::span<const double> values) {
  std::vector<double> y;
  for (double v : values)
    if (v > 0.0 && std::isfinite(v)) y.push_back(v);
  if (y.size() < 2) throw std::invalid_argument("fit_weibull: fewer than 2 positive values");
  const double top = *std::max_element(y.begin(), y.end());
  // scaled by the largest value: y^b neither overflows nor changes the shape equation
  std::vector<double> ln(y.size());
  double mean_ln = 0.0;
  for (std::size_t i = 0; i < y.size(); ++i) {
    ln[i] = std::log(y[i] / top);
    mean_ln += ln[i];
  }
  mean_ln /= static_cast<double>(y.size());
  if (!(mean_ln < 0.0)) throw std::invalid_argument("fit_weibull: the values have no spread");
  // ML shape equation (JKB 1994 eq. (21.74)); increasing in b, solved by bisection on ln b
  const auto g = [&](double b) {
    double s0 = 0.0, s1 = 0.0;
    for (double l : ln) {
      const double w = std::exp(b * l);
      s0 += w;
      s1 += w * l;
    }
    return s1 / s0 - 1.0 / b - mean_ln;
  };
  double lo = std::log(1e-3), hi = std::log(1e3);
  for (int it = 0; it < 200 && hi - lo > 1e-15; ++it) {
    const double mid = 0.5 * (lo + hi);
    (g(std::exp(mid)) < 0.0 ? lo : hi) = mid;
  }
  const double beta = std::exp(0.5 * (lo + hi));
  double s0 = 0.0;
  for (double l : ln) s0 += std::exp(beta * l);
  const double alpha = top * std::pow(s0 / static_cast<double>(y.size()), 1.0 / beta);
  return {alpha, beta};  // JKB 1994 eq. (21.73)
}

GumbelFit fit_gumbel(std::span<const double> values) {
  if (values.size() < 2) throw std::invalid_argument("fit_gumbel: fewer than 2 values");
  const double n = static_cast<double>(values.size());
  double mean = 0.0;
  for (double v : values) mean += v;
  mean /= n;
  double ss = 0.0;
  for (double v : values) ss += (v - mean) * (v - mean);
  const double s = std::sqrt(ss / (n - 1.0));
  const double b = s * std::sqrt(6.0) / std::numbers::pi;  // Gumbel (1958): var = pi^2 b^2 / 6
  return {mean - std::numbers::egamma * b, b};
}

ExtremeEstimate rayleigh_extreme(double mean, double sigma, double tz, double storm_duration,
                                 double p) {
  ExtremeEstimate e;
  e.method = "rayleigh";
  e.input = "sigma and the mean up-crossing period of the record (narrow-band Gaussian)";
  e.parameters = fmt::format("sigma={:.10g};Tz={:.10g}", sigma, tz);
  e.storm_duration = storm_duration;
  e.storm_count = storm_duration / tz;
  e.exceedance_probability = p;
  const double N = e.storm_count;
  // characteristic largest of N Rayleigh amplitudes: sigma sqrt(2 ln N) (Ochi 1998)
  e.most_probable_maximum = N > 1.0 ? mean + sigma * std::sqrt(2.0 * std::log(N)) : kNaN;
  e.value_at_exceedance = N > 0.0 ? mean + sigma * std::sqrt(2.0 * tail_variate(p, N)) : kNaN;
  return e;
}

ExtremeEstimate weibull_extreme(double mean, std::span<const double> peaks, double record_duration,
                                double storm_duration, double p) {
  std::vector<double> amplitudes;
  for (double x : peaks) amplitudes.push_back(x - mean);
  const WeibullFit fit = fit_weibull(amplitudes);
  ExtremeEstimate e;
  e.method = "weibull";
  e.input =
      fmt::format("{} peak amplitudes above the mean, 2-parameter Weibull by maximum likelihood",
                  amplitudes.size());
  e.parameters = fmt::format("scale={:.10g};shape={:.10g}", fit.scale, fit.shape);
  e.storm_duration = storm_duration;
  e.storm_count = storm_duration * static_cast<double>(amplitudes.size()) / record_duration;
  e.exceedance_probability = p;
  const double N = e.storm_count;
  e.most_probable_maximum =
      N > 1.0 ? mean + fit.scale * std::pow(std::log(N), 1.0 / fit.shape) : kNaN;
  e.value_at_exceedance = mean + fit.scale * std::pow(tail_variate(p, N), 1.0 / fit.shape);
  return e;
}

ExtremeEstimate gumbel_extreme(std::span<const double> block_maxima, double block_duration,
                               double storm_duration, double p) {
  std::vector<double> m;
  for (double x : block_maxima)
    if (std::isfinite(x)) m.push_back(x);
  const GumbelFit fit = fit_gumbel(m);
  ExtremeEstimate e;
  e.method = "gumbel";
  e.input = fmt::format("maxima of {} blocks of {:.10g} s, Gumbel by the method of moments",
                        m.size(), block_duration);
  e.parameters = fmt::format("location={:.10g};scale={:.10g}", fit.location, fit.scale);
  e.storm_duration = storm_duration;
  e.storm_count = storm_duration / block_duration;
  e.exceedance_probability = p;
  // the largest of k blocks: F^k is a Gumbel with location mu + b ln k
  const double mu = fit.location + fit.scale * std::log(e.storm_count);
  e.most_probable_maximum = mu;
  e.value_at_exceedance = mu - fit.scale * std::log(-std::log1p(-p));
  return e;
}

}  // namespace seaflex::post
