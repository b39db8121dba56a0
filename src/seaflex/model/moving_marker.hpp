// A marker on ground that follows an imposed Motion (model/motion.hpp): its point and
// frame at rest (p0, R0) are displaced about the motion's origin o,
//   p(t) = o + x(t) + R(t) (p0 - o),   axes R(t) R0.
// It has no coordinates; its rate is the explicit time derivative x_t and its bias the
// second derivative x_tt, so every joint and force written against markers (thesis
// eq. 133: C_t and C_tt enter C' and gamma) takes a moving support without change.
#pragma once

#include <memory>
#include <string>

#include "seaflex/model/marker.hpp"
#include "seaflex/model/motion.hpp"

namespace seaflex {

class MovingMarker : public Marker {
 public:
  MovingMarker(std::shared_ptr<const Motion> motion, const Vec3& origin, const Vec3& position,
               const Mat3& frame = Mat3::Identity());
  std::string describe() const override;
  const Body* body() const override { return nullptr; }
  std::vector<Index> coordinates() const override { return {}; }
  bool has(MarkerVector) const override { return true; }
  void evaluate(MarkerVector which, const State& state, MarkerVectorEval& out) const override;
  void add_hessian(MarkerVector, const State&, const Vec3&, Eigen::Ref<MatX>) const override {}
  bool linear() const override { return true; }
  bool moving() const override { return true; }

 private:
  std::shared_ptr<const Motion> motion_;
  Vec3 origin_, position_;
  Mat3 frame_;
};

}  // namespace seaflex
