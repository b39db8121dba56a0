// A force F(t) (N) in the world frame applied at an attachment point: Q = J^T F
// (thesis eq. 126 for a point on an ANCF beam, Q = S(x_p)^T F).
#pragma once

#include <memory>

#include "seaflex/model/attachment.hpp"
#include "seaflex/model/force.hpp"
#include "seaflex/model/time_signal.hpp"

namespace seaflex {

class PointLoad : public Force {
 public:
  PointLoad(std::string name, std::unique_ptr<Attachment> point, VectorSignal force);

  void declare_blocks(math::SparseBlockAssembler& matrix) override;
  void assemble(const State& state, double load_factor, AssemblyTarget& target) const override;
  double potential_energy(const State& state) const override;

 private:
  std::unique_ptr<Attachment> point_;
  VectorSignal force_;
  std::vector<Index> dofs_;
  math::BlockId block_ = -1;
};

}  // namespace seaflex
