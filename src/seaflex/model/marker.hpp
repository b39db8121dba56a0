// A marker is a point, with axes where the body has them, fixed on a body: a rigid body
// (point and a full frame), an ANCF beam node or a point along a beam (point and one
// axis, the slope r' = dr/dx, since the cable element carries no torsion), or ground.
// Joints, springs and loads are written once against markers, not once per pair of
// body kinds (thesis eq. 138-171 are all instances of the rows in constraints/joint.hpp).
//
// Each marker vector x(q) (the point or an axis) reports its value, J = dx/dq, the rate
// x' = J v, the acceleration bias J' v (so x'' = J q'' + J' v, thesis eq. 133), the rate
// Jacobian d(J v)/dq and the contraction d(J^T F)/dq used by Newton tangents.
#pragma once

#include <string>
#include <vector>

#include "seaflex/model/state.hpp"

namespace seaflex {

class Body;

/// Largest number of coordinates one marker may depend on (an ANCF plate element has
/// 48); lets joints and force elements keep their scratch matrices on the stack.
inline constexpr int kMaxMarkerCoordinates = 48;

using MarkerJacobian =
    Eigen::Matrix<double, 3, Eigen::Dynamic, Eigen::ColMajor, 3, kMaxMarkerCoordinates>;
using MarkerSquare = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::ColMajor,
                                   kMaxMarkerCoordinates, kMaxMarkerCoordinates>;

enum class MarkerVector : int { kPoint = 0, kAxisX = 1, kAxisY = 2, kAxisZ = 3 };

struct MarkerVectorEval {
  Vec3 value = Vec3::Zero();
  Vec3 rate = Vec3::Zero();  ///< dx/dt = J v + x_t
  Vec3 bias = Vec3::Zero();  ///< J' v (+ x_tt for a moving marker): x'' = J q'' + bias
  Vec3 dt = Vec3::Zero();    ///< x_t, the explicit time derivative (moving markers only)
  MarkerJacobian J;          ///< dx/dq, 3 x coordinates().size()
  MarkerJacobian Jv;         ///< d(J v)/dq
};

class Marker {
 public:
  virtual ~Marker() = default;

  /// Human-readable place, e.g. "riser.n10", "riser@4.5m", "rig@(0, 0, -10)", "ground".
  virtual std::string describe() const = 0;
  /// The body the marker is fixed on; nullptr for ground.
  virtual const Body* body() const = 0;
  /// Global coordinates the marker depends on (valid after numbering); empty for ground.
  virtual std::vector<Index> coordinates() const = 0;
  /// Whether the marker has this vector (every marker has its point).
  virtual bool has(MarkerVector which) const = 0;
  /// Fills out for the vector; J and Jv are resized to 3 x coordinates().size().
  virtual void evaluate(MarkerVector which, const State& state, MarkerVectorEval& out) const = 0;
  /// H += d(J^T F)/dq for a constant F (coordinates() square); zero when x is linear in q.
  virtual void add_hessian(MarkerVector which, const State& state, const Vec3& F,
                           Eigen::Ref<MatX> H) const = 0;

  /// True when every vector of the marker is linear in q (beam, ground).
  virtual bool linear() const = 0;
  /// True when the marker's vectors depend on time explicitly (a moving ground marker).
  virtual bool moving() const { return false; }

  Vec3 position(const State& state) const;
};

/// A fixed point and frame in the world: no coordinates.
class GroundMarker : public Marker {
 public:
  explicit GroundMarker(const Vec3& position, const Mat3& frame = Mat3::Identity());
  std::string describe() const override;
  const Body* body() const override { return nullptr; }
  std::vector<Index> coordinates() const override { return {}; }
  bool has(MarkerVector) const override { return true; }
  void evaluate(MarkerVector which, const State& state, MarkerVectorEval& out) const override;
  void add_hessian(MarkerVector, const State&, const Vec3&, Eigen::Ref<MatX>) const override {}
  bool linear() const override { return true; }

 private:
  Vec3 position_;
  Mat3 frame_;
};

}  // namespace seaflex
