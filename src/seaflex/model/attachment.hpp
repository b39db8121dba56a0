// An attachment is a point on a body (a beam node, a point along a beam, later a marker
// on a rigid body or a plate node, or ground). Constraints and force elements are
// written once against attachments instead of once per pair of body kinds.
#pragma once

#include <string>
#include <vector>

#include "seaflex/model/state.hpp"

namespace seaflex {

/// Largest number of coordinates one attachment point may depend on (an ANCF plate
/// element has 48); lets force elements keep their scratch matrices on the stack.
inline constexpr int kMaxAttachmentCoordinates = 48;

class Attachment {
 public:
  virtual ~Attachment() = default;

  /// Human-readable place, e.g. "beam.n10" or "beam@4.5m".
  virtual std::string describe() const = 0;
  /// Global coordinates the point depends on (valid after numbering); may be empty (ground).
  virtual std::vector<Index> coordinates() const = 0;
  /// Position in the world frame (m).
  virtual Vec3 position(const State& state) const = 0;
  /// J = dp/dq, 3 x coordinates().size().
  virtual void jacobian(const State& state, Eigen::Ref<MatX> J) const = 0;
  /// d/dq (J^T F) for a constant world force F, coordinates() square; zero when p is
  /// linear in q.
  virtual void add_force_jacobian(const State& state, const Vec3& F,
                                  Eigen::Ref<MatX> dQdq) const = 0;
};

}  // namespace seaflex
