#include "seaflex/hydro/displaced_volume.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace seaflex::hydro {

namespace {

// every face counter-clockwise seen from outside: reverse those whose normal points
// towards the centroid of the vertices (valid for convex polyhedra)
void orient_faces(ConvexPolyhedron& p) {
  Vec3 c = Vec3::Zero();
  for (const Vec3& v : p.vertices) c += v;
  c /= static_cast<double>(p.vertices.size());
  for (auto& f : p.faces) {
    Vec3 n = Vec3::Zero(), fc = Vec3::Zero();
    for (std::size_t i = 0; i < f.size(); ++i) {
      const Vec3& a = p.vertices[f[i]];
      const Vec3& b = p.vertices[f[(i + 1) % f.size()]];
      n += a.cross(b);  // Newell's normal
      fc += a;
    }
    fc /= static_cast<double>(f.size());
    if (n.dot(fc - c) < 0.0) std::reverse(f.begin(), f.end());
  }
}

// Sutherland-Hodgman: the part of a planar polygon with z <= 0
void clip_below(const std::vector<Vec3>& in, std::vector<Vec3>& out) {
  out.clear();
  const std::size_t n = in.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& a = in[i];
    const Vec3& b = in[(i + 1) % n];
    const bool a_in = a.z() <= 0.0, b_in = b.z() <= 0.0;
    if (a_in) out.push_back(a);
    if (a_in != b_in) {
      const double s = a.z() / (a.z() - b.z());
      Vec3 x = a + s * (b - a);
      x.z() = 0.0;
      out.push_back(x);
    }
  }
}

}  // namespace

ConvexPolyhedron ConvexPolyhedron::box(const Vec3& center, const Vec3& size, const Mat3& axes) {
  ConvexPolyhedron p;
  for (int k = 0; k < 8; ++k) {
    const Vec3 s((k & 1) ? 0.5 : -0.5, (k & 2) ? 0.5 : -0.5, (k & 4) ? 0.5 : -0.5);
    p.vertices.push_back(center + axes * s.cwiseProduct(size));
  }
  p.faces = {{0, 2, 6, 4}, {1, 5, 7, 3}, {0, 4, 5, 1}, {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 6, 7, 5}};
  orient_faces(p);
  return p;
}

ConvexPolyhedron ConvexPolyhedron::cylinder(const Vec3& a, const Vec3& b, double diameter,
                                            int sides) {
  const Vec3 axis = b - a;
  if (!(axis.norm() > 0.0) || !(diameter > 0.0) || sides < 3)
    throw std::invalid_argument("ConvexPolyhedron::cylinder: degenerate cylinder");
  const Vec3 t = axis.normalized();
  const Vec3 e1 = (std::abs(t.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY()).cross(t).normalized();
  const Vec3 e2 = t.cross(e1);
  // circumradius of the regular polygon with the circle's area
  const double phi = 2.0 * std::numbers::pi / sides;
  const double rc = 0.5 * diameter * std::sqrt(phi / std::sin(phi));
  ConvexPolyhedron p;
  for (int end = 0; end < 2; ++end)
    for (int i = 0; i < sides; ++i)
      p.vertices.push_back((end ? b : a) + rc * (std::cos(i * phi) * e1 + std::sin(i * phi) * e2));
  std::vector<int> bottom, top;
  for (int i = 0; i < sides; ++i) {
    bottom.push_back(i);
    top.push_back(sides + i);
    p.faces.push_back({i, (i + 1) % sides, sides + (i + 1) % sides, sides + i});
  }
  p.faces.push_back(bottom);
  p.faces.push_back(top);
  orient_faces(p);
  return p;
}

double ConvexPolyhedron::volume() const {
  // the same integral with no clipping: shift far below the plane
  const Vec3 shift(0, 0, -1e6);
  double v = 0.0;
  for (const auto& f : faces)
    for (std::size_t i = 1; i + 1 < f.size(); ++i) {
      const Vec3 a = vertices[f[0]] + shift, b = vertices[f[i]] + shift,
                 c = vertices[f[i + 1]] + shift;
      v += 0.5 * (b - a).cross(c - a).z() * (a.z() + b.z() + c.z()) / 3.0;
    }
  return v;
}

Displacement submerged_part(const ConvexPolyhedron& hull, const Vec3& r, const Mat3& R) {
  Displacement d;
  // scratch reused between calls: no allocation once warm
  thread_local std::vector<Vec3> poly, cut;
  double V = 0.0, mx = 0.0, my = 0.0, mz = 0.0, awp = 0.0;
  for (const auto& f : hull.faces) {
    poly.clear();
    for (int i : f) poly.push_back(r + R * hull.vertices[i]);
    clip_below(poly, cut);
    if (cut.size() < 3) continue;
    for (std::size_t i = 1; i + 1 < cut.size(); ++i) {
      const Vec3& a = cut[0];
      const Vec3& b = cut[i];
      const Vec3& c = cut[i + 1];
      const double an = 0.5 * (b - a).cross(c - a).z();  // n_z dA of the triangle
      const double sx = a.x() + b.x() + c.x(), sy = a.y() + b.y() + c.y(),
                   sz = a.z() + b.z() + c.z();
      V += an * sz / 3.0;
      mx += an / 12.0 * (a.x() * a.z() + b.x() * b.z() + c.x() * c.z() + sx * sz);
      my += an / 12.0 * (a.y() * a.z() + b.y() * b.z() + c.y() * c.z() + sy * sz);
      mz += 0.5 * an / 12.0 * (a.z() * a.z() + b.z() * b.z() + c.z() * c.z() + sz * sz);
      awp -= an;  // the wetted surface's projection closes on the waterplane
    }
  }
  if (V <= 0.0) return d;
  d.volume = V;
  d.centroid = Vec3(mx, my, mz) / V;
  d.waterplane_area = awp;
  return d;
}

}  // namespace seaflex::hydro
