// The submerged part of a convex hull piece (box, cylinder) below the plane z = 0: its
// volume and centre of buoyancy, exactly, for any position and attitude (thesis eq. 172,
// "the displaced volume recomputed each step").
//
// Divergence theorem with fields whose flux through the plane z = 0 vanishes:
//   V = oint z n_z dA,  V x_b = oint x z n_z dA,  V y_b = oint y z n_z dA,
//   V z_b = oint z^2/2 n_z dA,
// over the faces clipped to z <= 0 only, so the waterplane cut never has to be built.
// On a planar triangle the integral of a product of two linear functions g h is
// (A/12) (sum g_i h_i + sum g_i sum h_i) (exact).
// A cylinder is a prism on a regular polygon whose area equals pi R^2 (volume exact when
// upright; the waterplane's second moment differs from pi R^4/4 by O((2 pi/N)^2), 2e-4
// relative for the default N = 64 sides: see tests/unit/test_hull_hydrostatics.cpp).
#pragma once

#include <vector>

#include "seaflex/core/types.hpp"

namespace seaflex::hydro {

struct ConvexPolyhedron {
  std::vector<Vec3> vertices;
  std::vector<std::vector<int>> faces;  ///< vertex indices, counter-clockwise seen from outside

  /// Box with centre c, edge lengths size (m) along the columns of axes.
  static ConvexPolyhedron box(const Vec3& center, const Vec3& size, const Mat3& axes);
  /// Circular cylinder between the centres a and b of its end faces, diameter (m).
  static ConvexPolyhedron cylinder(const Vec3& a, const Vec3& b, double diameter, int sides = 64);
  double volume() const;
};

struct Displacement {
  double volume = 0.0;           ///< m^3
  Vec3 centroid = Vec3::Zero();  ///< centre of buoyancy (world, m); zero when dry
  double waterplane_area = 0.0;  ///< m^2 (the cut's area, projected on z = 0)
};

/// The part of the hull below z = 0, the hull's vertices mapped to the world by
/// x = r + R x_hull.
Displacement submerged_part(const ConvexPolyhedron& hull, const Vec3& r, const Mat3& R);

}  // namespace seaflex::hydro
