// The weighted catenary first guess (elements/line_catenary.hpp):
//  - with a uniform weight it is the uniform catenary of elements/catenary_shape (itself
//    checked against Irvine's closed form in test_catenary_shape.cpp), free-hanging and
//    with a laid length, and with the line given from its upper end;
//  - for a line of two weights it is the equilibrium of the inextensible chain: every
//    element keeps its length, and the tension (H, V) of the shooting jumps by the point
//    weight at a clump; checked by the discrete equilibrium of the chord polygon: the
//    horizontal component of the chord direction times the local tension is constant.
#include <gtest/gtest.h>

#include <cmath>

#include "seaflex/elements/catenary_shape.hpp"
#include "seaflex/elements/line_catenary.hpp"

using namespace seaflex;

namespace {

void expect_same(const BeamGeometry& a, const BeamGeometry& b, double tol) {
  ASSERT_EQ(a.positions.size(), b.positions.size());
  for (std::size_t k = 0; k < a.positions.size(); ++k) {
    EXPECT_LT((a.positions[k] - b.positions[k]).norm(), tol) << "node " << k;
    EXPECT_LT((a.slopes[k] - b.slopes[k]).norm(), tol / 100.0) << "node " << k;
  }
}

}  // namespace

TEST(LineCatenary, UniformWeightIsTheUniformCatenary) {
  struct Case {
    Vec3 start, end;
    double length;
    bool seabed;
  };
  const Case cases[] = {
      {{0, 0, -100}, {300, 0, 0}, 400, false},   // free-hanging
      {{0, 0, -200}, {600, 200, 0}, 780, true},  // laid on the seabed from the start
      {{800, 0, 0}, {0, 0, -200}, 950, true},    // given from the upper end
  };
  for (const Case& c : cases) {
    const int n = 80;
    CatenaryShape shape;
    const BeamGeometry uniform = catenary_geometry(
        c.start, c.end, c.length, n,
        c.seabed ? std::optional<double>(std::min(c.start.z(), c.end.z())) : std::nullopt, &shape);
    LineWeights w;
    w.per_length.assign(n, 700.0);
    const auto g =
        weighted_catenary(c.start, c.end, uniform.element_lengths, w, c.seabed, uniform, shape);
    ASSERT_TRUE(g.has_value());
    // both solve the same equations to round-off (1e-9 of the span in the iterations)
    expect_same(*g, uniform, 1e-6 * c.length);
  }
}

TEST(LineCatenary, TwoWeightsAndAClumpAreAnInextensibleEquilibrium) {
  // 600 m from an anchor on the seabed at (0, 0, -300) to (500, 0, 0): a heavy lower half
  // (1500 N/m), a light upper half (300 N/m), a 100 kN clump at 450 m
  const Vec3 start(0, 0, -300), end(500, 0, 0);
  const int n = 240;
  CatenaryShape shape;
  const BeamGeometry uniform = catenary_geometry(start, end, 600.0, n, -300.0, &shape);
  LineWeights w;
  for (int k = 0; k < n; ++k) w.per_length.push_back(k < n / 2 ? 1500.0 : 300.0);
  w.points.push_back({450.0, 1.0e5});
  const auto g = weighted_catenary(start, end, uniform.element_lengths, w, true, uniform, shape);
  ASSERT_TRUE(g.has_value());
  EXPECT_LT((g->positions.front() - start).norm(), 1e-12);
  EXPECT_LT((g->positions.back() - end).norm(), 1e-12);
  // every chord is no longer than its element (an arc), and close to it: the chord of an
  // arc of curvature radius R over 2.5 m is shorter by l^3 / (24 R^2): R > 16 m here
  for (int k = 0; k < n; ++k) {
    const double chord = (g->positions[k + 1] - g->positions[k]).norm();
    EXPECT_LE(chord, 2.5 * (1 + 1e-9));
    EXPECT_GT(chord, 2.5 * (1 - 1e-3));
  }
  // the unit slopes are tangent to the chords between nodes (to the curvature's l / R),
  // except at the clump's kink (node 180)
  for (int k = 1; k < n; ++k) {
    if (k == 180) continue;
    const Vec3 chord = (g->positions[k + 1] - g->positions[k - 1]).normalized();
    EXPECT_GT(chord.dot(g->slopes[k]), 1.0 - 1e-3) << "node " << k;
    EXPECT_NEAR(g->slopes[k].norm(), 1.0, 1e-12);
  }
  // the slope angle's tangent V / H grows by w / H per metre and jumps by P / H at the
  // clump: from the slopes either side of node 180 (450 m), and in the heavy part
  auto tan_at = [&](int k) { return g->slopes[k].z() / g->slopes[k].x(); };
  ASSERT_GT(tan_at(100), 0.0);  // suspended from 250 m on (laid length below it)
  const double per_metre_heavy = (tan_at(110) - tan_at(100)) / 25.0;  // = 1500 / H
  const double H = 1500.0 / per_metre_heavy;
  const double per_metre_light = (tan_at(170) - tan_at(150)) / 50.0;
  // finite differences of exact slopes over 50 m: exact for a piecewise linear V
  EXPECT_NEAR(per_metre_light * H, 300.0, 1e-6 * 300.0);
  const double jump = (tan_at(182) - tan_at(178)) - 10.0 * per_metre_light;
  EXPECT_NEAR(jump * H, 1.0e5, 1e-6 * 1.0e5);
}
