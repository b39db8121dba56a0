#include "seaflex/simulation/growth_monitor.hpp"

#include <algorithm>
#include <cmath>

namespace seaflex {

std::optional<double> GrowthMonitor::observe(double velocity_norm) {
  current_ = std::max(current_, velocity_norm);
  if (++steps_ < kWindow) return std::nullopt;
  // a window is complete: compare its maximum with the previous window's
  const double previous = last_, now = current_;
  last_ = now;
  current_ = 0.0;
  steps_ = 0;
  if (!(previous > 0.0) || !(now >= kFactor * previous)) {
    growing_ = 0;
    return std::nullopt;
  }
  const double ratio = now / previous;
  if (growing_ == 0) {
    first_ = previous;
    first_ratio_ = ratio;
  }
  if (++growing_ < kWindows) return std::nullopt;
  if (ratio < 0.25 * first_ratio_) {  // slowing down: a start from rest, not a geometric growth
    growing_ = 0;
    return std::nullopt;
  }
  return std::pow(now / first_, 1.0 / static_cast<double>(kWindows * kWindow));
}

double GrowthMonitor::rk4_omega_h(double growth) {
  // |R(iy)|^2 - growth^2 = 1 - y^6/72 + y^8/576 - growth^2 rises monotonically for
  // y > 2 sqrt(2) (its derivative y^5 (y^2 - 6) / 72 > 0): bisection
  const auto f = [growth](double y) {
    return 1.0 - std::pow(y, 6) / 72.0 + std::pow(y, 8) / 576.0 - growth * growth;
  };
  double lo = 2.0 * std::sqrt(2.0), hi = 4.0;
  while (f(hi) < 0.0) hi *= 2.0;
  for (int k = 0; k < 100; ++k) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) < 0.0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace seaflex
