#include "seaflex/model/moving_marker.hpp"

#include <fmt/format.h>

namespace seaflex {

MovingMarker::MovingMarker(std::shared_ptr<const Motion> motion, const Vec3& origin,
                           const Vec3& position, const Mat3& frame)
    : motion_(std::move(motion)), origin_(origin), position_(position), frame_(frame) {}

std::string MovingMarker::describe() const {
  return fmt::format("moving ground@({:g}, {:g}, {:g})", position_.x(), position_.y(),
                     position_.z());
}

void MovingMarker::evaluate(MarkerVector which, const State& state, MarkerVectorEval& out) const {
  const MotionPose pose = motion_->pose(state.t);
  const int k = static_cast<int>(which);
  const MovingVector m = k == 0 ? displaced_point(pose, origin_, position_)
                                : displaced_axis(pose, Vec3(frame_.col(k - 1)));
  out.value = m.value;
  out.rate = m.rate;
  out.dt = m.rate;
  out.bias = m.accel;
  out.J.resize(3, 0);
  out.Jv.resize(3, 0);
}

}  // namespace seaflex
