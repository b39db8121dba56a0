#include "seaflex/forces/constant_tensioner.hpp"

#include <fmt/format.h>

namespace seaflex {

double TensionerLaw::restoring(double s) const {
  double T = tension + stiffness * s;
  if (s > stroke_max) T += stop_stiffness * (s - stroke_max);
  if (s < stroke_min) T -= stop_stiffness * (stroke_min - s);
  return T;
}

double TensionerLaw::slope(double s) const {
  return stiffness + (s > stroke_max || s < stroke_min ? stop_stiffness : 0.0);
}

double TensionerLaw::energy(double s) const {
  double V = tension * s + 0.5 * stiffness * s * s;
  if (s > stroke_max) V += 0.5 * stop_stiffness * (s - stroke_max) * (s - stroke_max);
  if (s < stroke_min) V += 0.5 * stop_stiffness * (stroke_min - s) * (stroke_min - s);
  return V;
}

ConstantTensioner::ConstantTensioner(std::string name, std::unique_ptr<Marker> from,
                                     std::unique_ptr<Marker> to, TensionerLaw law)
    : LineForce(std::move(name), std::move(from), std::move(to)), law_(law) {}

double ConstantTensioner::stroke(const State& state) const {
  return length(state) - reference_length_;
}

double ConstantTensioner::tension(const State& state) const {
  const LineState s = line(state);
  return law_.restoring(s.length - reference_length_) + law_.damping * s.rate;
}

void ConstantTensioner::assemble(const State& state, double, AssemblyTarget& target) const {
  if (!has_coordinates()) return;
  const LineState s = line_for_assembly(state, "tensioner");
  const double stroke = s.length - reference_length_;
  const double T = law_.restoring(stroke) + law_.damping * s.rate;
  assemble_line(s, {T, law_.slope(stroke), law_.damping}, state, target);
}

double ConstantTensioner::potential_energy(const State& state) const {
  return law_.energy(stroke(state));
}

void ConstantTensioner::add_channels(ChannelList& channels) const {
  channels.push_back(
      {fmt::format("{}.tension", name()), [this](const State& s) { return tension(s); }});
  channels.push_back(
      {fmt::format("{}.stroke", name()), [this](const State& s) { return stroke(s); }});
  channels.push_back(
      {fmt::format("{}.length", name()), [this](const State& s) { return length(s); }});
}

}  // namespace seaflex
