#include "seaflex/model/marker.hpp"

#include <fmt/format.h>

namespace seaflex {

Vec3 Marker::position(const State& state) const {
  MarkerVectorEval e;
  evaluate(MarkerVector::kPoint, state, e);
  return e.value;
}

GroundMarker::GroundMarker(const Vec3& position, const Mat3& frame)
    : position_(position), frame_(frame) {}

std::string GroundMarker::describe() const {
  return fmt::format("ground@({:g}, {:g}, {:g})", position_.x(), position_.y(), position_.z());
}

void GroundMarker::evaluate(MarkerVector which, const State&, MarkerVectorEval& out) const {
  const int k = static_cast<int>(which);
  out.value = k == 0 ? position_ : Vec3(frame_.col(k - 1));
  out.rate.setZero();
  out.bias.setZero();
  out.dt.setZero();
  out.J.resize(3, 0);
  out.Jv.resize(3, 0);
}

}  // namespace seaflex
