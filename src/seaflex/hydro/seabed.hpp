// The seabed's geometry: a height z = h(x, y) below the mean free surface, with its
// gradient. Three shapes, as offered by OrcaFlex and MoorDyn:
//   flat   h = -d                                   (d: the water depth)
//   plane  h = -(d + tan(slope) (x cos(psi) + y sin(psi)))
//          (the seabed falls by tan(slope) per metre along the downhill direction psi,
//           measured from x towards y; d is the depth at the origin)
//   grid   a rectangular grid of depths, bilinear in each cell (a bathymetry table);
//          outside the grid the edge values continue (the depth is held constant
//          along the outward normal of the grid's edge).
// The outward (upward) unit normal is n = (-h_x, -h_y, 1)/N, N = sqrt(1 + h_x^2 + h_y^2);
// the penetration of a point r below the seabed's local tangent plane is
//   d = (h(x, y) - z)/N,
// exact for a plane (the distance to it), and to first order for a grid.
#pragma once

#include <vector>

#include "seaflex/core/types.hpp"

namespace seaflex::hydro {

/// The seabed at one horizontal position.
struct SeabedPoint {
  double height = 0.0;  ///< h (m), z of the seabed (negative below the surface)
  double hx = 0.0;      ///< dh/dx
  double hy = 0.0;      ///< dh/dy

  /// Outward (upward) unit normal.
  Vec3 normal() const;
  /// Penetration of the point r: (h - z)/N (m), positive below the seabed.
  double penetration(const Vec3& r) const;
};

class Seabed {
 public:
  /// Flat at depth (m > 0).
  static Seabed flat(double depth);
  /// A plane with the depth depth_at_origin (m) at x = y = 0 that falls by tan(slope) per
  /// metre (slope in rad, 0 <= slope < pi/2) along the horizontal downhill direction
  /// direction (rad, from x towards y).
  static Seabed plane(double depth_at_origin, double slope, double direction);
  /// A bathymetry grid: xs and ys strictly increasing (at least two each), depths[j * nx + i]
  /// the depth (m, > 0) at (xs[i], ys[j]). Throws std::invalid_argument otherwise.
  static Seabed grid(std::vector<double> xs, std::vector<double> ys, std::vector<double> depths);

  SeabedPoint at(double x, double y) const;
  /// The shallowest point of the seabed (m below the surface): its depth nearest z = 0.
  double least_depth() const;

 private:
  enum class Kind { kFlat, kPlane, kGrid };
  Kind kind_ = Kind::kFlat;
  double depth_ = 0.0;          // flat, plane: the depth at the origin
  double gx_ = 0.0, gy_ = 0.0;  // plane: the gradient of the depth
  std::vector<double> xs_, ys_, depths_;
};

}  // namespace seaflex::hydro
