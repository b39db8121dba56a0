#include "seaflex/model/motion.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace seaflex {

namespace {
// an elementary rotation about axis k by alpha(t) and its time derivatives:
// R = I + sin(a) K + (1 - cos(a)) K^2 (Rodrigues), dR/da = cos(a) K + sin(a) K^2,
// d2R/da2 = -sin(a) K + cos(a) K^2
struct Factor {
  Mat3 F, F_t, F_tt;
};
Factor elementary(int k, double a, double a_t, double a_tt) {
  Mat3 K = Mat3::Zero();
  const int i = (k + 1) % 3, j = (k + 2) % 3;
  K(j, i) = 1.0;
  K(i, j) = -1.0;
  const Mat3 K2 = K * K;
  const double s = std::sin(a), c = std::cos(a);
  const Mat3 d1 = c * K + s * K2;
  const Mat3 d2 = -s * K + c * K2;
  return {Mat3::Identity() + s * K + (1.0 - c) * K2, d1 * a_t, d2 * (a_t * a_t) + d1 * a_tt};
}
}  // namespace

MotionPose compute_motion_pose(const MotionSample& s) {
  MotionPose pose;
  pose.p = s.x.head<3>();
  pose.p_t = s.x_t.head<3>();
  pose.p_tt = s.x_tt.head<3>();
  // R = A B C = Rz(yaw) Ry(pitch) Rx(roll) (math/rotation.hpp)
  const Factor A = elementary(2, s.x[5], s.x_t[5], s.x_tt[5]);
  const Factor B = elementary(1, s.x[4], s.x_t[4], s.x_tt[4]);
  const Factor C = elementary(0, s.x[3], s.x_t[3], s.x_tt[3]);
  pose.R = A.F * B.F * C.F;
  pose.R_t = A.F_t * B.F * C.F + A.F * B.F_t * C.F + A.F * B.F * C.F_t;
  pose.R_tt = A.F_tt * B.F * C.F + A.F * B.F_tt * C.F + A.F * B.F * C.F_tt +
              2.0 * (A.F_t * B.F_t * C.F + A.F_t * B.F * C.F_t + A.F * B.F_t * C.F_t);
  return pose;
}

namespace {
std::uint64_t next_motion_id() {
  static std::atomic<std::uint64_t> next{1};
  return next.fetch_add(1, std::memory_order_relaxed);
}
}  // namespace

Motion::Motion() : id_(next_motion_id()) {}
Motion::Motion(const Motion&) : id_(next_motion_id()) {}
Motion& Motion::operator=(const Motion&) {
  id_ = next_motion_id();  // other values: no longer the motion the cache knew
  return *this;
}

MotionPose Motion::pose(double t) const {
  // a few entries per thread, replaced in turn (ids start at 1: an empty entry never matches)
  struct Entry {
    std::uint64_t id = 0;
    double t = 0.0;
    MotionPose pose;
  };
  thread_local std::array<Entry, 4> cache;
  thread_local std::size_t next = 0;
  for (const Entry& e : cache)
    if (e.id == id_ && e.t == t) return e.pose;
  Entry& e = cache[next];
  next = (next + 1) % cache.size();
  e.pose = compute_motion_pose(sample(t));
  e.id = id_;
  e.t = t;
  return e.pose;
}

MovingVector displaced_point(const MotionPose& pose, const Vec3& origin, const Vec3& p0) {
  const Vec3 r = p0 - origin;
  return {origin + pose.p + pose.R * r, pose.p_t + pose.R_t * r, pose.p_tt + pose.R_tt * r};
}

MovingVector displaced_axis(const MotionPose& pose, const Vec3& a0) {
  return {pose.R * a0, pose.R_t * a0, pose.R_tt * a0};
}

RampedMotion::RampedMotion(std::shared_ptr<const Motion> inner, double duration)
    : inner_(std::move(inner)), duration_(duration) {
  if (!(duration > 0.0)) throw std::invalid_argument("RampedMotion: duration must be positive");
}

MotionSample RampedMotion::sample(double t) const {
  MotionSample m = inner_->sample(t);
  if (t >= duration_) return m;
  // quintic smoothstep: s(0) = s'(0) = s''(0) = 0, s(1) = 1, s'(1) = s''(1) = 0
  const double u = std::max(t, 0.0) / duration_;
  const double s = u * u * u * (10.0 - 15.0 * u + 6.0 * u * u);
  const double s_t = 30.0 * u * u * (1.0 - u) * (1.0 - u) / duration_;
  const double s_tt = 60.0 * u * (1.0 - u) * (1.0 - 2.0 * u) / (duration_ * duration_);
  MotionSample out;
  out.x = s * m.x;
  out.x_t = s_t * m.x + s * m.x_t;
  out.x_tt = s_tt * m.x + 2.0 * s_t * m.x_t + s * m.x_tt;
  return out;
}

MotionSample ConstantVelocityMotion::sample(double t) const {
  MotionSample m;
  m.x = velocity_ * t;
  m.x_t = velocity_;
  return m;
}

HarmonicMotion::HarmonicMotion(const Vec6& amplitude, const Vec6& period, const Vec6& phase)
    : amplitude_(amplitude), phase_(phase) {
  for (int i = 0; i < 6; ++i) {
    if (amplitude[i] != 0.0 && !(period[i] > 0.0))
      throw std::invalid_argument("HarmonicMotion: periods must be positive");
    omega_[i] = amplitude[i] != 0.0 ? 2.0 * std::numbers::pi / period[i] : 0.0;
  }
}

MotionSample HarmonicMotion::sample(double t) const {
  MotionSample m;
  for (int i = 0; i < 6; ++i) {
    if (amplitude_[i] == 0.0) continue;
    const double w = omega_[i], th = w * t + phase_[i];
    m.x[i] = amplitude_[i] * std::sin(th);
    m.x_t[i] = amplitude_[i] * w * std::cos(th);
    m.x_tt[i] = -amplitude_[i] * w * w * std::sin(th);
  }
  return m;
}

}  // namespace seaflex
