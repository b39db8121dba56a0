// First-order wave excitation of a floating rigid body from force RAOs (thesis eq. 173,
// F_exciting): for every wave component c (amplitude a_c, frequency w_c, direction b_c,
// phase phi_c) the RAO X(w_c, b_c - heading) of the BEM database (WAMIT convention,
// F = Re{X A e^{i w t}}, per unit amplitude of the wave at the body origin) gives
//   f(t) = ramp(t) sum_c Re{ X a_c e^{i (w_c t - k_c (x0 cos b_c + y0 sin b_c) + phi_c)} },
// a force and moment in body axes about the reference point u (the BEM origin), where
// (x0, y0) is the reference point's horizontal position at rest (linear theory: the
// phase is taken at the mean position) and the heading is the body's current yaw.
#pragma once

#include <memory>

#include "seaflex/forces/rigid_body_load.hpp"
#include "seaflex/hydro/hydro_database.hpp"
#include "seaflex/hydro/ocean.hpp"

namespace seaflex {

class RaoExcitation : public RigidBodyLoad {
 public:
  /// reference: u, body axes from the CG (m); rest_position: world (x0, y0) of u at rest.
  RaoExcitation(std::string name, const RigidBody& body,
                std::shared_ptr<const hydro::HydroDatabase> database,
                std::shared_ptr<const hydro::Ocean> ocean, const Vec3& reference,
                const Vec3& rest_position);

  /// The excitation (body axes, about u) at time t for a body at the given heading (rad).
  Vec6 excitation(double t, double heading) const;
  void add_channels(ChannelList& channels) const override;

 protected:
  Wrench wrench(const RigidBodyMotion& m) const override;
  bool velocity_dependent() const override { return false; }

 private:
  std::shared_ptr<const hydro::HydroDatabase> db_;
  std::shared_ptr<const hydro::Ocean> ocean_;
  Vec3 reference_;
  Vec3 rest_;
};

}  // namespace seaflex
