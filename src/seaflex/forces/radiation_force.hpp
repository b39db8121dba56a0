// The memory part of the radiation force of the Cummins equation (thesis eq. 173):
//   f(t) = - int_0^t K(t - s) v(s) ds,   K(t) = 2/pi int_0^inf B(w) cos(w t) dw,
// with v the six body-axis velocities of the reference point u (the BEM origin). The
// infinite-frequency added mass is HydroMatrices' job. Evaluated either by direct
// convolution over a finite memory or by a state-space model fitted once to K
// (hydro/radiation_memory.hpp). The memory advances only when a time step is accepted
// (Force::accept_step), so RK4 stages and Newton iterations are safe.
#pragma once

#include <memory>
#include <optional>

#include "seaflex/forces/rigid_body_load.hpp"
#include "seaflex/hydro/radiation_memory.hpp"

namespace seaflex {

class RadiationForce : public RigidBodyLoad {
 public:
  RadiationForce(std::string name, const RigidBody& body, const Vec3& reference,
                 hydro::ConvolutionRadiation convolution);
  RadiationForce(std::string name, const RigidBody& body, const Vec3& reference,
                 hydro::StateSpaceRadiation state_space);

  void start(const State& state) override;
  void accept_step(const State& state) override;
  bool has_memory() const override { return true; }
  /// The memory force (body axes, about u) in the state.
  Vec6 memory_force(const State& state) const;
  void add_channels(ChannelList& channels) const override;

 protected:
  Wrench wrench(const RigidBodyMotion& m) const override;

 private:
  Vec6 force_at(const RigidBodyMotion& m) const;
  Vec3 reference_;
  std::optional<hydro::ConvolutionRadiation> convolution_;
  std::optional<hydro::StateSpaceRadiation> state_space_;
  bool started_ = false;
};

}  // namespace seaflex
