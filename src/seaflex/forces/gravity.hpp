// Gravity on every body of the system: a uniform acceleration field g (m/s^2).
// Each body turns it into generalized forces (for ANCF beams thesis eq. 175).
#pragma once

#include <memory>
#include <vector>

#include "seaflex/model/body.hpp"
#include "seaflex/model/force.hpp"

namespace seaflex {

class Gravity : public Force {
 public:
  Gravity(Vec3 g, std::vector<const Body*> bodies);

  void declare_blocks(math::SparseBlockAssembler& matrix) override;
  void assemble(const State& state, double load_factor, AssemblyTarget& target) const override;
  double potential_energy(const State& state) const override;
  const Vec3& acceleration() const { return g_; }

 private:
  Vec3 g_;
  std::vector<const Body*> bodies_;
};

}  // namespace seaflex
