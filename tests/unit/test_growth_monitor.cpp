// GrowthMonitor (simulation/growth_monitor.hpp): fires on the geometric growth of an RK4 run
// above its stability limit, not on the polynomial growth of a motion starting from rest
// nor on an undamped oscillation; and the omega h it infers from a growth per step is the
// one whose amplification |R(i omega h)|, computed here with complex numbers from the
// polynomial R(z) = 1 + z + z^2/2 + z^3/6 + z^4/24, gives that growth.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>

#include "seaflex/simulation/growth_monitor.hpp"

namespace {

std::complex<double> rk4_r(double y) {
  const std::complex<double> z(0.0, y);
  return 1.0 + z + z * z / 2.0 + z * z * z / 6.0 + z * z * z * z / 24.0;
}

// steps until the monitor fires (0: never, within `steps`), |v|_k = norm(k)
template <class F>
int fires_after(F norm, int steps) {
  seaflex::GrowthMonitor m;
  for (int k = 1; k <= steps; ++k)
    if (m.observe(norm(k))) return k;
  return 0;
}

}  // namespace

TEST(GrowthMonitor, RecoversOmegaHFromTheRk4Amplification) {
  // the inverse of |R(iy)| on y > 2 sqrt(2), to the bisection's round-off
  for (double y : {2.9, 3.0, 3.5, 5.0, 20.0})
    EXPECT_NEAR(seaflex::GrowthMonitor::rk4_omega_h(std::abs(rk4_r(y))), y, 1e-10 * y) << y;
  EXPECT_NEAR(std::abs(rk4_r(2.0 * std::sqrt(2.0))), 1.0, 1e-14);  // the stability limit
}

TEST(GrowthMonitor, FiresOnAnRk4SpringAboveItsLimit) {
  // the velocity of an undamped spring integrated by RK4: |v_k| = |Re(R^k)| amplitude
  for (double y : {3.0, 3.5, 5.0}) {
    const std::complex<double> R = rk4_r(y);
    const int k = fires_after([&](int n) { return std::abs(std::pow(R, n).imag()); }, 200);
    // five windows of six steps (the first one sets the scale), whatever the phase
    EXPECT_EQ(k, 5 * seaflex::GrowthMonitor::kWindow) << y;
  }
}

TEST(GrowthMonitor, QuietOnResolvedMotions) {
  // a start from rest, |v| ~ t^p for powers below 12: the window ratios fall (a higher
  // power is locally an exponential: growth_monitor.hpp)
  for (double p = 0.5; p < 12.0; p += 0.5)
    EXPECT_EQ(fires_after([&](int n) { return std::pow(n * 1e-3, p); }, 5000), 0) << p;
  // a stable RK4 spring (omega h = 2.8) and an undamped oscillation
  EXPECT_EQ(fires_after([](int n) { return std::abs(std::pow(rk4_r(2.8), n).imag()); }, 5000), 0);
  EXPECT_EQ(fires_after([](int n) { return std::abs(std::sin(0.3 * n)); }, 5000), 0);
  // a resolved physical exponential growth, e^(lambda t) with lambda h = 0.05
  EXPECT_EQ(fires_after([](int n) { return std::exp(0.05 * n); }, 5000), 0);
  // at rest, then a sudden kick (a snap load), then a decaying oscillation
  EXPECT_EQ(
      fires_after(
          [](int n) { return n < 100 ? 1e-18 : std::exp(-0.01 * (n - 100)) * (1.0 + std::sin(n)); },
          5000),
      0);
}
