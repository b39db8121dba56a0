// Linear (Airy) dispersion relation for surface gravity waves over a flat bed:
//   omega^2 = g k tanh(k d)
// (DNV-RP-C205 (2021) section 3.2.2.3; Dean & Dalrymple, Water Wave Mechanics for
// Engineers and Scientists, 1991, eq. 4.19). Solved for k by Newton iteration on the
// nondimensional form y tanh(y) = x with y = k d, x = omega^2 d / g.
#pragma once

namespace seaflex::hydro {

/// Wave number k (rad/m) of a wave of angular frequency omega (rad/s, >= 0) in water of
/// depth `depth` (m) under gravity g (m/s^2, > 0). depth <= 0 or infinite (std::isinf)
/// means deep water, k = omega^2 / g. Converges to ~1e-15 relative.
/// Throws std::invalid_argument for omega < 0, g <= 0 or non-finite omega or g.
double wave_number(double omega, double depth, double g);

}  // namespace seaflex::hydro
