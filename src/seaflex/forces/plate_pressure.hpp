// A uniform pressure p(t) (Pa) on an ANCF plate, per unit reference area, thesis eq. (126):
//   fixed direction d (unit vector): Q_e = p (int S dP)^T d    (eq. 128; constant in q)
//   following the normal:            Q_e = p int S^T (r_p1 x r_p2) dP
// The follower form acts along the deformed normal on the deformed area: |r_p1 x r_p2| dP
// is the deformed area element, so the force per deformed area is p. It is quadratic in
// e, integrated exactly by 5 x 5 Gauss points (degree 8 per direction), and its tangent is
// included (not symmetric in general: a follower load).
#pragma once

#include <optional>

#include "seaflex/elements/ancf_plate.hpp"
#include "seaflex/model/force.hpp"
#include "seaflex/model/time_signal.hpp"

namespace seaflex {

class PlatePressure : public Force {
 public:
  /// p(t) = pressure (Pa) times factor(t); direction: a fixed world direction (normalized
  /// here), or nullopt for the deformed normal r_p1 x r_p2 (t1 x t2 in the reference plate).
  PlatePressure(std::string name, const AncfPlate& plate, double pressure, TimeSignal factor,
                std::optional<Vec3> direction);

  void declare_blocks(math::SparseBlockAssembler& matrix) override;
  void assemble(const State& state, double load_factor, AssemblyTarget& target) const override;
  double potential_energy(const State& state) const override;

  /// Element generalized force of the follower pressure p and its derivative dQ/de.
  static ancf_plate::Vec48 follower_force(const ancf_plate::Vec48& e, double p, double a, double b,
                                          ancf_plate::Mat48* dQ);

 private:
  const AncfPlate& plate_;
  double pressure_;
  TimeSignal factor_;
  std::optional<Vec3> direction_;
  std::vector<math::BlockId> blocks_;
};

}  // namespace seaflex
