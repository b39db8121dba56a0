#include "seaflex/hydro/ramp.hpp"

#include <cmath>
#include <numbers>

namespace seaflex::hydro {

double Ramp::factor(double t) const {
  if (duration <= 0.0) {
    if (start == 0.0) return 1.0;
    return t < start ? 0.0 : 1.0;
  }
  if (t < start) return 0.0;
  if (t >= start + duration) return 1.0;
  return 0.5 * (1.0 - std::cos(std::numbers::pi * (t - start) / duration));
}

}  // namespace seaflex::hydro
