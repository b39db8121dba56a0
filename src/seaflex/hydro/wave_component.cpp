#include "seaflex/hydro/wave_component.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "seaflex/hydro/dispersion.hpp"

namespace seaflex::hydro {

WaveComponent regular_component(double height, double period, double direction, double phase,
                                double depth, double g) {
  if (!std::isfinite(height) || height < 0.0)
    throw std::invalid_argument(fmt::format("height must be >= 0, got {}", height));
  if (!std::isfinite(period) || period <= 0.0)
    throw std::invalid_argument(fmt::format("period must be > 0, got {}", period));
  WaveComponent c;
  c.amplitude = 0.5 * height;
  c.omega = 2.0 * std::numbers::pi / period;
  c.k = wave_number(c.omega, depth, g);
  c.direction = direction;
  c.phase = phase;
  return c;
}

}  // namespace seaflex::hydro
