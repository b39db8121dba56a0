#include "seaflex/forces/distributed_load.hpp"

#include <stdexcept>

namespace seaflex {

DistributedLoad::DistributedLoad(std::string name, const AncfBeam& beam, int first, int last,
                                 VectorSignal load)
    : Force(std::move(name)), beam_(beam), first_(first), last_(last), load_(std::move(load)) {
  if (first < 0 || last >= beam.num_elements() || first > last)
    throw std::out_of_range("DistributedLoad: element range outside the beam");
}

void DistributedLoad::declare_blocks(math::SparseBlockAssembler&) {}

void DistributedLoad::assemble(const State& state, double load_factor,
                               AssemblyTarget& target) const {
  if (!target.forces) return;
  const Vec3 f = load_factor * load_(state.t);
  for (int el = first_; el <= last_; ++el)
    target.forces->segment<12>(beam_.node_index(el)) +=
        ancf_cable::uniform_load(f, beam_.element_length(el));  // thesis eq. (127)
}

double DistributedLoad::potential_energy(const State&) const {
  return 0.0;
}

}  // namespace seaflex
