#include "seaflex/forces/gravity.hpp"

namespace seaflex {

Gravity::Gravity(Vec3 g, std::vector<const Body*> bodies)
    : Force("gravity"), g_(std::move(g)), bodies_(std::move(bodies)) {}

void Gravity::declare_blocks(math::SparseBlockAssembler&) {}

void Gravity::assemble(const State& state, double load_factor, AssemblyTarget& target) const {
  const Vec3 g = load_factor * g_;
  for (const Body* b : bodies_) b->add_gravity(g, state, target);
}

double Gravity::potential_energy(const State& state) const {
  double V = 0.0;
  for (const Body* b : bodies_) V += b->gravity_potential(g_, state);
  return V;
}

}  // namespace seaflex
