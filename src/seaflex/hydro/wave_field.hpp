// Linear superposition of Airy wave components: free-surface elevation, water particle
// velocity and local acceleration, and dynamic pressure, with Wheeler stretching above
// the mean free surface.
// - Airy (linear) theory over a flat bed of depth d, theta_i = w t - k (x cos b + y sin b) + phase:
//     eta = a cos(theta)
//     u_h = a w cosh(k(z+d)) / sinh(kd) cos(theta)      (along the direction b)
//     u_z = -a w sinh(k(z+d)) / sinh(kd) sin(theta)
//     p_d = rho g a cosh(k(z+d)) / cosh(kd) cos(theta)
//   (DNV-RP-C205 (2021) table 3-1, written with the e^{i w t} phase of WAMIT; the sign of
//   u_z follows from the kinematic surface condition u_z = d eta/dt at z = 0.)
//   Accelerations are the local time derivatives du/dt (no convective term, linear).
//   Deep water (d infinite): all three depth factors become e^{kz}.
//   The depth factors are evaluated as ratios of exponentials,
//     cosh(k(z+d))/sinh(kd) = (e^{kz} + e^{-k(z+2d)}) / (1 - e^{-2kd}),
//   which cannot overflow for short waves in deep water.
// - Wheeler stretching (Wheeler 1970, "Method for calculating forces produced by irregular
//   waves", J. Petroleum Technology 22; DNV-RP-C205 3.3.3): below the instantaneous
//   surface eta the profile is evaluated at z_s = d (z - eta) / (d + eta) (deep water:
//   z_s = z - eta), so the surface values of linear theory hold at the true surface.
//   Without stretching, points in (0, eta] take the z = 0 values (constant extrapolation).
#pragma once

#include <limits>
#include <memory>
#include <vector>

#include "seaflex/core/types.hpp"
#include "seaflex/hydro/ramp.hpp"
#include "seaflex/hydro/wave_component.hpp"

namespace seaflex::hydro {

class WaveGrid;

/// Fluid state at one point: z up, mean free surface at z = 0, seabed at z = -depth.
struct FluidKinematics {
  Vec3 velocity = Vec3::Zero();      ///< (m/s)
  Vec3 acceleration = Vec3::Zero();  ///< local du/dt (m/s^2)
  double dynamic_pressure = 0.0;     ///< (Pa), excluding the hydrostatic -rho g z
  bool wet = false;                  ///< the point is at or below the instantaneous surface
};

/// A linear sea state: a sum of Airy components, multiplied by a start-up ramp.
class WaveField {
 public:
  /// depth (m, > 0; std::numeric_limits<double>::infinity() for deep water), g (m/s^2,
  /// > 0), rho (kg/m^3, > 0), the components (their k must satisfy the dispersion
  /// relation for this depth and g: build them with regular_component or
  /// irregular_components), the ramp, and Wheeler stretching on or off.
  /// Throws std::invalid_argument for depth <= 0 or NaN, g <= 0 or rho <= 0.
  WaveField(double depth, double g, double rho, std::vector<WaveComponent> components, Ramp ramp,
            bool wheeler_stretching = true);

  /// Free-surface elevation eta (m) at (x, y) (m) and time t (s), ramp included.
  double elevation(double x, double y, double t) const;

  /// Velocity, local acceleration and dynamic pressure at p (m, world frame) and time t (s),
  /// ramp included (the ramp multiplies velocity, acceleration and pressure; the term
  /// ramp'(t) u of the acceleration is neglected, as in common practice). Above the instantaneous
  /// surface: all zero and wet = false. Points below the seabed (z < -depth) get the seabed values
  /// (wet = true). pressure = false: the caller does not need the dynamic pressure; the grid
  /// (set_grid) then neither fills nor interpolates it and returns NaN for it (the exact sum
  /// computes it anyway).
  FluidKinematics kinematics(const Vec3& p, double t, bool pressure = true) const;

  /// The components as given to the constructor.
  const std::vector<WaveComponent>& components() const { return components_; }
  /// The ramp factor (-) at time t (s).
  double ramp_factor(double t) const { return ramp_.factor(t); }
  /// Water depth (m); infinity for deep water.
  double depth() const { return depth_; }
  /// Gravity (m/s^2).
  double g() const { return g_; }
  /// Water density (kg/m^3).
  double rho() const { return rho_; }
  /// Whether Wheeler stretching is applied.
  bool wheeler_stretching() const { return wheeler_; }

  /// A bound on |elevation(x, y, t)| everywhere, with the exact sum or the grid (m):
  /// 1.5625 sum |a_i|. The exact sum is at most sum |a_i| (the ramp is in [0, 1]); the grid's
  /// cubic Lagrange interpolation in s and in t multiplies that by at most its Lebesgue
  /// constant on the middle interval, 1.25 per direction (weights -1/16, 9/16, 9/16, -1/16
  /// at the midpoint). A point below -elevation_bound() is under water at every time.
  double elevation_bound() const { return 1.5625 * amplitude_sum_; }

  /// Evaluates elevation() and kinematics() by interpolation in `grid` (wave_grid.hpp; built
  /// from a copy of this field without a grid) instead of the exact sum; nullptr: exact.
  void set_grid(std::shared_ptr<const WaveGrid> grid) { grid_ = std::move(grid); }
  /// The grid in use, or nullptr for the exact sum.
  const WaveGrid* grid() const { return grid_.get(); }

 private:
  // Airy kinematics of all components at (x, y, z) with z in [-depth, 0], without the ramp
  FluidKinematics airy(double x, double y, double z, double t) const;

  double depth_;
  double g_;
  double rho_;
  std::vector<WaveComponent> components_;
  std::vector<double> cos_dir_;
  std::vector<double> sin_dir_;
  Ramp ramp_;
  bool wheeler_;
  bool deep_;
  double amplitude_sum_ = 0.0;  // sum |a_i| (m)
  std::shared_ptr<const WaveGrid> grid_;
};

}  // namespace seaflex::hydro
