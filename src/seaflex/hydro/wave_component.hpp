// One linear (Airy) wave component and the regular wave built from one.
// Phase convention (the same as WAMIT's e^{i omega t}, WAMIT User Manual v7 ch. 4, so
// that excitation RAOs X multiply the complex amplitude directly, F = Re{X A e^{i w t}}):
//   eta(x, y, t) = a cos(omega t - k (x cos(beta) + y sin(beta)) + phase)
//                = Re{ a e^{i phase} e^{i (omega t - k x cos(beta) - k y sin(beta))} }.
// Airy theory: DNV-RP-C205 (2021) section 3.2.2; Dean & Dalrymple (1991) ch. 4.
#pragma once

namespace seaflex::hydro {

/// One regular component of a (possibly irregular) linear sea state.
struct WaveComponent {
  double amplitude = 0.0;  ///< a (m), half the crest-to-trough height
  double omega = 0.0;      ///< angular frequency (rad/s)
  double k = 0.0;          ///< wave number (rad/m), from the dispersion relation
  double direction = 0.0;  ///< beta (rad): the direction the wave travels TO, from +x towards +y
  double phase = 0.0;      ///< (rad), eta = a cos(omega t - k (x cos b + y sin b) + phase)
};

/// A regular Airy wave of height (m, crest to trough, > 0 ... 0 allowed for calm water),
/// period (s, > 0), direction (rad, travels to) and phase (rad), in water of depth (m;
/// <= 0 or infinite: deep water) under gravity g (m/s^2).
/// Throws std::invalid_argument for height < 0 or period <= 0 (messages name the field).
WaveComponent regular_component(double height, double period, double direction, double phase,
                                double depth, double g);

}  // namespace seaflex::hydro
