#include "seaflex/hydro/hydro_database.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace seaflex::hydro {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// index i0 and weight s with x = (1 - s) xs[i0] + s xs[i0 + 1], clamped to the ends;
// a one-point table gives i0 = 0, s = 0
struct Bracket {
  std::size_t i0 = 0;
  std::size_t i1 = 0;
  double s = 0.0;
  bool clamped = false;
};

Bracket bracket(const std::vector<double>& xs, double x) {
  Bracket b;
  if (xs.size() <= 1 || x <= xs.front()) {
    b.clamped = xs.empty() || x < xs.front();
    return b;
  }
  if (x >= xs.back()) {
    b.i0 = b.i1 = xs.size() - 1;
    b.clamped = x > xs.back();
    return b;
  }
  const auto it = std::upper_bound(xs.begin(), xs.end(), x);
  b.i1 = static_cast<std::size_t>(it - xs.begin());
  b.i0 = b.i1 - 1;
  b.s = (x - xs[b.i0]) / (xs[b.i1] - xs[b.i0]);
  return b;
}

Mat6 interpolate(const std::vector<Mat6>& table, const std::vector<double>& omega, double w) {
  if (table.empty()) return Mat6::Zero();
  const Bracket b = bracket(omega, w);
  return (1.0 - b.s) * table[b.i0] + b.s * table[b.i1];
}

// heading bracket with the wrap-around rule of excitation_at
Bracket heading_bracket(const std::vector<double>& h, double beta) {
  Bracket b;
  const std::size_t n = h.size();
  if (n == 1) {
    const double d = std::remainder(beta - h[0], kTwoPi);
    b.clamped = std::abs(d) > 1e-9;
    return b;
  }
  double max_gap = 0.0;
  for (std::size_t i = 1; i < n; ++i) max_gap = std::max(max_gap, h[i] - h[i - 1]);
  const double closing = h.front() + kTwoPi - h.back();
  if (closing <= max_gap * (1.0 + 1e-9) + 1e-12) {
    // periodic: map beta into [front, front + 2 pi)
    double x = h.front() + std::fmod(beta - h.front(), kTwoPi);
    if (x < h.front()) x += kTwoPi;
    if (x <= h.back()) return bracket(h, x);
    b.i0 = n - 1;
    b.i1 = 0;
    b.s = closing > 0.0 ? (x - h.back()) / closing : 0.0;
    return b;
  }
  // not periodic: the equivalent angle nearest the middle of the range, then clamp
  const double mid = 0.5 * (h.front() + h.back());
  const double x = mid + std::remainder(beta - mid, kTwoPi);
  b = bracket(h, x);
  b.clamped = x < h.front() - 1e-9 || x > h.back() + 1e-9;
  return b;
}

}  // namespace

Vec6c HydroDatabase::excitation_at(double w, double heading, bool* extrapolated,
                                   bool* heading_clamped) const {
  if (extrapolated) *extrapolated = false;
  if (heading_clamped) *heading_clamped = false;
  if (!has_excitation || omega.empty() || headings.empty()) return Vec6c::Zero();
  const Bracket bw = bracket(omega, w);
  const Bracket bh = heading_bracket(headings, heading);
  if (extrapolated) *extrapolated = bw.clamped;
  if (heading_clamped) *heading_clamped = bh.clamped;
  auto at_heading = [&](std::size_t ih) -> Vec6c {
    const auto& row = excitation[ih];
    return (1.0 - bw.s) * row[bw.i0] + bw.s * row[bw.i1];
  };
  return (1.0 - bh.s) * at_heading(bh.i0) + bh.s * at_heading(bh.i1);
}

Mat6 HydroDatabase::added_mass_at(double w) const {
  return interpolate(added_mass, omega, w);
}

Mat6 HydroDatabase::damping_at(double w) const {
  return interpolate(damping, omega, w);
}

}  // namespace seaflex::hydro
