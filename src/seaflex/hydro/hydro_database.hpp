// Frequency-domain hydrodynamic coefficients of one rigid body in its 6 modes (surge,
// sway, heave, roll, pitch, yaw about the body's reference point), dimensional SI:
// added mass A(w), radiation damping B(w), their w -> infinity and w -> 0 limits,
// first-order wave excitation X(w, beta) per unit wave amplitude and the hydrostatic
// restoring matrix C. Phases follow WAMIT (User Manual v7, ch. 4): with the incident
// wave eta = Re{A e^{i (w t - k x cos(beta) - k y sin(beta))}} (see wave_component.hpp)
// the exciting force is F(t) = Re{X A e^{i w t}}.
// Filled by read_wamit (wamit_reader.hpp); the interpolation is linear in w and beta.
#pragma once

#include <complex>
#include <vector>

#include "seaflex/core/types.hpp"

namespace seaflex::hydro {

using Vec6 = Eigen::Matrix<double, 6, 1>;
using Mat6 = Eigen::Matrix<double, 6, 6>;
using Vec6c = Eigen::Matrix<std::complex<double>, 6, 1>;

/// Hydrodynamic database of one body; every matrix in SI units (kg, kg m, kg m^2 for
/// added mass; kg/s, kg m/s, kg m^2/s for damping; N/m, N m/m, N m/rad for stiffness).
struct HydroDatabase {
  std::vector<double> omega;     ///< (rad/s), strictly ascending, finite frequencies only
  std::vector<Mat6> added_mass;  ///< A(omega[k]), one per omega
  std::vector<Mat6> damping;     ///< B(omega[k]), one per omega
  bool has_added_mass_inf = false;
  Mat6 added_mass_inf = Mat6::Zero();  ///< A(infinity), from WAMIT's PER = 0 rows
  bool has_added_mass_zero = false;
  Mat6 added_mass_zero = Mat6::Zero();  ///< A(0), from WAMIT's PER = -1 rows
  std::vector<double> headings;         ///< (rad), ascending; beta = direction the wave travels to
  /// excitation[heading][omega]: force (N/m) and moment (N m/m) per unit wave amplitude,
  /// F = Re{X A e^{i w t}}
  std::vector<std::vector<Vec6c>> excitation;
  bool has_excitation = false;
  bool has_hydrostatics = false;
  Mat6 hydrostatic_stiffness = Mat6::Zero();  ///< C

  /// X at omega (rad/s) and heading (rad), linear interpolation of the real and imaginary
  /// parts in omega and heading. Headings wrap around 360 deg when the set covers the
  /// circle (the gap from the last heading back to the first + 360 deg is not larger
  /// than the largest gap between neighbours, e.g. 0:15:345 deg or 0:15:360 deg);
  /// otherwise the heading is taken to the equivalent angle nearest the covered range
  /// and clamped to it. Outside [omega.front(), omega.back()] omega is clamped to the
  /// nearest end. *extrapolated (if given) is set to whether omega was clamped;
  /// *heading_clamped (if given) to whether the heading was clamped by more than 1e-9 rad
  /// (always the case for a query off the only heading of a one-heading table).
  /// Returns zero when there is no excitation data.
  Vec6c excitation_at(double omega, double heading, bool* extrapolated = nullptr,
                      bool* heading_clamped = nullptr) const;
  /// A(omega), linear interpolation in omega (rad/s), clamped to the table's ends
  /// (not interpolated towards added_mass_zero or added_mass_inf). Zero for an empty table.
  Mat6 added_mass_at(double omega) const;
  /// B(omega), linear interpolation in omega (rad/s), clamped to the table's ends.
  Mat6 damping_at(double omega) const;
};

}  // namespace seaflex::hydro
