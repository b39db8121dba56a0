// Imposed motion: a pure function of time giving the six displacements of a frame and
// their first two time derivatives (DESIGN.md section 8). A prescribed rigid body, a
// moving ground marker and a moving beam support all follow a Motion through the
// rheonomic constraints of constraints/ (thesis eq. 133 with C_t and C_tt).
//
// Displacements x = (surge, sway, heave, roll, pitch, yaw): the translation (m, world
// axes) of the motion's origin o and the rotation (rad) about it in the offshore
// convention of math/rotation.hpp, R = Rz(yaw) Ry(pitch) Rx(roll). A point p0 of the
// frame at rest moves to
//   p(t) = o + x_123(t) + R(t) (p0 - o),     an axis a0 turns to a(t) = R(t) a0,
// with R' and R'' from the chain rule on the three elementary rotations (exact for large
// angles, not a small-angle linearization).
//
// A smooth ramp (quintic smoothstep s = 10 u^3 - 15 u^4 + 6 u^5, u = t / T) multiplies
// a motion so that it starts from rest with zero displacement, velocity and acceleration.
#pragma once

#include <cstdint>
#include <memory>

#include "seaflex/core/types.hpp"

namespace seaflex {

using Vec6 = Eigen::Matrix<double, 6, 1>;

/// Displacements (m, rad) and their first and second time derivatives.
struct MotionSample {
  Vec6 x = Vec6::Zero();
  Vec6 x_t = Vec6::Zero();
  Vec6 x_tt = Vec6::Zero();
};

/// Pose of the displaced frame and its time derivatives: translation p of the origin and
/// rotation R.
struct MotionPose {
  Vec3 p = Vec3::Zero(), p_t = Vec3::Zero(), p_tt = Vec3::Zero();
  Mat3 R = Mat3::Identity(), R_t = Mat3::Zero(), R_tt = Mat3::Zero();
};

/// The pose of a sample (chain rule on R = Rz(yaw) Ry(pitch) Rx(roll)).
MotionPose compute_motion_pose(const MotionSample& s);

/// A pure function of time t (s).
class Motion {
 public:
  Motion();
  Motion(const Motion&);             // a copy is another motion: its own id
  Motion& operator=(const Motion&);  // and so is an assigned one
  virtual ~Motion() = default;
  virtual MotionSample sample(double t) const = 0;
  /// compute_motion_pose(sample(t)), computed once per thread for the last few (motion, t)
  /// asked for: the markers and constraints on one vessel all ask at the same t, several
  /// times per Newton iteration (a pure function of t: the same value, bit for bit).
  MotionPose pose(double t) const;

 private:
  std::uint64_t id_;  // unique per object of the run (the cache's key; never reused)
};

/// A point p0 (at rest) of the frame displaced about origin o: value, first and second
/// time derivatives.
struct MovingVector {
  Vec3 value, rate, accel;
};
MovingVector displaced_point(const MotionPose& pose, const Vec3& origin, const Vec3& p0);
MovingVector displaced_axis(const MotionPose& pose, const Vec3& a0);

/// Motion multiplied by the quintic ramp over [0, duration] (duration > 0).
class RampedMotion : public Motion {
 public:
  RampedMotion(std::shared_ptr<const Motion> inner, double duration);
  MotionSample sample(double t) const override;

 private:
  std::shared_ptr<const Motion> inner_;
  double duration_;
};

/// x(t) = x0 + v t (m, rad; v in m/s, rad/s).
class ConstantVelocityMotion : public Motion {
 public:
  explicit ConstantVelocityMotion(const Vec6& velocity) : velocity_(velocity) {}
  MotionSample sample(double t) const override;

 private:
  Vec6 velocity_;
};

/// x_i(t) = A_i sin(2 pi t / T_i + phi_i) per degree of freedom (phi a lead, rad);
/// a degree of freedom with A_i = 0 stays at rest.
class HarmonicMotion : public Motion {
 public:
  HarmonicMotion(const Vec6& amplitude, const Vec6& period, const Vec6& phase);
  MotionSample sample(double t) const override;

 private:
  Vec6 amplitude_, omega_, phase_;
};

}  // namespace seaflex
