#include "seaflex/hydro/dispersion.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace seaflex::hydro {

double wave_number(double omega, double depth, double g) {
  if (!std::isfinite(omega) || omega < 0.0)
    throw std::invalid_argument(fmt::format("wave_number: omega must be >= 0, got {}", omega));
  if (!std::isfinite(g) || g <= 0.0)
    throw std::invalid_argument(fmt::format("wave_number: g must be > 0, got {}", g));
  const double k_deep = omega * omega / g;
  if (omega == 0.0) return 0.0;
  if (depth <= 0.0 || std::isinf(depth)) return k_deep;

  // y tanh(y) = x, y = k d; the root lies in [max(x, sqrt(x)), max(x, sqrt(x)) + 1]
  // because tanh(y) <= 1 and tanh(y) <= y, and y tanh(y) >= y - 1 for y >= 0
  const double x = k_deep * depth;
  if (x > 40.0) return k_deep;  // tanh(y) == 1 in double precision for y > 19
  double lo = std::max(x, std::sqrt(x));
  double hi = lo + 1.0;
  // Eckart (1952) approximation as the starting guess, within 5 %
  double y = x / std::sqrt(std::tanh(x));
  if (y < lo || y > hi) y = 0.5 * (lo + hi);
  for (int iter = 0; iter < 100; ++iter) {
    const double th = std::tanh(y);
    const double f = y * th - x;
    if (f > 0.0) hi = y;
    if (f < 0.0) lo = y;
    const double df = th + y * (1.0 - th * th);
    double y_new = y - f / df;
    // safeguard: Newton stays inside the bracket, otherwise bisect
    if (!(y_new > lo && y_new < hi)) y_new = 0.5 * (lo + hi);
    const double step = std::abs(y_new - y);
    y = y_new;
    if (step <= 1e-16 * y || f == 0.0) break;
  }
  return y / depth;
}

}  // namespace seaflex::hydro
