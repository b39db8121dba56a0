// A spring-damper between the points of two markers a and b: with d = p_b - p_a,
// L = |d| and L' = d^ . d', the tension T = T_s(L - L0) + c L' pulls the points together
// (force T d^ on a, -T d^ on b). T_s is linear, k (L - L0), or a table of tension
// against extension interpolated linearly and extended with its end slopes. A slack
// element (rope, sling) carries nothing while L < L0 and never pushes (T >= 0). Exact
// tangents: the stiffness T_s' d^ d^T + T/L (I - d^ d^T), the damping c d^ d^T, and the
// attitude terms of rigid-body markers.
#pragma once

#include <memory>
#include <vector>

#include "seaflex/forces/line_force.hpp"

namespace seaflex {

/// Tension (N) against extension (m): linear or piecewise linear.
class SpringLaw {
 public:
  static SpringLaw linear(double stiffness);
  /// extensions strictly increasing, at least two points.
  static SpringLaw table(std::vector<double> extensions, std::vector<double> tensions);

  double tension(double extension) const;
  double stiffness(double extension) const;  ///< dT/d(extension)
  double energy(double extension) const;     ///< integral of T from 0 to extension
  double zero_extension_tension() const { return tension(0.0); }

 private:
  int segment(double x) const;
  double k_ = 0.0;
  std::vector<double> x_, t_;
};

class SpringDamper : public LineForce {
 public:
  SpringDamper(std::string name, std::unique_ptr<Marker> a, std::unique_ptr<Marker> b,
               double free_length, SpringLaw law, double damping, bool slack);

  void assemble(const State& state, double load_factor, AssemblyTarget& target) const override;
  double potential_energy(const State& state) const override;
  void add_channels(ChannelList& channels) const override;

  double tension(const State& state) const;

 private:
  double free_length_;
  SpringLaw law_;
  double damping_;
  bool slack_;
};

}  // namespace seaflex
