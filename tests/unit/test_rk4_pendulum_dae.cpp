// RK4 on the augmented formulation driven by a hand-written DAE: a point-mass pendulum
// in Cartesian coordinates with the nonlinear constraint x^2 + z^2 - L^2 = 0. Checks the
// period against the exact elliptic-integral value, energy conservation, constraint
// drift under projection, Baumgarte stabilization, and fourth-order convergence.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "pendulum_dae.hpp"
#include "seaflex/integrators/rk4_augmented.hpp"

using namespace seaflex;
using seaflex::test_support::PendulumDae;

namespace {

// time of the first upward zero crossing of x after t = 0 (start at x > 0, v = 0):
// x crosses zero downward at T/4 and upward at 3T/4
double three_quarter_period(PendulumDae& dae, Integrator& rk4, double theta0, double h) {
  State s = dae.start(theta0);
  double x_prev = s.q[0];
  bool down = false;
  for (int k = 0; k < 1000000; ++k) {
    const double t_prev = s.t;
    rk4.step(dae, s, h);
    if (!down && x_prev > 0 && s.q[0] <= 0) down = true;
    if (down && x_prev < 0 && s.q[0] >= 0)
      return t_prev + h * (-x_prev) / (s.q[0] - x_prev);  // linear interpolation
    x_prev = s.q[0];
  }
  return NAN;
}

}  // namespace

TEST(Rk4Pendulum, PeriodMatchesEllipticIntegral) {
  const double L = 2.0, g = 9.81, theta0 = 1.0;
  PendulumDae dae(3.0, L, g);
  Rk4Augmented rk4(Stabilization::kProjection);
  // exact period T = 4 sqrt(L/g) K(sin(theta0/2))
  const double T = 4.0 * std::sqrt(L / g) * std::comp_ellint_1(std::sin(theta0 / 2));
  const double t34 = three_quarter_period(dae, rk4, theta0, 1e-3);
  // interpolation error of the crossing ~ h^2 * a / v: well below 1e-6 s
  EXPECT_NEAR(t34, 0.75 * T, 1e-6);
}

TEST(Rk4Pendulum, ProjectionKeepsConstraintAndEnergy) {
  PendulumDae dae(1.0, 1.0, 9.81);
  Rk4Augmented rk4(Stabilization::kProjection);
  State s = dae.start(1.2);
  const double E0 = dae.energy(s);
  double drift = 0.0;
  for (int k = 0; k < 10000; ++k) drift = std::max(drift, rk4.step(dae, s, 1e-3).residual);
  EXPECT_LT(drift, 1e-12);  // projected to round-off every step
  EXPECT_NEAR(dae.energy(s) / E0, 1.0, 1e-6);
}

TEST(Rk4Pendulum, BaumgarteBoundsDriftUnstabilizedDrifts) {
  PendulumDae dae(1.0, 1.0, 9.81);
  Rk4Augmented plain(Stabilization::kNone), baum(Stabilization::kBaumgarte, 10.0, 10.0);
  State a = dae.start(1.2), b = a;
  double drift_plain = 0, drift_baum = 0;
  for (int k = 0; k < 5000; ++k) {
    drift_plain = std::max(drift_plain, std::abs(plain.step(dae, a, 1e-2).residual));
    drift_baum = std::max(drift_baum, std::abs(baum.step(dae, b, 1e-2).residual));
  }
  EXPECT_GT(drift_plain, 10 * drift_baum);
  EXPECT_LT(drift_baum, 1e-5);
}

// global error of RK4 falls by 2^4 when h halves (MFEM-style convergence study)
TEST(Rk4Pendulum, FourthOrderConvergence) {
  PendulumDae dae(1.0, 1.0, 9.81);
  auto run = [&](double h) {
    Rk4Augmented rk4(Stabilization::kNone);
    State s = dae.start(0.8);
    const int n = static_cast<int>(std::lround(1.0 / h));
    for (int k = 0; k < n; ++k) rk4.step(dae, s, h);
    return s.q;
  };
  const VecX ref = run(1.0 / 3200);
  const double e1 = (run(1.0 / 50) - ref).norm(), e2 = (run(1.0 / 100) - ref).norm();
  const double order = std::log2(e1 / e2);
  EXPECT_NEAR(order, 4.0, 0.3);
}
