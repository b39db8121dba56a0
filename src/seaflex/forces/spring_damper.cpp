#include "seaflex/forces/spring_damper.hpp"

#include "seaflex/core/errors.hpp"
#include "seaflex/forces/line_force.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

namespace seaflex {

SpringLaw SpringLaw::linear(double stiffness) {
  SpringLaw law;
  law.k_ = stiffness;
  return law;
}

SpringLaw SpringLaw::table(std::vector<double> extensions, std::vector<double> tensions) {
  if (extensions.size() < 2 || extensions.size() != tensions.size())
    throw std::invalid_argument("SpringLaw: a table needs two or more (extension, tension) pairs");
  for (std::size_t i = 1; i < extensions.size(); ++i)
    if (!(extensions[i] > extensions[i - 1]))
      throw std::invalid_argument("SpringLaw: extensions must increase strictly");
  SpringLaw law;
  law.x_ = std::move(extensions);
  law.t_ = std::move(tensions);
  return law;
}

int SpringLaw::segment(double x) const {
  const int n = static_cast<int>(x_.size());
  int i = 0;
  while (i < n - 2 && x > x_[i + 1]) ++i;
  return i;  // the first or last segment also extends the table beyond its ends
}

double SpringLaw::tension(double x) const {
  if (x_.empty()) return k_ * x;
  const int i = segment(x);
  return t_[i] + stiffness(x) * (x - x_[i]);
}

double SpringLaw::stiffness(double x) const {
  if (x_.empty()) return k_;
  const int i = segment(x);
  return (t_[i + 1] - t_[i]) / (x_[i + 1] - x_[i]);
}

double SpringLaw::energy(double x) const {
  if (x_.empty()) return 0.5 * k_ * x * x;
  // T is linear between breakpoints (and beyond the ends): trapezoids over the
  // breakpoints between 0 and x integrate it exactly
  const double lo = std::min(0.0, x), hi = std::max(0.0, x);
  std::vector<double> pts{lo};
  for (double b : x_)
    if (b > lo && b < hi) pts.push_back(b);
  pts.push_back(hi);
  double e = 0.0;
  for (std::size_t i = 1; i < pts.size(); ++i)
    e += 0.5 * (tension(pts[i - 1]) + tension(pts[i])) * (pts[i] - pts[i - 1]);
  return x >= 0.0 ? e : -e;
}

SpringDamper::SpringDamper(std::string name, std::unique_ptr<Marker> a, std::unique_ptr<Marker> b,
                           double free_length, SpringLaw law, double damping, bool slack)
    : LineForce(std::move(name), std::move(a), std::move(b)),
      free_length_(free_length),
      law_(std::move(law)),
      damping_(damping),
      slack_(slack) {}

double SpringDamper::tension(const State& state) const {
  const LineState s = line(state);
  if (slack_ && s.length < free_length_) return 0.0;
  const double T = law_.tension(s.length - free_length_) + damping_ * s.rate;
  return slack_ ? std::max(T, 0.0) : T;
}

void SpringDamper::assemble(const State& state, double, AssemblyTarget& target) const {
  if (!has_coordinates()) return;
  const LineState s = line_for_assembly(state, "spring");
  if (slack_ && s.length < free_length_) return;
  const double T = law_.tension(s.length - free_length_) + damping_ * s.rate;
  if (slack_ && T <= 0.0) return;  // a rope cannot push, even while it shortens fast
  assemble_line(s, {T, law_.stiffness(s.length - free_length_), damping_}, state, target);
}

double SpringDamper::potential_energy(const State& state) const {
  const double x = length(state) - free_length_;
  if (slack_ && x < 0.0) return 0.0;
  return law_.energy(x);
}

void SpringDamper::add_channels(ChannelList& channels) const {
  channels.push_back(
      {fmt::format("{}.tension", name()), [this](const State& s) { return tension(s); }});
  channels.push_back(
      {fmt::format("{}.length", name()), [this](const State& s) { return length(s); }});
}

}  // namespace seaflex
