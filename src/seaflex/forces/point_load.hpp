// A force F(t) (N) and a moment M(t) (N m), both in world axes, applied at a marker.
//   force:  Q = J_p^T F  (thesis eq. 126 for a point on an ANCF beam, Q = S(x_p)^T F)
//   moment: virtual rotation of a marker frame dtheta = 1/2 sum_k a_k x da_k, so
//           Q = 1/2 sum_k J_ak^T (M x a_k);  on a beam marker, whose slope t rotates by
//           dtheta x t, Q = J_t^T (M x t) / |t|^2 (the part of M along t, a torsion,
//           has no work on a cable element and is dropped).
// Both are follower-free (fixed world direction) but the moment's generalized force
// depends on the attitude: its tangent is included.
#pragma once

#include <memory>
#include <optional>

#include "seaflex/model/force.hpp"
#include "seaflex/model/marker.hpp"
#include "seaflex/model/time_signal.hpp"

namespace seaflex {

class PointLoad : public Force {
 public:
  /// A moment needs a marker with axes (every marker has at least its z axis).
  PointLoad(std::string name, std::unique_ptr<Marker> point, VectorSignal force,
            std::optional<VectorSignal> moment = std::nullopt);

  void declare_blocks(math::SparseBlockAssembler& matrix) override;
  void assemble(const State& state, double load_factor, AssemblyTarget& target) const override;
  double potential_energy(const State& state) const override;

 private:
  std::unique_ptr<Marker> point_;
  VectorSignal force_;
  std::optional<VectorSignal> moment_;
  std::vector<Index> dofs_;
  math::BlockId block_ = -1;
};

}  // namespace seaflex
