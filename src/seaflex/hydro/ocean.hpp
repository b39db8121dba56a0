// The sea a model sits in: water density, depth, gravity, the wave field and the current
// profile, and the fluid velocity and acceleration at a point (waves plus current) that
// Morison loads need (thesis eq. 176). z is up; the mean free surface is z = 0; the
// seabed is at z = -depth.
#pragma once

#include <memory>

#include "seaflex/core/types.hpp"
#include "seaflex/hydro/current_profile.hpp"
#include "seaflex/hydro/wave_field.hpp"

namespace seaflex::hydro {

/// Fluid at one point and time: velocity (waves + current) and acceleration (waves; the
/// current is steady), wet = below the instantaneous surface.
struct FluidPoint {
  Vec3 velocity = Vec3::Zero();
  Vec3 acceleration = Vec3::Zero();
  double dynamic_pressure = 0.0;  ///< wave pressure (Pa), without the hydrostatic -rho g z
  bool wet = false;
};

class Ocean {
 public:
  /// waves: may hold no components (still water). current: may be empty.
  Ocean(double rho, double g, double depth, WaveField waves, CurrentProfile current);

  double rho() const { return rho_; }
  double g() const { return g_; }
  /// Water depth (m), +infinity for deep water.
  double depth() const { return depth_; }
  const WaveField& waves() const { return waves_; }
  const CurrentProfile& current() const { return current_; }
  bool has_waves() const { return !waves_.components().empty(); }

  /// Surface elevation eta(x, y, t) (m), including the wave ramp.
  double elevation(double x, double y, double t) const;
  /// Fluid velocity and acceleration at p; zero (and wet = false) above the surface.
  /// The current applies below the surface; in a crest above z = 0 it takes its z = 0
  /// value. Below the seabed nothing is wet. pressure = false: the dynamic pressure is not
  /// needed (NaN when the grid skips it; WaveField::kinematics).
  FluidPoint fluid(const Vec3& p, double t, bool pressure = true) const;

 private:
  double rho_, g_, depth_;
  WaveField waves_;
  CurrentProfile current_;
};

}  // namespace seaflex::hydro
