#include "seaflex/hydro/current_profile.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace seaflex::hydro {

CurrentProfile::CurrentProfile(std::vector<std::array<double, 3>> table) {
  for (const auto& row : table) {
    if (!std::isfinite(row[0]) || !std::isfinite(row[1]) || !std::isfinite(row[2]))
      throw std::invalid_argument(fmt::format(
          "current table: values must be finite, got ({}, {}, {})", row[0], row[1], row[2]));
    if (row[0] > 0.0)
      throw std::invalid_argument(
          fmt::format("current table: z must be <= 0 (z up, surface at 0), got {} m", row[0]));
    if (row[1] < 0.0)
      throw std::invalid_argument(
          fmt::format("current table: speed must be >= 0, got {} m/s at z = {} m", row[1], row[0]));
  }
  std::sort(table.begin(), table.end(), [](const auto& a, const auto& b) { return a[0] < b[0]; });
  for (std::size_t i = 1; i < table.size(); ++i)
    if (table[i][0] == table[i - 1][0])
      throw std::invalid_argument(fmt::format("current table: duplicate z = {} m", table[i][0]));
  z_.reserve(table.size());
  v_.reserve(table.size());
  for (const auto& row : table) {
    z_.push_back(row[0]);
    v_.emplace_back(row[1] * std::cos(row[2]), row[1] * std::sin(row[2]), 0.0);
  }
}

Vec3 CurrentProfile::velocity(double z) const {
  if (z_.empty() || z > 0.0) return Vec3::Zero();
  if (z <= z_.front()) return v_.front();
  if (z >= z_.back()) return v_.back();
  const auto it = std::upper_bound(z_.begin(), z_.end(), z);
  const auto i = static_cast<std::size_t>(it - z_.begin());  // z_[i-1] <= z < z_[i]
  const double s = (z - z_[i - 1]) / (z_[i] - z_[i - 1]);
  return (1.0 - s) * v_[i - 1] + s * v_[i];
}

}  // namespace seaflex::hydro
