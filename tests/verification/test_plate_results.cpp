// Plate section results (post/plate_results.hpp) of the simply supported square plate of
// thesis 3.1.2 (plate_models.hpp) against Navier's series (Timoshenko & Woinowsky-Krieger,
// Theory of Plates and Shells (1959) sec. 28, eq. (131)-(133)):
//   w   = sum_{m,n odd} 16 q sin(m pi x/a) sin(n pi y/b) / (pi^6 D m n (m^2/a^2 + n^2/b^2)^2)
//   M_x = 16 q / pi^4 sum (m^2/a^2 + nu n^2/b^2) / (m n (m^2/a^2 + n^2/b^2)^2) sin sin
//   M_xy = -16 q (1 - nu) / pi^4 sum 1 / (a b (m^2/a^2 + n^2/b^2)^2) cos cos
// At 1 % of the self-weight (w/h = 0.0016) the plate is linear (test_plate.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "plate_models.hpp"
#include "seaflex/post/plate_results.hpp"

namespace seaflex {
namespace {

using namespace plate_models;

struct NavierMoments {
  double mx, my, mxy;
};
NavierMoments navier_moments(double q, double a, double b, double nu, double x, double y) {
  const double pi = std::numbers::pi;
  NavierMoments r{0, 0, 0};
  for (int m = 1; m <= 801; m += 2)
    for (int n = 1; n <= 801; n += 2) {
      const double k = m * m / (a * a) + n * n / (b * b);
      const double ss = std::sin(m * pi * x / a) * std::sin(n * pi * y / b);
      const double cc = std::cos(m * pi * x / a) * std::cos(n * pi * y / b);
      r.mx += (m * m / (a * a) + nu * n * n / (b * b)) / (m * n * k * k) * ss;
      r.my += (n * n / (b * b) + nu * m * m / (a * a)) / (m * n * k * k) * ss;
      r.mxy -= (1.0 - nu) / (a * b * k * k) * cc;
    }
  const double f = 16.0 * q / std::pow(pi, 4);
  return {f * r.mx, f * r.my, f * r.mxy};
}

}  // namespace

// the series itself: Timoshenko's Table 8 gives M_x = M_y = 0.0479 q a^2 at the centre of a
// square plate with nu = 0.3 (three digits)
TEST(PlateResults, NavierSeriesMatchesTimoshenkoTable) {
  const NavierMoments c = navier_moments(1.0, 1.0, 1.0, 0.3, 0.5, 0.5);
  EXPECT_NEAR(c.mx, 0.0479, 0.00005);
  EXPECT_NEAR(c.my, 0.0479, 0.00005);
}

// 16 x 16 elements: moments at the centre and at (a/4, a/2), and the twisting moment at
// (a/4, a/4), within 2 % of Navier (the tolerance: bicubic Hermite curvatures at
// the nodes, averaged over the elements around them, converge as h^2); the membrane
// forces of the linear regime are negligible: the surface stress is 6 m / h^2 to 1 %
TEST(PlateResults, SimplySupportedMomentsMatchNavierAt16x16) {
  PlateCase c;
  c.n = 16;
  c.load = 0.01;
  io::Model model = load(c);
  State s = model.system->initial_state();
  solve_statics(*model.system, s, model.statics);
  const auto& plate = dynamic_cast<const AncfPlate&>(*model.system->find_body("plate"));
  MatX out;
  post::compute_plate_results(plate, s, out);
  ASSERT_EQ(out.rows(), plate.num_nodes());
  const double q = c.load * kRho * kH * kG;
  using Q = post::PlateQuantity;
  const auto at = [&](int i, int j, Q quantity) {
    return out(plate.node_number(i, j), static_cast<int>(quantity));
  };
  const auto check = [&](int i, int j) {
    const double x = kSide * i / c.n, y = kSide * j / c.n;
    const NavierMoments ref = navier_moments(q, kSide, kSide, kNu, x, y);
    EXPECT_NEAR(at(i, j, Q::kM11), ref.mx, 0.02 * std::abs(ref.mx)) << "node " << i << "," << j;
    EXPECT_NEAR(at(i, j, Q::kM22), ref.my, 0.02 * std::abs(ref.my)) << "node " << i << "," << j;
    return ref;
  };
  const NavierMoments centre = check(8, 8);
  check(4, 8);
  check(8, 4);
  const NavierMoments quarter = navier_moments(q, kSide, kSide, kNu, kSide / 4, kSide / 4);
  // the twisting moment with its sign (m12 = D (1 - nu) k12 and the series above share
  // the convention), and its symmetry about the centre lines
  EXPECT_NEAR(at(4, 4, Q::kM12), quarter.mxy, 0.02 * std::abs(quarter.mxy));
  EXPECT_NEAR(at(12, 12, Q::kM12), at(4, 4, Q::kM12), 1e-6 * std::abs(quarter.mxy));
  EXPECT_NEAR(at(4, 12, Q::kM12), -at(4, 4, Q::kM12), 1e-6 * std::abs(quarter.mxy));
  // surfaces at the centre: bottom in tension, top in compression, 6 M / h^2
  const double sb = 6.0 * centre.mx / (kH * kH);
  EXPECT_NEAR(at(8, 8, Q::kS11Bottom), sb, 0.03 * sb);
  EXPECT_NEAR(at(8, 8, Q::kS11Top), -sb, 0.03 * sb);
  EXPECT_LT(std::abs(at(8, 8, Q::kN11)) / kH, 0.01 * sb);
  std::printf("centre m11 %.6g (Navier %.6g), m12(a/4,a/4) %.6g (Navier %.6g)\n", at(8, 8, Q::kM11),
              centre.mx, at(4, 4, Q::kM12), quarter.mxy);
}

}  // namespace seaflex
