#include "seaflex/hydro/seabed.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace seaflex::hydro {

Vec3 SeabedPoint::normal() const {
  return Vec3(-hx, -hy, 1.0) / std::sqrt(1.0 + hx * hx + hy * hy);
}

double SeabedPoint::penetration(const Vec3& r) const {
  return (height - r.z()) / std::sqrt(1.0 + hx * hx + hy * hy);
}

Seabed Seabed::flat(double depth) {
  if (!(depth > 0.0) || !std::isfinite(depth))
    throw std::invalid_argument("a flat seabed needs a finite depth > 0");
  Seabed s;
  s.kind_ = Kind::kFlat;
  s.depth_ = depth;
  return s;
}

Seabed Seabed::plane(double depth_at_origin, double slope, double direction) {
  if (!(depth_at_origin > 0.0) || !std::isfinite(depth_at_origin))
    throw std::invalid_argument("a sloped seabed needs a finite depth > 0 at the origin");
  if (!(slope >= 0.0 && slope < 0.5 * std::numbers::pi))
    throw std::invalid_argument("the seabed slope must lie in [0, 90) deg");
  Seabed s;
  s.kind_ = Kind::kPlane;
  s.depth_ = depth_at_origin;
  const double t = std::tan(slope);
  s.gx_ = t * std::cos(direction);
  s.gy_ = t * std::sin(direction);
  return s;
}

Seabed Seabed::grid(std::vector<double> xs, std::vector<double> ys, std::vector<double> depths) {
  auto increasing = [](const std::vector<double>& v) {
    for (std::size_t i = 1; i < v.size(); ++i)
      if (!(v[i] > v[i - 1])) return false;
    return v.size() >= 2;
  };
  if (!increasing(xs) || !increasing(ys))
    throw std::invalid_argument("a bathymetry grid needs at least two distinct x and y values");
  if (depths.size() != xs.size() * ys.size())
    throw std::invalid_argument("a bathymetry grid needs a depth at every (x, y) of the grid");
  for (double d : depths)
    if (!(d > 0.0) || !std::isfinite(d))
      throw std::invalid_argument("every depth of a bathymetry grid must be finite and > 0");
  Seabed s;
  s.kind_ = Kind::kGrid;
  s.xs_ = std::move(xs);
  s.ys_ = std::move(ys);
  s.depths_ = std::move(depths);
  return s;
}

namespace {
// cell index i with v[i] <= x < v[i+1] (clamped to the grid) and the local coordinate in
// [0, 1]; outside the grid the coordinate is clamped, so the edge values continue
std::pair<std::size_t, double> locate(const std::vector<double>& v, double x) {
  const auto it = std::upper_bound(v.begin(), v.end(), x);
  std::size_t i = it == v.begin() ? 0 : static_cast<std::size_t>(it - v.begin()) - 1;
  i = std::min(i, v.size() - 2);
  const double u = (x - v[i]) / (v[i + 1] - v[i]);
  return {i, std::clamp(u, 0.0, 1.0)};
}
}  // namespace

SeabedPoint Seabed::at(double x, double y) const {
  SeabedPoint p;
  switch (kind_) {
    case Kind::kFlat:
      p.height = -depth_;
      break;
    case Kind::kPlane:
      p.height = -(depth_ + gx_ * x + gy_ * y);
      p.hx = -gx_;
      p.hy = -gy_;
      break;
    case Kind::kGrid: {
      const auto [i, u] = locate(xs_, x);
      const auto [j, w] = locate(ys_, y);
      const std::size_t nx = xs_.size();
      const double d00 = depths_[j * nx + i], d10 = depths_[j * nx + i + 1];
      const double d01 = depths_[(j + 1) * nx + i], d11 = depths_[(j + 1) * nx + i + 1];
      // bilinear in the cell; the gradient is zero across a clamped (outside) direction
      const double depth =
          (1 - u) * (1 - w) * d00 + u * (1 - w) * d10 + (1 - u) * w * d01 + u * w * d11;
      const bool inside_x = x >= xs_.front() && x <= xs_.back();
      const bool inside_y = y >= ys_.front() && y <= ys_.back();
      const double ddx = ((1 - w) * (d10 - d00) + w * (d11 - d01)) / (xs_[i + 1] - xs_[i]);
      const double ddy = ((1 - u) * (d01 - d00) + u * (d11 - d10)) / (ys_[j + 1] - ys_[j]);
      p.height = -depth;
      p.hx = inside_x ? -ddx : 0.0;
      p.hy = inside_y ? -ddy : 0.0;
      break;
    }
  }
  return p;
}

double Seabed::least_depth() const {
  switch (kind_) {
    case Kind::kFlat:
      return depth_;
    case Kind::kPlane:
      return gx_ == 0.0 && gy_ == 0.0 ? depth_ : -std::numeric_limits<double>::infinity();
    case Kind::kGrid:
      return *std::min_element(depths_.begin(), depths_.end());
  }
  return depth_;
}

}  // namespace seaflex::hydro
