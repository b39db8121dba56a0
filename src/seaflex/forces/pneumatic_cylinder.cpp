#include "seaflex/forces/pneumatic_cylinder.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "seaflex/core/errors.hpp"
#include "seaflex/forces/line_force.hpp"

namespace seaflex {

// thesis eq. (184), polytropic: P V^n = P0 V0^n
double GasSpringLaw::pressure_at(double c) const {
  return pressure * std::pow(volume / gas_volume(c), exponent);
}

double GasSpringLaw::pressure_slope(double c) const {
  return exponent * pressure_at(c) * piston_area / gas_volume(c);
}

double GasSpringLaw::energy(double c) const {
  // integral of P A dc = integral of P dV' over the volume swept, V from V0 down to V
  const double V = gas_volume(c);
  if (std::abs(exponent - 1.0) < 1e-12) return pressure * volume * std::log(volume / V);
  return pressure * volume / (exponent - 1.0) * (std::pow(volume / V, exponent - 1.0) - 1.0);
}

// thesis eq. (185) with sgn(v) -> tanh(v / v_r)
double StribeckFriction::force(double v, double p) const {
  const double s = std::tanh(v / regularization_velocity);
  const double stribeck =
      coulomb + (static_friction - coulomb) * std::exp(-std::abs(v) / stribeck_velocity);
  const double fp = std::min(pressure_coefficient * p, max_pressure_friction);
  return (stribeck + fp) * s + viscous * v;
}

double StribeckFriction::dforce_dv(double v, double p) const {
  const double s = std::tanh(v / regularization_velocity);
  const double ds = (1.0 - s * s) / regularization_velocity;
  const double e = std::exp(-std::abs(v) / stribeck_velocity);
  const double stribeck = coulomb + (static_friction - coulomb) * e;
  // d/dv exp(-|v|/v_s) = -sgn(v) e / v_s; times tanh it is -|tanh| e / v_s (continuous)
  const double dstribeck_s = -(static_friction - coulomb) * e / stribeck_velocity * std::abs(s);
  const double fp = std::min(pressure_coefficient * p, max_pressure_friction);
  return (stribeck + fp) * ds + dstribeck_s + viscous;
}

double StribeckFriction::dforce_dpressure(double v, double p) const {
  if (pressure_coefficient * p >= max_pressure_friction) return 0.0;
  return pressure_coefficient * std::tanh(v / regularization_velocity);
}

PneumaticCylinder::PneumaticCylinder(std::string name, std::unique_ptr<Marker> a,
                                     std::unique_ptr<Marker> b, GasSpringLaw gas,
                                     StribeckFriction friction)
    : LineForce(std::move(name), std::move(a), std::move(b)), gas_(gas), friction_(friction) {}

double PneumaticCylinder::extension_rate(const State& state) const {
  return line(state).rate;
}

double PneumaticCylinder::pressure(const State& state) const {
  return gas_.pressure_at(compression(length(state)));
}

double PneumaticCylinder::friction(const State& state) const {
  return friction_.force(extension_rate(state), pressure(state));
}

double PneumaticCylinder::force(const State& state) const {
  return pressure(state) * gas_.piston_area - friction(state);
}

double PneumaticCylinder::dissipation(const State& state) const {
  return friction(state) * extension_rate(state);
}

void PneumaticCylinder::assemble(const State& state, double, AssemblyTarget& target) const {
  if (!has_coordinates()) return;
  const LineState s = line_for_assembly(state, "cylinder");
  const double L = s.length, Ld = s.rate;
  const double c = compression(L);
  const double V = gas_.gas_volume(c);
  if (!(V > 0.01 * gas_.volume))
    throw SolverError(
        fmt::format("t = {:.6g} s: cylinder {} is compressed by {:.4g} m, which leaves {:.3g} "
                    "of its gas volume: the piston has run out of stroke (the load exceeds what "
                    "the tensioner can hold, or the gas volume is too small)",
                    state.t, name(), c, V / gas_.volume),
        state.t);
  const double P = gas_.pressure_at(c);
  // tension (spring convention): T = F_friction(L', P) - P A
  const double T = friction_.force(Ld, P) - P * gas_.piston_area;
  // dP/dL = -dP/dc
  const double dPdL = -gas_.pressure_slope(c);
  const double dTdL = (friction_.dforce_dpressure(Ld, P) - gas_.piston_area) * dPdL;
  assemble_line(s, {T, dTdL, friction_.dforce_dv(Ld, P)}, state, target);
}

double PneumaticCylinder::potential_energy(const State& state) const {
  return gas_.energy(compression(length(state)));
}

void PneumaticCylinder::add_channels(ChannelList& channels) const {
  channels.push_back(
      {fmt::format("{}.pressure", name()), [this](const State& s) { return pressure(s); }});
  channels.push_back({fmt::format("{}.stroke", name()),
                      [this](const State& s) { return length(s) - reference_length_; }});
  channels.push_back(
      {fmt::format("{}.force", name()), [this](const State& s) { return force(s); }});
  channels.push_back(
      {fmt::format("{}.friction", name()), [this](const State& s) { return friction(s); }});
}

}  // namespace seaflex
