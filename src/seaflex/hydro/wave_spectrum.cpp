#include "seaflex/hydro/wave_spectrum.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <stdexcept>

#include "seaflex/hydro/dispersion.hpp"

namespace seaflex::hydro {

namespace {

// uniform in [0, 1) from the top 53 bits of one 64-bit draw
double uniform01(std::mt19937_64& engine) {
  const std::uint64_t x = engine();
  return static_cast<double>(x >> 11) * 0x1.0p-53;
}

void validate(const SpectrumSpec& spec) {
  if (!(spec.hs > 0.0) || !std::isfinite(spec.hs))
    throw std::invalid_argument(fmt::format("hs must be > 0, got {}", spec.hs));
  if (!(spec.tp > 0.0) || !std::isfinite(spec.tp))
    throw std::invalid_argument(fmt::format("tp must be > 0, got {}", spec.tp));
  if (spec.kind == SpectrumKind::kJonswap && (!(spec.gamma >= 1.0) || !std::isfinite(spec.gamma)))
    throw std::invalid_argument(fmt::format("gamma must be >= 1, got {}", spec.gamma));
  if (spec.components < 1)
    throw std::invalid_argument(fmt::format("components must be >= 1, got {}", spec.components));
  if (spec.omega_min < 0.0 || !std::isfinite(spec.omega_min))
    throw std::invalid_argument(fmt::format("omega_min must be >= 0, got {}", spec.omega_min));
  if (spec.omega_max < 0.0 || !std::isfinite(spec.omega_max))
    throw std::invalid_argument(fmt::format("omega_max must be >= 0, got {}", spec.omega_max));
  double lo = 0.0, hi = 0.0;
  spectrum_band(spec, lo, hi);
  if ((spec.omega_min > 0.0 || spec.omega_max > 0.0) && !(hi > lo))
    throw std::invalid_argument(
        fmt::format("omega_max must exceed omega_min, got {} <= {}", hi, lo));
}

}  // namespace

double spectral_density(const SpectrumSpec& spec, double omega) {
  if (!(omega > 0.0)) return 0.0;
  const double wp = 2.0 * std::numbers::pi / spec.tp;
  const double r = wp / omega;  // (w/wp)^-1
  const double r4 = r * r * r * r;
  // DNV-RP-C205 eq. (3.5.5.1): Pierson-Moskowitz
  const double s_pm = 5.0 / 16.0 * spec.hs * spec.hs * r4 / omega * std::exp(-1.25 * r4);
  if (spec.kind == SpectrumKind::kPiersonMoskowitz || spec.gamma == 1.0) return s_pm;
  // DNV-RP-C205 eq. (3.5.5.2)-(3.5.5.4): JONSWAP
  const double sigma = omega <= wp ? 0.07 : 0.09;
  const double e = (omega - wp) / (sigma * wp);
  const double a_gamma = 1.0 - 0.287 * std::log(spec.gamma);
  return a_gamma * s_pm * std::pow(spec.gamma, std::exp(-0.5 * e * e));
}

void spectrum_band(const SpectrumSpec& spec, double& omega_min, double& omega_max) {
  const double wp = 2.0 * std::numbers::pi / spec.tp;
  omega_min = spec.omega_min > 0.0 ? spec.omega_min : 0.5 * wp;
  omega_max = spec.omega_max > 0.0 ? spec.omega_max : 5.0 * wp;
}

std::vector<WaveComponent> irregular_components(const SpectrumSpec& spec, double depth, double g,
                                                const DirectionSet& directions) {
  validate(spec);
  if (directions.angles.size() != directions.weights.size() || directions.angles.empty())
    throw std::invalid_argument("directions must hold as many angles as weights");
  double lo = 0.0, hi = 0.0;
  spectrum_band(spec, lo, hi);
  const int n = spec.components;
  const double dw = (hi - lo) / n;
  std::mt19937_64 engine(spec.seed);
  std::vector<WaveComponent> components;
  components.reserve(directions.angles.size() * static_cast<std::size_t>(n));
  for (std::size_t j = 0; j < directions.angles.size(); ++j) {
    const double weight = directions.weights[j];
    const double direction = spec.direction + directions.angles[j];
    for (int i = 0; i < n; ++i) {
      const double u = uniform01(engine);
      const double v = uniform01(engine);
      WaveComponent& c = components.emplace_back();
      c.omega = lo + (i + u) * dw;
      // S(omega, theta) = S(omega) D(theta): the bin's share w_j (DNV-RP-C205 3.5.8)
      c.amplitude = std::sqrt(2.0 * weight * spectral_density(spec, c.omega) * dw);
      c.k = wave_number(c.omega, depth, g);
      c.direction = direction;
      c.phase = 2.0 * std::numbers::pi * v;
    }
  }
  return components;
}

}  // namespace seaflex::hydro
