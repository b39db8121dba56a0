#include "seaflex/post/fatigue_damage.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace seaflex::post {

Vec3 circumference_reference(const Vec3& t) {
  const Vec3 a = t.cwiseAbs();
  if (a.x() <= a.y() && a.x() <= a.z()) return Vec3::UnitX();
  return a.y() <= a.z() ? Vec3::UnitY() : Vec3::UnitZ();
}

void pipe_fibre_stresses(double tension_wall, const Vec3& moment, const Vec3& t, const Vec3& ref,
                         double area, double second_moment, double outer_radius,
                         std::span<double> out) {
  const Vec3 tu = t.normalized();
  Vec3 e1 = ref - ref.dot(tu) * tu;
  // a line that turned onto its reference axis: the least parallel axis now (the points
  // jump, but stay finite)
  if (e1.norm() < 1e-6) e1 = circumference_reference(tu) - circumference_reference(tu).dot(tu) * tu;
  e1.normalize();
  const Vec3 e2 = tu.cross(e1);
  const Vec3 g = tu.cross(moment) * (outer_radius / second_moment);  // stress gradient
  const double s_axial = tension_wall / area;
  const double g1 = g.dot(e1), g2 = g.dot(e2);
  const std::size_t n = out.size();
  for (std::size_t j = 0; j < n; ++j) {
    const double theta = 2.0 * std::numbers::pi * static_cast<double>(j) / static_cast<double>(n);
    out[j] = s_axial + g1 * std::cos(theta) + g2 * std::sin(theta);
  }
}

FatigueDamage::FatigueDamage(int histories, SnCurve curve, double range_factor)
    : counters_(static_cast<std::size_t>(histories)),
      damage_(static_cast<std::size_t>(histories), 0.0),
      curve_(std::move(curve)),
      factor_(range_factor) {}

void FatigueDamage::add(std::span<const double> stresses) {
  for (std::size_t i = 0; i < counters_.size(); ++i) {
    double& d = damage_[i];
    counters_[i].add(stresses[i], [&](const RainflowCycle& c) {
      d += c.count * curve_.damage(factor_ * c.range);  // Miner, DNV-RP-C203 eq. (2.2.1)
    });
  }
}

void FatigueDamage::finish() {
  for (std::size_t i = 0; i < counters_.size(); ++i) {
    double& d = damage_[i];
    counters_[i].finish(
        [&](const RainflowCycle& c) { d += c.count * curve_.damage(factor_ * c.range); });
  }
}

std::size_t FatigueDamage::max_stack() const {
  std::size_t m = 0;
  for (const auto& c : counters_) m = std::max(m, c.stack_size());
  return m;
}

}  // namespace seaflex::post
