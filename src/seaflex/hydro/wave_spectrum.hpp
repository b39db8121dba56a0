// Wave spectra and their discretization into random-phase linear components.
// - JONSWAP and Pierson-Moskowitz one-sided spectra in angular frequency, DNV-RP-C205
//   (2021) section 3.5.5:
//     S_PM(w) = 5/16 Hs^2 wp^4 w^-5 exp(-5/4 (w/wp)^-4),  wp = 2 pi / Tp
//     S_J(w)  = A_gamma S_PM(w) gamma^exp(-0.5 ((w - wp) / (sigma wp))^2)
//     sigma = 0.07 (w <= wp), 0.09 (w > wp);  A_gamma = 1 - 0.287 ln(gamma).
//   A_gamma is DNV's approximate normalization: the integral of S_J is Hs^2/16 to
//   within 0.3 % for 1 <= gamma <= 5 and 1.8 % at gamma = 7 (exact for PM, gamma = 1).
// - Random-phase discretization (e.g. Faltinsen 1990, section 2.3; DNV-RP-C205 3.5.11):
//   N equal bins on [omega_min, omega_max]; the component frequency lies at a random
//   position inside its bin (so the realization has no repeat period 2 pi / dw) and
//   its amplitude is a_i = sqrt(2 S(w_i) dw).
// - Short-crested seas (directional spreading, hydro/directional_spreading.hpp): each of the M
//   directions theta0 + alpha_j (weight w_j) gets its own N components over the same bins, at
//   its own random frequencies and phases, amplitude sqrt(2 w_j S(w_ij) dw); the total variance
//   is then sum_j w_j (sum_i S(w_ij) dw), whose expectation is the band's m0 exactly (sum w_j =
//   1). Distinct frequencies in each direction make the sea ergodic: a long record at one point
//   has the statistics of the ensemble, without the spatially periodic interference that a
//   frequency shared by two directions makes (Jefferys 1987, "Directional seas should be
//   ergodic", Applied Ocean Research 9(4) 186-191).
// Determinism: uniforms come from std::mt19937_64 raw output, u = (x >> 11) 2^-53, not from
// std::uniform_real_distribution (whose algorithm the standard leaves to the library).
#pragma once

#include <vector>

#include "seaflex/hydro/directional_spreading.hpp"
#include "seaflex/hydro/wave_component.hpp"

namespace seaflex::hydro {

enum class SpectrumKind { kJonswap, kPiersonMoskowitz };

/// Parameters of an irregular sea (long-crested; spread by the DirectionSet of
/// irregular_components).
struct SpectrumSpec {
  SpectrumKind kind = SpectrumKind::kJonswap;
  double hs = 0.0;         ///< significant wave height (m), > 0
  double tp = 0.0;         ///< peak period (s), > 0
  double gamma = 3.3;      ///< JONSWAP peak enhancement (-), >= 1; ignored for PM
  double direction = 0.0;  ///< (rad) (mean) direction the waves travel TO
  unsigned seed = 1;       ///< seed of the random frequencies and phases
  int components = 200;    ///< number of components (per direction when spread), >= 1
  double omega_min = 0.0;  ///< (rad/s) lower end; 0 => 0.5 wp
  double omega_max = 0.0;  ///< (rad/s) upper end; 0 => 5 wp (the PM tail above holds 0.2 %)
};

/// One-sided spectral density S(omega) (m^2 s/rad) at omega (rad/s); 0 for omega <= 0.
/// For kPiersonMoskowitz gamma is not used (PM is JONSWAP with gamma = 1).
/// Does not validate spec (irregular_components does).
double spectral_density(const SpectrumSpec& spec, double omega);

/// The effective [omega_min, omega_max] (rad/s) of spec after applying the defaults.
void spectrum_band(const SpectrumSpec& spec, double& omega_min, double& omega_max);

/// Random-phase realization of spec (see the file comment) in water of depth (m; <= 0 or
/// infinite: deep) under gravity g (m/s^2), spread over directions (default: long-crested).
/// Component j N + i (direction j, bin i, 0-based) has
///   omega = omega_min + (i + u) dw,  dw = (omega_max - omega_min) / N,
///   amplitude sqrt(2 w_j S(omega) dw), phase 2 pi v, direction spec.direction + alpha_j,
/// where u, v are the (2(jN + i))-th and (2(jN + i) + 1)-th uniforms of std::mt19937_64(seed)
/// (so one direction of weight 1 is the long-crested sea, bit for bit).
/// Bit-identical on every platform for a given seed (up to libm's exp/pow).
/// Throws std::invalid_argument naming the field: "hs must be > 0, got -1" (same for tp),
/// "gamma must be >= 1, got 0.5", "components must be >= 1, got 0",
/// "omega_max must exceed omega_min, got 0.3 <= 0.5" (only when one of them is given),
/// "omega_min must be >= 0, got -1"; "directions must hold as many angles as weights" for a
/// malformed set.
std::vector<WaveComponent> irregular_components(
    const SpectrumSpec& spec, double depth, double g,
    const DirectionSet& directions = DirectionSet::long_crested());

}  // namespace seaflex::hydro
