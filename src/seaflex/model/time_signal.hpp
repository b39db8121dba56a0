// Time histories of loads: constant, linear ramp, or a table interpolated linearly
// (held at its end values outside the table).
#pragma once

#include <vector>

#include "seaflex/core/types.hpp"

namespace seaflex {

/// A scalar function of time.
class TimeSignal {
 public:
  /// Always value.
  static TimeSignal constant(double value);
  /// 0 before start, rising linearly to 1 at start + duration, 1 after. duration >= 0.
  static TimeSignal ramp(double start, double duration);
  /// Piecewise-linear through (times[i], values[i]); times strictly increasing.
  static TimeSignal table(std::vector<double> times, std::vector<double> values);

  double operator()(double t) const;

 private:
  enum class Kind { kConstant, kRamp, kTable };
  Kind kind_ = Kind::kConstant;
  double a_ = 1.0, b_ = 0.0;  // constant: a_; ramp: start a_, duration b_
  std::vector<double> times_, values_;
};

/// A vector (force, load per length) as a function of time: a constant vector times a
/// scalar signal, or a table of vectors interpolated linearly.
class VectorSignal {
 public:
  VectorSignal() = default;
  VectorSignal(const Vec3& value, TimeSignal factor) : value_(value), factor_(std::move(factor)) {}
  /// Piecewise-linear table; times strictly increasing.
  static VectorSignal table(std::vector<double> times, std::vector<Vec3> values);

  Vec3 operator()(double t) const;

 private:
  Vec3 value_ = Vec3::Zero();
  TimeSignal factor_ = TimeSignal::constant(1.0);
  std::vector<double> times_;
  std::vector<Vec3> values_;
};

}  // namespace seaflex
