#include "seaflex/hydro/directional_spreading.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "seaflex/math/gauss_legendre.hpp"

namespace seaflex::hydro {

namespace {

constexpr double kPi = std::numbers::pi;

// integral of cos^{2s}(x) over [a, b], -pi/2 <= a < b <= pi/2 (see the file comment)
double integral_cos_power(double s, double a, double b, const math::QuadratureRule& rule) {
  const auto piece = [&](double lo, double hi) {
    double sum = 0.0;
    for (std::size_t q = 0; q < rule.points.size(); ++q) {
      const double x = lo + rule.points[q] * (hi - lo);
      sum += rule.weights[q] * std::pow(std::max(0.0, std::cos(x)), 2.0 * s);
    }
    return sum * (hi - lo);
  };
  // grading of [e - h, e] towards e = +-pi/2: pieces [e - h r^k, e - h r^{k+1}], the last
  // one of length h r^40 (its integral is below (h r^40)^{2s+1}: nothing for s > 0.01)
  const auto graded = [&](double lo, double hi, bool at_hi) {
    constexpr double kRatio = 0.2;
    const double h = hi - lo;
    double sum = 0.0, len = h;
    for (int k = 0; k < 40; ++k) {
      const double next = len * kRatio;
      sum += at_hi ? piece(hi - len, hi - next) : piece(lo + next, lo + len);
      len = next;
    }
    return sum + (at_hi ? piece(hi - len, hi) : piece(lo, lo + len));
  };
  const double h = std::min(0.25, 1.0 / std::sqrt(s));
  const int n = std::max(1, static_cast<int>(std::ceil((b - a) / h)));
  const double dx = (b - a) / n;
  constexpr double kEdge = 1e-12;  // a piece ending this close to +-pi/2 is graded
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    const double lo = a + i * dx, hi = i + 1 == n ? b : a + (i + 1) * dx;
    if (hi > 0.5 * kPi - kEdge)
      sum += graded(lo, hi, true);
    else if (lo < -0.5 * kPi + kEdge)
      sum += graded(lo, hi, false);
    else
      sum += piece(lo, hi);
  }
  return sum;
}

// C(s) = Gamma(s + 1) / (2 sqrt(pi) Gamma(s + 1/2)), by lgamma (Gamma overflows for s > 170)
double normalization(double s) {
  return std::exp(std::lgamma(s + 1.0) - std::lgamma(s + 0.5)) / (2.0 * std::sqrt(kPi));
}

}  // namespace

double cos2s_density(double s, double angle) {
  if (!(std::abs(angle) <= kPi)) return 0.0;
  // DNV-RP-C205 (2021) section 3.5.8: D = C(s) cos^{2s}((theta - theta0) / 2)
  return normalization(s) * std::pow(std::cos(0.5 * angle), 2.0 * s);
}

DirectionSet cos2s_directions(const SpreadingSpec& spec) {
  if (!(spec.s > 0.0) || !std::isfinite(spec.s))
    throw std::invalid_argument(fmt::format("s must be > 0, got {}", spec.s));
  if (spec.directions < 1)
    throw std::invalid_argument(fmt::format("directions must be >= 1, got {}", spec.directions));
  if (!(spec.max_angle > 0.0) || !(spec.max_angle <= kPi))
    throw std::invalid_argument(
        fmt::format("max_angle must be in (0, pi], got {}", spec.max_angle));
  const int m = spec.directions;
  const double delta = 2.0 * spec.max_angle / m;
  static const math::QuadratureRule rule = math::gauss_legendre_unit(20);
  DirectionSet set;
  double total = 0.0;
  for (int j = 0; j < m; ++j) {
    const double centre = (j - 0.5 * (m - 1)) * delta;
    // the bin [centre - delta/2, centre + delta/2] in x = theta/2, clipped to [-pi/2, pi/2]
    const double a = std::max(-0.5 * kPi, 0.5 * (centre - 0.5 * delta));
    const double b = std::min(0.5 * kPi, 0.5 * (centre + 0.5 * delta));
    // d theta = 2 dx
    const double w = 2.0 * normalization(spec.s) * integral_cos_power(spec.s, a, b, rule);
    set.angles.push_back(centre);
    set.weights.push_back(w);
    total += w;
  }
  for (double& w : set.weights) w /= total;
  return set;
}

}  // namespace seaflex::hydro
