// The catenary first guess of a slack line (elements/catenary_shape.hpp), checked by
// properties it must have rather than by its own formulas:
// - the polyline through the nodes has the line's length and reaches the far end without
//   a jump (the last node is set to the end; the one before it must lie one element
//   length, L / N, away);
// - equilibrium of an inextensible chain of uniform weight w: the horizontal tension H is
//   constant and the vertical one grows by w per unit length, so the tangent of the slope
//   angle, tan(phi) = V / H, is linear in the arc length with slope w / H = 1 / a
//   (Irvine 1981, eq. 1.3); checked on the nodes' slopes and on finite differences of the
//   positions;
// - with a seabed the laid part is flat at the lower end's height and the hanging part
//   leaves it tangentially (tan(phi) = 0 at the touchdown point);
// - the nodes are symmetric under swapping the ends.
#include <gtest/gtest.h>

#include <cmath>

#include "seaflex/elements/catenary_shape.hpp"

using namespace seaflex;

namespace {

double polyline_length(const BeamGeometry& g) {
  double l = 0.0;
  for (std::size_t k = 0; k + 1 < g.positions.size(); ++k)
    l += (g.positions[k + 1] - g.positions[k]).norm();
  return l;
}

double tan_phi(const Vec3& t) {
  return t.z() / std::hypot(t.x(), t.y());
}

}  // namespace

TEST(CatenaryShape, FreeHangingLineIsAnInextensibleCatenary) {
  // a line between two points at different heights, 30 % longer than the chord
  const Vec3 A(10.0, -5.0, -80.0), B(10.0 + 240.0, -5.0 + 70.0, -20.0);
  const double L = 1.3 * (B - A).norm();
  const int n = 4000;
  CatenaryShape c;
  const BeamGeometry g = catenary_geometry(A, B, L, n, std::nullopt, &c);
  ASSERT_EQ(g.positions.size(), static_cast<std::size_t>(n + 1));
  EXPECT_FALSE(c.touchdown);
  EXPECT_EQ(g.positions.front(), A);
  EXPECT_EQ(g.positions.back(), B);
  for (double l : g.element_lengths) EXPECT_DOUBLE_EQ(l, L / n);
  // chords of arcs of length l = L / n with curvature kappa <= 1 / a (the vertex's) fall
  // short of l by at most l^3 kappa^2 / 24: in all, 0 <= L - polyline <= L l^2 / (24 a^2)
  // (plus round-off)
  const double l = L / n;
  EXPECT_GE(L - polyline_length(g), -1e-12 * L);
  EXPECT_LE(L - polyline_length(g), L * l * l / (24.0 * c.a * c.a) + 1e-12 * L);
  EXPECT_NEAR((g.positions[n] - g.positions[n - 1]).norm(), L / n, 1e-6 * L / n);
  // the plane of the curve is vertical through A and B
  const Vec3 e = Vec3(B.x() - A.x(), B.y() - A.y(), 0.0).normalized();
  for (const Vec3& p : g.positions) EXPECT_NEAR((p - A).cross(e).z(), 0.0, 1e-9 * L);
  // tan(phi) linear in s with slope 1 / a, from the slopes and from the positions
  for (int k = 0; k <= n; k += 50) {
    const double s = L * k / n;
    EXPECT_NEAR(g.slopes[k].norm(), 1.0, 1e-12);
    EXPECT_NEAR(tan_phi(g.slopes[k]), tan_phi(g.slopes[0]) + s / c.a, 1e-9 * (1.0 + L / c.a));
    if (k > 0 && k < n) {
      // a central difference of the positions: error l^2 / 6 of the third derivative
      const Vec3 d = g.positions[k + 1] - g.positions[k - 1];
      EXPECT_NEAR(tan_phi(d), tan_phi(g.slopes[k]), 1e-6);
    }
  }
  // and the hanging line sags below its lower end
  double lowest = A.z();
  for (const Vec3& p : g.positions) lowest = std::min(lowest, p.z());
  EXPECT_LT(lowest, A.z() - 1.0);
}

TEST(CatenaryShape, LaidLineLeavesTheSeabedTangentially) {
  // a mooring line: anchor on the seabed at 200 m, fairlead 10 m below the surface
  const Vec3 anchor(-800.0, 0.0, -200.0), fairlead(-20.0, 0.0, -10.0);
  const double L = 900.0;
  const int n = 3000;
  CatenaryShape c;
  const BeamGeometry g = catenary_geometry(anchor, fairlead, L, n, -200.0, &c);
  ASSERT_TRUE(c.touchdown);
  EXPECT_GT(c.laid_length, 0.0);
  EXPECT_LT(c.laid_length, L);
  const double l = L / n;  // chord deficit bound as in the free-hanging test
  EXPECT_GE(L - polyline_length(g), -1e-12 * L);
  EXPECT_LE(L - polyline_length(g), L * l * l / (24.0 * c.a * c.a) + 1e-12 * L);
  EXPECT_NEAR((g.positions[n] - g.positions[n - 1]).norm(), L / n, 1e-6 * L / n);
  for (int k = 0; k <= n; ++k) {
    const double s = L * k / n;
    EXPECT_GE(g.positions[k].z(), -200.0 - 1e-9) << "node " << k << " below the seabed";
    if (s <= c.laid_length) {
      EXPECT_NEAR(g.positions[k].z(), -200.0, 1e-9);
      EXPECT_NEAR(tan_phi(g.slopes[k]), 0.0, 1e-12);
    } else {
      // the hanging part: tan(phi) = (s - L_b) / a, zero at the touchdown point
      EXPECT_NEAR(tan_phi(g.slopes[k]), (s - c.laid_length) / c.a, 1e-9 * (1.0 + L / c.a));
    }
  }
  // the suspended part's horizontal span and height agree with the classic relations
  // h = a (cosh(x_s / a) - 1), L_s = a sinh(x_s / a) (Faltinsen 1990, sec. 8.1)
  const double Ls = L - c.laid_length, h = 190.0;
  const double xs = c.a * std::asinh(Ls / c.a);
  EXPECT_NEAR(c.a * (std::cosh(xs / c.a) - 1.0), h, 1e-9 * h);
  EXPECT_NEAR(c.laid_length + xs, 780.0, 1e-9 * 780.0);
}

TEST(CatenaryShape, SwappedEndsGiveTheSameCurveBackwards) {
  const Vec3 A(0.0, 0.0, -150.0), B(300.0, 100.0, -5.0);
  const int n = 100;
  for (const std::optional<double> seabed : {std::optional<double>(), std::optional(-150.0)}) {
    const BeamGeometry f = catenary_geometry(A, B, 450.0, n, seabed);
    const BeamGeometry b = catenary_geometry(B, A, 450.0, n, seabed);
    for (int k = 0; k <= n; ++k) {
      EXPECT_LT((f.positions[k] - b.positions[n - k]).norm(), 1e-9);
      EXPECT_LT((f.slopes[k] + b.slopes[n - k]).norm(), 1e-12);
    }
  }
}

TEST(CatenaryShape, RefusesWhatHasNoCatenary) {
  const Vec3 A(0.0, 0.0, -100.0), B(100.0, 0.0, 0.0);
  EXPECT_THROW(catenary_geometry(A, B, 100.0, 10, std::nullopt), std::invalid_argument);
  EXPECT_THROW(catenary_geometry(A, Vec3(0, 0, 0), 150.0, 10, std::nullopt), std::invalid_argument);
  // longer than along the seabed and straight up (100 + 100 m): it would pile up
  EXPECT_THROW(catenary_geometry(A, B, 250.0, 10, -100.0), std::invalid_argument);
}
