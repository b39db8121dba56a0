#include "seaflex/forces/rao_excitation.hpp"

#include <fmt/format.h>

#include <cmath>
#include <complex>

#include "seaflex/math/rotation.hpp"

namespace seaflex {

RaoExcitation::RaoExcitation(std::string name, const RigidBody& body,
                             std::shared_ptr<const hydro::HydroDatabase> database,
                             std::shared_ptr<const hydro::Ocean> ocean, const Vec3& reference,
                             const Vec3& rest_position)
    : RigidBodyLoad(std::move(name), body),
      db_(std::move(database)),
      ocean_(std::move(ocean)),
      reference_(reference),
      rest_(rest_position) {}

Vec6 RaoExcitation::excitation(double t, double heading) const {
  Vec6 f = Vec6::Zero();
  const double ramp = ocean_->waves().ramp_factor(t);
  if (ramp == 0.0) return f;
  for (const hydro::WaveComponent& c : ocean_->waves().components()) {
    const hydro::Vec6c X = db_->excitation_at(c.omega, c.direction - heading);
    const double arg =
        c.omega * t -
        c.k * (rest_.x() * std::cos(c.direction) + rest_.y() * std::sin(c.direction)) + c.phase;
    const std::complex<double> e = c.amplitude * std::polar(1.0, arg);
    for (int i = 0; i < 6; ++i) f[i] += (X[i] * e).real();  // WAMIT: F = Re{X A e^{iwt}}
  }
  return ramp * f;
}

Wrench RaoExcitation::wrench(const RigidBodyMotion& m) const {
  Wrench W;
  const double heading = math::roll_pitch_yaw_from_rotation(m.R)[2];
  add_body_wrench(W, m, reference_, excitation(m.t, heading));
  return W;
}

void RaoExcitation::add_channels(ChannelList& channels) const {
  static constexpr const char* kMode[6] = {"fx", "fy", "fz", "mx", "my", "mz"};
  for (int i = 0; i < 6; ++i)
    channels.push_back({fmt::format("{}.{}", name(), kMode[i]), [this, i](const State& s) {
                          const RigidBodyMotion m = motion(s);
                          const double heading = math::roll_pitch_yaw_from_rotation(m.R)[2];
                          return excitation(s.t, heading)[i];
                        }});
}

}  // namespace seaflex
