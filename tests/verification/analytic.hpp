// Analytic and independent reference solutions used by the verification tests.
#pragma once

#include <cmath>
#include <functional>
#include <numbers>

namespace seaflex::analytic {

/// Linear cantilever under a uniform load q (N/m): tip deflection q L^4 / (8 E I)
/// (thesis eq. 180; Gere & Timoshenko 1997).
inline double cantilever_tip_deflection(double q, double L, double EI) {
  return q * L * L * L * L / (8.0 * EI);
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
};

/// With a vertical tip load P (N, downward) as well: M' = -(q (L - s) + P) cos(theta).
inline ElasticaTip elastica_cantilever(double q, double L, double EI, int n = 4000,
                                       double P = 0.0) {
  // integrates (theta, M, x, z) from 0 to L for a given M(0)
  auto integrate = [&](double M0, double* x_tip, double* z_tip) {
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
    return y[1];  // M(L), to be zero
  };
  // the root moment lies in (0, M_lin], M_lin that of linear theory (the load arm only
  // shortens); M(L) grows with M(0): bisection to round-off
  const double M_lin = 0.5 * q * L * L + P * L;
  double lo = 0.0, hi = M_lin, b = M_lin;
  for (int it = 0; it < 200 && hi - lo > 1e-15 * M_lin; ++it) {
    b = 0.5 * (lo + hi);
    if (integrate(b, nullptr, nullptr) > 0.0)
      hi = b;
    else
      lo = b;
  }
  double x = 0, z = 0;
  integrate(b, &x, &z);
  return {z, L - x};
}

}  // namespace seaflex::analytic
