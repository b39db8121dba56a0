// A constant-tension tensioner with stroke limits between the points of two markers:
// `from` (on the vessel: the tensioner's sheave or cylinder attachment) and `to` (the
// tension ring or riser top). The simple tensioner of storm analysis (the OrcaFlex and
// Flexcom "constant tension winch/tensioner" idealization); the detailed gas spring with
// Stribeck friction of thesis 3.3.2 is pneumatic_cylinder.
//
// With L = |p_to - p_from|, L' = n . (p_to - p_from)', n the unit vector from `from` to
// `to`, the stroke s = L - L_ref (L_ref: the distance at the start, or given) and the
// stroke limits s_min < 0 < s_max, the tension pulling the points together is
//   T = T0 + k s + c L' + k_stop (s - s_max) [s > s_max] - k_stop (s_min - s) [s < s_min]
// (force T n on `from`, -T n on `to`). k = 0 is a constant tension T0; the stops are stiff
// linear springs (k_stop) beyond the ends of the stroke. T is piecewise linear in s with
// kinks at s_min and s_max: dT/ds jumps from k to k + k_stop there (the tangent is the
// one-sided slope of the side s is on; at exactly s = s_max or s_min the inner one).
// Beyond the lower stop the tension can turn negative (the stop pushes, as a collapsed
// cylinder does). The restoring part is conservative, with potential
//   V(s) = T0 s + k s^2 / 2 + k_stop (s - s_max)^2 / 2 [s > s_max]
//          + k_stop (s_min - s)^2 / 2 [s < s_min],
// so statics finds its equilibrium; the damping c L' acts only in dynamics. Exact tangents
// dT/dL = k (+ k_stop beyond a stop) and dT/dL' = c through LineForce.
#pragma once

#include <limits>
#include <memory>
#include <string>

#include "seaflex/forces/line_force.hpp"

namespace seaflex {

/// The tension law of the tensioner against its stroke s (m) and rate L' (m/s).
struct TensionerLaw {
  double tension = 0.0;    ///< T0 (N), > 0
  double stiffness = 0.0;  ///< k (N/m), >= 0
  double damping = 0.0;    ///< c (N s/m), >= 0
  /// s_min < 0 (m); -infinity: no lower stop
  double stroke_min = -std::numeric_limits<double>::infinity();
  /// s_max > 0 (m); +infinity: no upper stop
  double stroke_max = std::numeric_limits<double>::infinity();
  double stop_stiffness = 0.0;  ///< k_stop (N/m), > 0 when a stop is finite

  /// The restoring tension T0 + k s + the stop terms (N), without damping.
  double restoring(double stroke) const;
  /// dT/ds (N/m): k, plus k_stop strictly beyond a stop.
  double slope(double stroke) const;
  /// V(s) (J), the integral of the restoring tension from 0 to s.
  double energy(double stroke) const;
};

class ConstantTensioner : public LineForce {
 public:
  ConstantTensioner(std::string name, std::unique_ptr<Marker> from, std::unique_ptr<Marker> to,
                    TensionerLaw law);

  /// L_ref (m): the length at zero stroke; the loader sets it to the distance at the start
  /// unless reference_length is given.
  void set_reference_length(double length) { reference_length_ = length; }
  double reference_length() const { return reference_length_; }

  void assemble(const State& state, double load_factor, AssemblyTarget& target) const override;
  double potential_energy(const State& state) const override;
  void add_channels(ChannelList& channels) const override;

  double stroke(const State& state) const;   ///< s = L - L_ref (m)
  double tension(const State& state) const;  ///< T (N), damping included
  const TensionerLaw& law() const { return law_; }

 private:
  TensionerLaw law_;
  double reference_length_ = 0.0;
};

}  // namespace seaflex
