// Analytic and independent reference solutions used by the verification tests.
#pragma once

#include <cmath>
#include <functional>
#include <numbers>
#include <utility>

namespace seaflex::analytic {

/// Linear cantilever under a uniform load q (N/m): tip deflection q L^4 / (8 E I)
/// (thesis eq. 180; Gere & Timoshenko 1997).
inline double cantilever_tip_deflection(double q, double L, double EI) {
  return q * L * L * L * L / (8.0 * EI);
}

/// Navier's series for the centre deflection of a simply supported rectangular Kirchhoff
/// plate a x b under a uniform load q (Pa), D the flexural rigidity (N m) (thesis eq. 181;
/// Timoshenko & Woinowsky-Krieger 1959, sec. 30):
///   w = 16 q / (pi^6 D) sum_{m, n odd} (-1)^((m + n)/2 - 1) / (m n (m^2/a^2 + n^2/b^2)^2)
/// summed while m, n <= terms (the series converges like 1/m^5).
inline double navier_plate_centre(double q, double a, double b, double D, int terms = 401) {
  double sum = 0.0;
  for (int m = 1; m <= terms; m += 2)
    for (int n = 1; n <= terms; n += 2) {
      const double sign = ((m + n) / 2 - 1) % 2 == 0 ? 1.0 : -1.0;
      const double k = m * m / (a * a) + n * n / (b * b);
      sum += sign / (m * n * k * k);
    }
  return 16.0 * q / (std::pow(std::numbers::pi, 6) * D) * sum;
}

/// Euler-Bernoulli clamped-free beam: beta_n L, roots of cos(x) cosh(x) = -1.
inline constexpr double kCantileverBetaL[] = {1.8751040687, 4.6940911330, 7.8547574382};

/// omega_n = (beta_n L)^2 sqrt(EI / (rho A L^4)) (rad/s).
inline double cantilever_omega(int n, double EI, double rhoA, double L) {
  const double b = kCantileverBetaL[n];
  return b * b * std::sqrt(EI / (rhoA * L * L * L * L));
}

/// Large-deflection (inextensible elastica) cantilever under its own weight q (N/m):
///   theta' = M / EI,  M' = -q (L - s) cos(theta),  theta(0) = 0,  M(L) = 0,
/// with theta the downward slope angle and M the bending moment; solved by shooting on
/// M(0) by bisection and RK4 (n steps) in s. Returns the tip's vertical
/// deflection and its horizontal shortening L - x_tip.
struct ElasticaTip {
  double deflection;
  double shortening;
  double angle = 0.0;  ///< tip slope angle theta(L), rad (down positive)
};

/// With a vertical tip load P (N, downward) as well: M' = -(q (L - s) + P) cos(theta);
/// and a tip moment (N m, sagging positive) that may depend on the tip angle (a body
/// hanging off the tip whose lever turns with it): M(L) = tip_moment(theta(L)).
inline ElasticaTip elastica_cantilever(double q, double L, double EI, int n = 4000, double P = 0.0,
                                       const std::function<double(double)>& tip_moment = {}) {
  // integrates (theta, M, x, z) from 0 to L for a given M(0)
  auto integrate = [&](double M0, double* x_tip, double* z_tip, double* theta_tip) {
    double y[4] = {0.0, M0, 0.0, 0.0};  // theta, M, x, z (down positive)
    auto f = [&](double s, const double* v, double* d) {
      d[0] = v[1] / EI;
      d[1] = -(q * (L - s) + P) * std::cos(v[0]);
      d[2] = std::cos(v[0]);
      d[3] = std::sin(v[0]);
    };
    const double h = L / n;
    for (int i = 0; i < n; ++i) {
      const double s = i * h;
      double k1[4], k2[4], k3[4], k4[4], t[4];
      f(s, y, k1);
      for (int j = 0; j < 4; ++j) t[j] = y[j] + 0.5 * h * k1[j];
      f(s + 0.5 * h, t, k2);
      for (int j = 0; j < 4; ++j) t[j] = y[j] + 0.5 * h * k2[j];
      f(s + 0.5 * h, t, k3);
      for (int j = 0; j < 4; ++j) t[j] = y[j] + h * k3[j];
      f(s + h, t, k4);
      for (int j = 0; j < 4; ++j) y[j] += h / 6.0 * (k1[j] + 2 * k2[j] + 2 * k3[j] + k4[j]);
    }
    if (x_tip) *x_tip = y[2];
    if (z_tip) *z_tip = y[3];
    if (theta_tip) *theta_tip = y[0];
    return y[1] - (tip_moment ? tip_moment(y[0]) : 0.0);  // M(L) - M_tip, to be zero
  };
  // the root moment lies in (0, M_lin], M_lin that of linear theory (the load arm only
  // shortens); M(L) grows with M(0): bisection to round-off
  const double M_lin = 0.5 * q * L * L + P * L + (tip_moment ? std::abs(tip_moment(0.0)) : 0.0);
  double lo = 0.0, hi = M_lin, b = M_lin;
  for (int it = 0; it < 200 && hi - lo > 1e-15 * M_lin; ++it) {
    b = 0.5 * (lo + hi);
    if (integrate(b, nullptr, nullptr, nullptr) > 0.0)
      hi = b;
    else
      lo = b;
  }
  double x = 0, z = 0, theta = 0;
  integrate(b, &x, &z, &theta);
  return {z, L - x, theta};
}

/// Complete elliptic integral of the first kind K(k) from the complementary modulus
/// k' = sqrt(1 - k^2) (passed directly, so k near 1 loses no digits), by the
/// arithmetic-geometric mean: K = pi / (2 agm(1, k')) (Abramowitz & Stegun 17.6).
inline double elliptic_k_complementary(double kprime) {
  double a = 1.0, b = kprime;
  for (int i = 0; i < 64 && std::abs(a - b) > 1e-16 * a; ++i) {
    const double m = 0.5 * (a + b);
    b = std::sqrt(a * b);
    a = m;
  }
  return std::numbers::pi / (a + b);
}

/// Torque-free rigid body (Landau & Lifshitz, Mechanics, sec. 37): principal inertias
/// I1 < I2 < I3 and body angular velocity (w1, w2, w3) about those axes. With
/// E = 1/2 sum I_i w_i^2 and M^2 = sum I_i^2 w_i^2, for M^2 > 2 E I2
///   w2 = sqrt((2 E I3 - M^2) / (I2 (I3 - I2))) sn(tau, k),
///   tau = t sqrt((I3 - I2)(M^2 - 2 E I1) / (I1 I2 I3)),
///   k^2 = (I2 - I1)(2 E I3 - M^2) / ((I3 - I2)(M^2 - 2 E I1)),
///   k'^2 = 1 - k^2 = (I3 - I1)(M^2 - 2 E I2) / ((I3 - I2)(M^2 - 2 E I1)),
/// and with the suffixes 1 and 3 exchanged for M^2 < 2 E I2. sn changes sign every 2 K(k)
/// of tau, so the intermediate axis reverses (w2 and the axis' component along the
/// angular momentum change sign) every 2 K(k) / (dtau/dt) seconds: this is returned.
/// Differences such as M^2 - 2 E I_j are summed as sum I_i (I_i - I_j) w_i^2, without
/// cancellation.
inline double torque_free_flip_interval(double I1, double I2, double I3, double w1, double w2,
                                        double w3) {
  auto diff = [&](double Ij) {  // M^2 - 2 E Ij
    return I1 * (I1 - Ij) * w1 * w1 + I2 * (I2 - Ij) * w2 * w2 + I3 * (I3 - Ij) * w3 * w3;
  };
  if (diff(I2) < 0.0) std::swap(I1, I3);  // the motion circles the other extreme axis
  const double rate = std::sqrt((I3 - I2) * diff(I1) / (I1 * I2 * I3));
  const double kprime = std::sqrt((I3 - I1) * diff(I2) / ((I3 - I2) * diff(I1)));
  return 2.0 * elliptic_k_complementary(kprime) / rate;
}

}  // namespace seaflex::analytic
