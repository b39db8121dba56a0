// A load per unit reference length f(t) (N/m) in a fixed world direction on a range of
// elements of an ANCF beam: Q_e = (int_0^l S dx)^T f, thesis eq. (127).
#pragma once

#include "seaflex/elements/ancf_beam.hpp"
#include "seaflex/model/force.hpp"
#include "seaflex/model/time_signal.hpp"

namespace seaflex {

class DistributedLoad : public Force {
 public:
  /// Elements first..last (inclusive) of beam carry the load.
  DistributedLoad(std::string name, const AncfBeam& beam, int first, int last, VectorSignal load);

  void declare_blocks(math::SparseBlockAssembler& matrix) override;
  void assemble(const State& state, double load_factor, AssemblyTarget& target) const override;
  double potential_energy(const State& state) const override;

 private:
  const AncfBeam& beam_;
  int first_, last_;
  VectorSignal load_;
};

}  // namespace seaflex
