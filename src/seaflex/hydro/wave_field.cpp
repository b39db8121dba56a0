#include "seaflex/hydro/wave_field.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "seaflex/hydro/wave_grid.hpp"

namespace seaflex::hydro {

WaveField::WaveField(double depth, double g, double rho, std::vector<WaveComponent> components,
                     Ramp ramp, bool wheeler_stretching)
    : depth_(depth),
      g_(g),
      rho_(rho),
      components_(std::move(components)),
      ramp_(ramp),
      wheeler_(wheeler_stretching),
      deep_(std::isinf(depth)) {
  if (!(depth > 0.0))
    throw std::invalid_argument(fmt::format("WaveField: depth must be > 0, got {}", depth));
  if (!(g > 0.0) || !std::isfinite(g))
    throw std::invalid_argument(fmt::format("WaveField: g must be > 0, got {}", g));
  if (!(rho > 0.0) || !std::isfinite(rho))
    throw std::invalid_argument(fmt::format("WaveField: rho must be > 0, got {}", rho));
  cos_dir_.reserve(components_.size());
  sin_dir_.reserve(components_.size());
  for (const auto& c : components_) {
    cos_dir_.push_back(std::cos(c.direction));
    sin_dir_.push_back(std::sin(c.direction));
    amplitude_sum_ += std::abs(c.amplitude);
  }
}

double WaveField::elevation(double x, double y, double t) const {
  if (grid_) return grid_->elevation(x, y, t);
  const double ramp = ramp_.factor(t);
  if (ramp == 0.0) return 0.0;
  double eta = 0.0;
  for (std::size_t i = 0; i < components_.size(); ++i) {
    const auto& c = components_[i];
    const double theta = c.omega * t - c.k * (x * cos_dir_[i] + y * sin_dir_[i]) + c.phase;
    eta += c.amplitude * std::cos(theta);
  }
  return ramp * eta;
}

FluidKinematics WaveField::airy(double x, double y, double z, double t) const {
  FluidKinematics out;
  double pressure_over_rho_g = 0.0;
  for (std::size_t i = 0; i < components_.size(); ++i) {
    const auto& c = components_[i];
    if (c.amplitude == 0.0 || c.omega == 0.0) continue;
    const double theta = c.omega * t - c.k * (x * cos_dir_[i] + y * sin_dir_[i]) + c.phase;
    const double ct = std::cos(theta);
    const double st = std::sin(theta);
    // depth factors: horizontal cosh(k(z+d))/sinh(kd), vertical sinh(k(z+d))/sinh(kd),
    // pressure cosh(k(z+d))/cosh(kd); all e^{kz} in deep water
    double f_h, f_v, f_p;
    const double ekz = std::exp(c.k * z);
    if (deep_) {
      f_h = f_v = f_p = ekz;
    } else {
      const double e_image = std::exp(-c.k * (z + 2.0 * depth_));  // e^{-k(z+2d)} <= e^{-kd}
      const double e2 = std::exp(-2.0 * c.k * depth_);
      const double one_minus =
          -std::expm1(-2.0 * c.k * depth_);  // 1 - e^{-2kd}, accurate for small kd
      f_h = (ekz + e_image) / one_minus;
      f_v = (ekz - e_image) / one_minus;
      f_p = (ekz + e_image) / (1.0 + e2);
    }
    const double aw = c.amplitude * c.omega;
    const double aww = aw * c.omega;
    const double uh = aw * f_h * ct;
    const double duh = -aww * f_h * st;
    out.velocity.x() += uh * cos_dir_[i];
    out.velocity.y() += uh * sin_dir_[i];
    out.velocity.z() += -aw * f_v * st;
    out.acceleration.x() += duh * cos_dir_[i];
    out.acceleration.y() += duh * sin_dir_[i];
    out.acceleration.z() += -aww * f_v * ct;
    pressure_over_rho_g += c.amplitude * f_p * ct;
  }
  out.dynamic_pressure = rho_ * g_ * pressure_over_rho_g;
  return out;
}

FluidKinematics WaveField::kinematics(const Vec3& p, double t, bool pressure) const {
  if (grid_) return grid_->kinematics(p, t, pressure);
  const double ramp = ramp_.factor(t);
  if (ramp == 0.0) {
    FluidKinematics calm;
    calm.wet = p.z() <= 0.0;
    return calm;
  }
  const double eta = elevation(p.x(), p.y(), t);  // ramp included
  if (p.z() > eta) return FluidKinematics{};
  double z = p.z();
  if (!deep_ && z < -depth_) z = -depth_;
  double z_eval;
  if (wheeler_) {
    // Wheeler (1970): map [-d, eta] onto [-d, 0]
    z_eval = deep_ ? z - eta : depth_ * (z - eta) / (depth_ + eta);
  } else {
    z_eval = std::min(z, 0.0);
  }
  FluidKinematics out = airy(p.x(), p.y(), z_eval, t);
  out.velocity *= ramp;
  out.acceleration *= ramp;
  out.dynamic_pressure *= ramp;
  out.wet = true;
  return out;
}

}  // namespace seaflex::hydro
