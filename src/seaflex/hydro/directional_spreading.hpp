// Directional spreading of a short-crested sea: the cos-2s distribution of Longuet-Higgins,
// Cartwright & Smith (1963), as DNV-RP-C205 (2021) section 3.5.8 (directional distribution
// of wind sea and swell) writes it,
//   S(omega, theta) = S(omega) D(theta),
//   D(theta) = C(s) cos^{2s}((theta - theta0) / 2),   |theta - theta0| <= pi,
//   C(s) = Gamma(s + 1) / (2 sqrt(pi) Gamma(s + 1/2)),
// so that the integral of D over the circle is 1. Its circular moments are
//   E[cos n(theta - theta0)] = Gamma(s + 1)^2 / (Gamma(s + 1 - n) Gamma(s + 1 + n)),
// n = 1: s / (s + 1); n = 2: s (s - 1) / ((s + 1) (s + 2)).
// Discretization (equal-angle direction set): M bins of width Delta = 2 theta_max / M tile
// [theta0 - theta_max, theta0 + theta_max]; direction j (0-based) lies at the centre of bin j,
//   theta_j = theta0 + (j - (M - 1) / 2) Delta,
// (M odd puts one on theta0) and carries the weight w_j = integral of D over bin j divided by
// the integral of D over [-theta_max, theta_max] (the weights sum to 1; with theta_max = pi
// the divisor is 1). The integrals are composite 20-point Gauss-Legendre in
// x = (theta - theta0) / 2 over pieces no wider than min(0.25, 1/sqrt(s)) rad (D is about a
// Gaussian of standard deviation 1/sqrt(2s) in x), geometrically graded towards x = +-pi/2
// where cos^{2s} has a weak singularity for s < 1/2; within 1e-13 of scipy's adaptive
// quadrature (tests/unit/test_directional_spreading.cpp).
// A bin-centred set is slightly wider than D: for a smooth f, the sum of w_j f(theta_j)
// differs from the integral of D f by (Delta^2 / 24) * integral of D f'' + O(Delta^4)
// (theta_max = pi), e.g. E[cos] is low by (Delta^2 / 24) s / (s + 1).
#pragma once

#include <vector>

namespace seaflex::hydro {

/// The cos-2s spreading of an irregular sea (see the file comment).
struct SpreadingSpec {
  double s = 8.0;                        ///< spreading exponent (-), > 0
  int directions = 1;                    ///< M, the number of discrete directions, >= 1
  double max_angle = 3.141592653589793;  ///< theta_max (rad), 0 < theta_max <= pi
};

/// A discrete set of directions relative to the mean direction, with weights summing to 1.
struct DirectionSet {
  std::vector<double> angles;   ///< theta_j - theta0 (rad), increasing
  std::vector<double> weights;  ///< w_j (-), sum 1

  /// One direction, the mean one, with weight 1 (a long-crested sea).
  static DirectionSet long_crested() { return {{0.0}, {1.0}}; }
};

/// D(theta) (1/rad) of cos-2s with exponent s at theta - theta0 = angle (rad); 0 beyond pi.
double cos2s_density(double s, double angle);

/// The equal-angle discretization of cos-2s described in the file comment.
/// Throws std::invalid_argument naming the field: "s must be > 0, got 0",
/// "directions must be >= 1, got 0", "max_angle must be in (0, pi], got 4".
DirectionSet cos2s_directions(const SpreadingSpec& spec);

}  // namespace seaflex::hydro
