// Steady current profile: horizontal velocity as a function of depth, tabulated and
// interpolated linearly in the velocity vector components (not in speed and direction,
// which would fail when the direction turns through 180 deg). Cf. DNV-RP-C205 (2021)
// section 4.1 for current profiles.
#pragma once

#include <array>
#include <vector>

#include "seaflex/core/types.hpp"

namespace seaflex::hydro {

/// A current given at a few depths.
class CurrentProfile {
 public:
  /// table rows (z (m, <= 0, z up, any order: the rows are sorted by z), speed (m/s, >= 0),
  /// direction (rad, the current flows TO, from +x towards +y)). An empty table means no
  /// current. Throws std::invalid_argument for a duplicate z ("current table: duplicate
  /// z = -10 m"), a negative speed ("current table: speed must be >= 0, got -1 m/s at
  /// z = -10 m"), z > 0 or any non-finite value.
  explicit CurrentProfile(std::vector<std::array<double, 3>> table = {});

  /// Horizontal current velocity (m/s; z component 0) at height z (m): linear
  /// interpolation of the velocity components between rows, constant beyond the table's
  /// ends, zero above the mean free surface z > 0.
  Vec3 velocity(double z) const;

  /// True if there is no current (empty table).
  bool empty() const { return z_.empty(); }

 private:
  std::vector<double> z_;  // ascending
  std::vector<Vec3> v_;
};

}  // namespace seaflex::hydro
