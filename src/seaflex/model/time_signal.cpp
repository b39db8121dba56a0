#include "seaflex/model/time_signal.hpp"

#include <algorithm>
#include <stdexcept>

namespace seaflex {

namespace {
// index i such that times[i] <= t < times[i+1], clamped to the table
std::size_t bracket(const std::vector<double>& times, double t) {
  const auto it = std::upper_bound(times.begin(), times.end(), t);
  const std::size_t hi = static_cast<std::size_t>(it - times.begin());
  return hi == 0 ? 0 : std::min(hi - 1, times.size() - 2);
}

void check_table(const std::vector<double>& times, std::size_t n_values) {
  if (times.size() < 2 || times.size() != n_values)
    throw std::invalid_argument("time table needs at least two rows");
  for (std::size_t i = 1; i < times.size(); ++i)
    if (!(times[i] > times[i - 1]))
      throw std::invalid_argument("time table: times must increase strictly");
}
}  // namespace

TimeSignal TimeSignal::constant(double value) {
  TimeSignal s;
  s.kind_ = Kind::kConstant;
  s.a_ = value;
  return s;
}

TimeSignal TimeSignal::ramp(double start, double duration) {
  if (duration < 0.0) throw std::invalid_argument("ramp duration must be >= 0");
  TimeSignal s;
  s.kind_ = Kind::kRamp;
  s.a_ = start;
  s.b_ = duration;
  return s;
}

TimeSignal TimeSignal::table(std::vector<double> times, std::vector<double> values) {
  check_table(times, values.size());
  TimeSignal s;
  s.kind_ = Kind::kTable;
  s.times_ = std::move(times);
  s.values_ = std::move(values);
  return s;
}

double TimeSignal::operator()(double t) const {
  switch (kind_) {
    case Kind::kConstant:
      return a_;
    case Kind::kRamp:
      if (t <= a_) return 0.0;
      if (t >= a_ + b_) return 1.0;
      return (t - a_) / b_;
    case Kind::kTable: {
      if (t <= times_.front()) return values_.front();
      if (t >= times_.back()) return values_.back();
      const std::size_t i = bracket(times_, t);
      const double s = (t - times_[i]) / (times_[i + 1] - times_[i]);
      return (1.0 - s) * values_[i] + s * values_[i + 1];
    }
  }
  return 0.0;
}

VectorSignal VectorSignal::table(std::vector<double> times, std::vector<Vec3> values) {
  check_table(times, values.size());
  VectorSignal s;
  s.times_ = std::move(times);
  s.values_ = std::move(values);
  return s;
}

Vec3 VectorSignal::operator()(double t) const {
  if (times_.empty()) return factor_(t) * value_;
  if (t <= times_.front()) return values_.front();
  if (t >= times_.back()) return values_.back();
  const std::size_t i = bracket(times_, t);
  const double s = (t - times_[i]) / (times_[i + 1] - times_[i]);
  return (1.0 - s) * values_[i] + s * values_[i + 1];
}

}  // namespace seaflex
