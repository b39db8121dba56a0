// Retardation (memory) kernel of the radiation force in Cummins' equation
// (Cummins 1962, "The impulse response function and ship motions", Schiffstechnik 9;
// thesis eq. 173):
//   (M + A_inf) x'' + int_0^t K(t - s) x'(s) ds + C x = F_exc,
//   K(t) = (2/pi) int_0^inf B(w) cos(w t) dw,
// and its inverse relations (Ogilvie 1964, "Recent progress toward the understanding and
// prediction of ship motions", 5th Symposium on Naval Hydrodynamics):
//   B(w) = int_0^inf K(t) cos(w t) dt,   A(w) = A_inf - (1/w) int_0^inf K(t) sin(w t) dt.
// Quadrature: B(w) is taken piecewise linear between the table's frequencies (from
// (0, 0) when the table does not start at w = 0) and the cosine transform of each linear
// piece is integrated exactly (a Filon-type rule: exact for the interpolant, so there is
// no condition on t dw). The same rule integrates the piecewise-linear K(t) for the
// inverse relations. No high-frequency tail is added: B is zero beyond the last
// tabulated frequency, so the table must reach where B is negligible (otherwise K(t)
// carries a ripple ~ B(w_max) sin(w_max t) / (pi t)).
#pragma once

#include <vector>

#include "seaflex/hydro/hydro_database.hpp"

namespace seaflex::hydro {

/// K(t) (6 x 6, SI: kg/s^2 for translations, kg m/s^2 mixed, kg m^2/s^2 rotations)
/// sampled on t = 0, dt, ..., t_max.
class RetardationKernel {
 public:
  /// K from the tabulated damping db.omega / db.damping (see the file comment), on
  /// t = 0, dt, ..., t_max with t_max rounded to a multiple of dt (s).
  /// Throws std::invalid_argument for dt <= 0, t_max < dt or an empty table.
  static RetardationKernel from_damping(const HydroDatabase& db, double dt, double t_max);

  /// A kernel given by its samples K(k dt), k = 0 .. samples.size() - 1 (e.g. from a
  /// time-domain BEM code, or analytic in tests). Throws std::invalid_argument for
  /// dt <= 0 or fewer than 2 samples.
  static RetardationKernel from_samples(std::vector<Mat6> samples, double dt);

  /// K(t) by linear interpolation between samples; zero for t < 0 and t > t_max (s).
  Mat6 at(double t) const;
  /// Sample spacing (s).
  double dt() const { return dt_; }
  /// Last sample time (s).
  double t_max() const { return dt_ * static_cast<double>(samples_.size() - 1); }
  /// K(k dt), k = 0, 1, ...
  const std::vector<Mat6>& samples() const { return samples_; }

  /// B(omega) = int_0^t_max K(t) cos(omega t) dt (same units as HydroDatabase::damping),
  /// omega in rad/s; the round trip of from_damping.
  Mat6 damping(double omega) const;
  /// A(omega) = a_inf - (1/omega) int_0^t_max K(t) sin(omega t) dt (Ogilvie 1964), omega in
  /// rad/s (omega = 0: a_inf - int_0^t_max K(t) t dt), a_inf = A(infinity).
  Mat6 added_mass(double omega, const Mat6& a_inf) const;

 private:
  RetardationKernel(std::vector<Mat6> samples, double dt) : samples_(std::move(samples)), dt_(dt) {}

  std::vector<Mat6> samples_;
  double dt_;
};

}  // namespace seaflex::hydro
