#include "seaflex/forces/radiation_force.hpp"

#include <fmt/format.h>

namespace seaflex {

RadiationForce::RadiationForce(std::string name, const RigidBody& body, const Vec3& reference,
                               hydro::ConvolutionRadiation convolution)
    : RigidBodyLoad(std::move(name), body),
      reference_(reference),
      convolution_(std::move(convolution)) {}

RadiationForce::RadiationForce(std::string name, const RigidBody& body, const Vec3& reference,
                               hydro::StateSpaceRadiation state_space)
    : RigidBodyLoad(std::move(name), body),
      reference_(reference),
      state_space_(std::move(state_space)) {}

void RadiationForce::start(const State& state) {
  const Vec6 v = body_velocity_at(motion(state), reference_);
  if (convolution_) convolution_->reset(state.t, v);
  if (state_space_) state_space_->reset(state.t, v);
  started_ = true;
}

void RadiationForce::accept_step(const State& state) {
  if (!started_) start(state);
  const Vec6 v = body_velocity_at(motion(state), reference_);
  if (convolution_) convolution_->accept(state.t, v);
  if (state_space_) state_space_->accept(state.t, v);
}

Vec6 RadiationForce::force_at(const RigidBodyMotion& m) const {
  if (!started_) return Vec6::Zero();  // statics, or before a simulation: no history
  const Vec6 v = body_velocity_at(m, reference_);
  return convolution_ ? convolution_->force(m.t, v) : state_space_->force(m.t, v);
}

Vec6 RadiationForce::memory_force(const State& state) const {
  return force_at(motion(state));
}

Wrench RadiationForce::wrench(const RigidBodyMotion& m) const {
  Wrench W;
  add_body_wrench(W, m, reference_, force_at(m));
  return W;
}

void RadiationForce::add_channels(ChannelList& channels) const {
  static constexpr const char* kMode[6] = {"fx", "fy", "fz", "mx", "my", "mz"};
  for (int i = 0; i < 6; ++i)
    channels.push_back({fmt::format("{}.{}", name(), kMode[i]),
                        [this, i](const State& s) { return memory_force(s)[i]; }});
}

}  // namespace seaflex
