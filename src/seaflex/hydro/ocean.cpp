#include "seaflex/hydro/ocean.hpp"

#include <algorithm>
#include <cmath>

#include "seaflex/hydro/kinematics_timer.hpp"

namespace seaflex::hydro {

Ocean::Ocean(double rho, double g, double depth, WaveField waves, CurrentProfile current)
    : rho_(rho), g_(g), depth_(depth), waves_(std::move(waves)), current_(std::move(current)) {}

double Ocean::elevation(double x, double y, double t) const {
  const kinematics_timer::Scope timed;
  return waves_.elevation(x, y, t);
}

FluidPoint Ocean::fluid(const Vec3& p, double t, bool pressure) const {
  const kinematics_timer::Scope timed;
  FluidPoint out;
  if (std::isfinite(depth_) && p.z() < -depth_) return out;
  if (has_waves()) {
    const FluidKinematics k = waves_.kinematics(p, t, pressure);
    if (!k.wet) return out;
    out.velocity = k.velocity;
    out.acceleration = k.acceleration;
    out.dynamic_pressure = k.dynamic_pressure;
  } else if (p.z() > 0.0) {
    return out;
  }
  out.wet = true;
  if (!current_.empty()) out.velocity += current_.velocity(std::min(p.z(), 0.0));
  return out;
}

}  // namespace seaflex::hydro
