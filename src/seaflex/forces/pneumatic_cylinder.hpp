// A pneumatic cylinder between two marker points a (the barrel, on the platform) and b
// (the rod end, on the piston and sheave): the riser tensioner of thesis 3.3.2
// (Lee et al. 2015).
//
// Gas spring, thesis eq. (184) with a polytropic law: the cylinder is connected to an air
// pressure vessel (APV) of gas volume V0 at pressure P0 when the cylinder has its
// reference length Lr (its length at the start of the model). Shortening the cylinder by
// c = Lr - L pushes the piston (area A) into the gas:
//   V = V0 - A c,   P = P0 (V0 / V)^n,   gas force P A pushing the ends apart,
// with stiffness -d(P A)/dL = n P A^2 / V (n = 1: isothermal, as printed in the thesis;
// n = 1.4: adiabatic nitrogen).
//
// Friction in the cylinder, thesis eq. (185), Stribeck's law on the rate of extension
// v = L':
//   F_v = (F_c + (F_s - F_c) exp(-|v / v_s|)) sgn(v) + k_v v,   F_p = min(k_p P, F_p,max) sgn(v)
// opposing the motion. sgn(v) is replaced by tanh(v / v_r) with a small regularization
// velocity v_r, so that the force is smooth through v = 0 and implicit integration
// converges; |v| >> v_r recovers eq. (185).
//
// The axial force pushing the ends apart is F = P A - F_v - F_p. In the sign convention
// of a spring it is a tension T = -F (force T n on a, -T n on b, n = (p_b - p_a)/L).
// Exact tangents: dT/dL through P, dT/dL' through the friction law.
#pragma once

#include <memory>

#include "seaflex/forces/line_force.hpp"

namespace seaflex {

/// The gas law of eq. (184): pressure against the cylinder's compression c = Lr - L.
struct GasSpringLaw {
  double piston_area = 0.0;  ///< A (m^2), > 0
  double pressure = 0.0;     ///< P0 (Pa) at c = 0, > 0
  double volume = 0.0;       ///< V0 (m^3) at c = 0, > 0
  double exponent = 1.0;     ///< polytropic exponent n, >= 1

  double gas_volume(double compression) const { return volume - piston_area * compression; }
  double pressure_at(double compression) const;
  /// dP/dc = n P A / V
  double pressure_slope(double compression) const;
  /// Work done on the gas from c = 0 to c: integral of P A dc (J).
  double energy(double compression) const;
};

/// Stribeck friction of eq. (185), regularized through v = 0.
struct StribeckFriction {
  double coulomb = 0.0;                   ///< F_c (N), >= 0
  double static_friction = 0.0;           ///< F_s (N), >= F_c
  double stribeck_velocity = 1.0;         ///< v_s (m/s), > 0
  double viscous = 0.0;                   ///< k_v (N s/m), >= 0
  double pressure_coefficient = 0.0;      ///< k_p (N/Pa = m^2), >= 0
  double max_pressure_friction = 0.0;     ///< cap of k_p P (N), >= 0
  double regularization_velocity = 1e-3;  ///< v_r (m/s), > 0

  /// Friction force (N) opposing the rate v: positive for v > 0.
  double force(double v, double pressure) const;
  double dforce_dv(double v, double pressure) const;
  double dforce_dpressure(double v, double pressure) const;
};

class PneumaticCylinder : public LineForce {
 public:
  PneumaticCylinder(std::string name, std::unique_ptr<Marker> a, std::unique_ptr<Marker> b,
                    GasSpringLaw gas, StribeckFriction friction);

  /// The length at which the gas holds V0 and P0: the distance of the markers at the start.
  void set_reference_length(double length) { reference_length_ = length; }
  double reference_length() const { return reference_length_; }

  void assemble(const State& state, double load_factor, AssemblyTarget& target) const override;
  double potential_energy(const State& state) const override;
  void add_channels(ChannelList& channels) const override;

  double extension_rate(const State& state) const;  ///< L' (m/s)
  double pressure(const State& state) const;        ///< P (Pa)
  double friction(const State& state) const;        ///< friction force (N), opposing L'
  /// The axial force pushing the ends apart, P A - friction (N).
  double force(const State& state) const;
  /// Friction power F_fr L' (W, >= 0): the rate at which friction dissipates energy.
  double dissipation(const State& state) const;

  const GasSpringLaw& gas() const { return gas_; }
  const StribeckFriction& friction_law() const { return friction_; }

 private:
  double compression(double length) const { return reference_length_ - length; }
  GasSpringLaw gas_;
  StribeckFriction friction_;
  double reference_length_ = 0.0;
};

}  // namespace seaflex
