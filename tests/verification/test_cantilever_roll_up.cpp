// Verification: the roll-up of a cantilever into a full circle by an end couple (issue 16,
// item 5). A pure couple M bends an elastic line into a circular arc of curvature
// d theta/dx = M/EI (per reference length) with no axial force, so M = 2 pi EI/L closes
// the beam into a circle of circumference L: the tip returns to the clamped root and the
// axis keeps its length (Reissner 1972, ZAMP 23:795-804: the elastic line's bending strain
// is d theta/dx, independent of the stretch). A classic large-rotation benchmark (e.g.
// Simo & Vu-Quoc 1986, CMAME 58:79-116, sec. 7.1; Ibrahimbegovic 1995).
//
// The couple is the point load's moment on the end node's slope t = r':
// Q = J_t^T (M x t)/|t|^2, the gradient of M theta for a couple normal to the plane of
// bending, so it follows the end section (a follower couple in 2-D) and is conservative.
//
// The thesis's curvature per deformed length (eq. 14, `bending_model: exact_deformed`),
// kappa = (d theta/dx)/lambda with lambda = |r'|, gives the energy density
// 1/2 EA eps^2 + 1/2 EI theta'^2/lambda^2; its equilibrium under the couple is
//   M = EI theta'/lambda^2,  EA eps lambda = EI theta'^2/lambda^3  =>  EA eps = M^2/EI,
// a uniform circle stretched by lambda = sqrt(1 + 2 M^2/(EI EA)), of radius
// rho = lambda/theta' = EI/(M lambda), closing an angle 2 pi lambda^2: it overlaps itself
// by 4 pi (lambda - 1) radians. Both closed forms are checked below.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

#include "seaflex/elements/ancf_beam.hpp"
#include "seaflex/io/model_loader.hpp"
#include "seaflex/io/output_selection.hpp"
#include "seaflex/math/gauss_legendre.hpp"
#include "seaflex/post/beam_results.hpp"
#include "seaflex/solvers/statics.hpp"

using namespace seaflex;

namespace {

constexpr double kPi = std::numbers::pi;
// the steel beam of the thesis's cantilever (section 3.1.1): EI = 1.749e6 N m^2,
// EA = 2.1e9 N, so M^2/(EI EA) = (2 pi/L)^2 EI/EA = 3.29e-4 for the full circle
constexpr double kL = 10.0, kE = 2.1e11, kA = 0.01, kI = 8.33e-6;
constexpr double kEI = kE * kI, kEA = kE * kA;
constexpr double kM = 2.0 * kPi * kEI / kL;

struct RollUp {
  Vec3 tip;                 // tip position (m); the root is at the origin
  double length = 0.0;      // axis length int |r'| dx (m)
  double moment_min = 0.0;  // smallest and largest bending moment output over the
  double moment_max = 0.0;  // Gauss-point stations (N m)
  int increments = 0;
};

// bending_model empty: the default (the key is left out of the file)
RollUp roll_up(int elements, const std::string& bending_model) {
  const std::string model_key =
      bending_model.empty() ? std::string() : ", bending_model: " + bending_model;
  const std::string text = fmt::format(
      R"(
environment: {{gravity: 0}}
bodies:
  beam: {{type: ancf_beam, start: [0, 0, 0], end: [{L}, 0, 0], elements: {n}, area: {A},
          second_moment: {I}, youngs_modulus: {E}, density: 7850{key}}}
supports:
  - {{body: beam, node: start, type: clamped}}
loads:
  - {{type: point_force, body: beam, node: end, moment: [0, 0, {M:.17g}]}}
statics: {{load_steps: 16, tolerance: 1e-12}}
)",
      fmt::arg("L", kL), fmt::arg("n", elements), fmt::arg("A", kA), fmt::arg("I", kI),
      fmt::arg("E", kE), fmt::arg("key", model_key), fmt::arg("M", kM));
  io::Model model = io::load_model_text(text, "roll_up.yaml");
  State s = model.system->initial_state();
  RollUp out;
  out.increments = solve_statics(*model.system, s, model.statics).increments;
  const auto& beam = dynamic_cast<const AncfBeam&>(*model.system->find_body("beam"));
  out.tip = s.q.segment<3>(beam.node_index(elements));
  // axis length: 8 Gauss points per element integrate |r'|, a smooth function of x within
  // 1e-6 of a constant, to round-off
  const math::QuadratureRule rule = math::gauss_legendre_unit(8);
  for (int el = 0; el < elements; ++el) {
    const ancf_cable::Vec12 e = beam.element_coordinates(s.q, el);
    const double l = beam.element_length(el);
    for (std::size_t k = 0; k < rule.points.size(); ++k)
      out.length +=
          rule.weights[k] * l *
          (ancf_cable::relative_nodes(e) * ancf_cable::shape_dx(rule.points[k], l)).norm();
  }
  const post::BeamResults results(beam, io::pipe_pressure(model, beam));
  MatX table;
  results.compute(s, table);
  out.moment_min = std::numeric_limits<double>::infinity();
  out.moment_max = -out.moment_min;
  for (Index i = 0; i < results.num_stations(); ++i) {
    if (results.stations()[static_cast<std::size_t>(i)].node >= 0) continue;
    const double m = table(i, static_cast<int>(post::BeamQuantity::kMoment));
    out.moment_min = std::min(out.moment_min, m);
    out.moment_max = std::max(out.moment_max, m);
  }
  return out;
}

}  // namespace

// The default exact model closes the circle. 32 elements: the tip at the root within 1e-4 L
// (the issue's figure; measured 6.2e-6 L). The axis length: the continuum solution keeps it
// exactly (lambda = 1); what is left is the mesh's error, measured -2.12e-8 L with 32
// elements and -1.76e-9 L with 64 (it falls about as l^4, like the tip error, and is 300
// times smaller). The issue's 1e-8 is therefore asserted with 64 elements; with 32 the
// bound is 3e-8 (the measured value with a 40 % margin). Either is four orders of magnitude
// below the 3.3e-4 of the thesis's curvature (next test). Statics converges to 1e-12 of
// the forces: a strain error of order 1e-12, far below both. The moment output equals the
// applied couple within 2e-5 at every Gauss point (the mesh error of the curvature of 32
// cubic elements: -1.2e-5 .. +3.9e-6 measured; -3.2e-4 .. +1.9e-4 with 16).
TEST(CantileverRollUp, DefaultModelClosesTheCircleWithoutStretching) {
  for (int n : {32, 64}) {
    const RollUp r = roll_up(n, "");
    const double tip_error = r.tip.norm() / kL;
    const double stretch = r.length / kL - 1.0;
    std::printf(
        "  default (exact), %d elements: |tip - root| = %.3e L, axis length - L = %.3e L,"
        " moment %.9g .. %.9g N m (M = %.9g), %d increments\n",
        n, tip_error, stretch, r.moment_min, r.moment_max, kM, r.increments);
    EXPECT_LT(tip_error, 1e-4) << n;
    EXPECT_LT(std::abs(stretch), n == 32 ? 3e-8 : 1e-8) << n;
    EXPECT_NEAR(r.moment_min / kM, 1.0, 2e-5) << n;
    EXPECT_NEAR(r.moment_max / kM, 1.0, 2e-5) << n;
  }
}

// `bending_model: exact` is the default
TEST(CantileverRollUp, ExactIsTheDefault) {
  const RollUp a = roll_up(8, ""), b = roll_up(8, "exact");
  EXPECT_EQ((a.tip - b.tip).norm(), 0.0);
  EXPECT_EQ(a.length, b.length);
}

// The thesis's curvature per deformed length (eq. 14) stretches the axis by
// lambda - 1 = sqrt(1 + 2 M^2/(EI EA)) - 1 = 3.288e-4 and overlaps the circle's ends, as
// the closed form above predicts. 32 elements: stretch within 1 % of the closed form (it
// converges slowly from below: -3.6, -0.83, -0.38, -0.18 % at 8, 16, 32, 64 elements),
// tip within 1e-4 L of the closed-form circle (measured 7.3e-6 L). A regression of the
// default to eq. (14) would fail the previous test by four orders of magnitude in the
// stretch.
TEST(CantileverRollUp, ThesisCurvatureStretchesTheAxis) {
  const RollUp r = roll_up(32, "exact_deformed");
  const double lambda = std::sqrt(1.0 + 2.0 * kM * kM / (kEI * kEA));
  const double rho = kEI / (kM * lambda), angle = 2.0 * kPi * lambda * lambda;
  const Vec3 tip(rho * std::sin(angle), rho * (1.0 - std::cos(angle)), 0.0);
  const double stretch = r.length / kL - 1.0;
  std::printf(
      "  exact_deformed, 32 elements: axis length - L = %.6e L (closed form %.6e),"
      " M^2/(EI EA) = %.6e; tip %.6e L from the root, %.3e L from the closed form\n",
      stretch, lambda - 1.0, kM * kM / (kEI * kEA), r.tip.norm() / kL, (r.tip - tip).norm() / kL);
  EXPECT_NEAR(stretch / (lambda - 1.0), 1.0, 1e-2);
  EXPECT_GT(stretch, 1e-4);  // the order of magnitude: 3.3e-4
  EXPECT_LT((r.tip - tip).norm() / kL, 1e-4);
  // the ends overlap: the tip misses the root by rho * (4 pi (lambda - 1)) ~ 6.6e-4 L
  EXPECT_GT(r.tip.norm() / kL, 5e-4);
  // its moment output EI kappa = EI theta'/lambda = M lambda (eq. 14's curvature), within
  // 1e-3 at the Gauss points (its curvature scatters by -5.9e-4 .. +5.1e-4 with 32 elements)
  EXPECT_NEAR(r.moment_min / (kM * lambda), 1.0, 1e-3);
  EXPECT_NEAR(r.moment_max / (kM * lambda), 1.0, 1e-3);
}

// Mesh convergence of the tip error, default model. Cubic Hermite interpolation of a smooth
// curve errs by O(l^4) in position (l the element length), so halving l divides the tip
// error by 2^4 = 16. Measured orders log2(e_n / e_2n): 4.30 (8 -> 16 elements, each element
// of the coarse mesh spans 45 degrees: before the asymptotic range), 3.995 (16 -> 32),
// 3.99 (32 -> 64). Asserted: 4 +- 0.1 from 16 elements on, 4 +- 0.5 for 8 -> 16.
TEST(CantileverRollUp, TipErrorConvergesAtTheOrderOfCubicHermiteInterpolation) {
  double previous = 0.0;
  for (int n : {8, 16, 32, 64}) {
    const double err = roll_up(n, "").tip.norm() / kL;
    if (previous > 0.0) {
      const double order = std::log2(previous / err);
      std::printf("  %2d elements: |tip - root| = %.4e L, observed order %.3f\n", n, err, order);
      EXPECT_NEAR(order, 4.0, n == 16 ? 0.5 : 0.1) << n << " elements";
    } else {
      std::printf("  %2d elements: |tip - root| = %.4e L\n", n, err);
    }
    previous = err;
  }
}
