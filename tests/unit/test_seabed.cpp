// The seabed's geometry (hydro/seabed.hpp) and the seabed contact force's exact tangents
// (forces/seabed_contact.hpp): d Q/d q and d Q/d v of a beam lying partly on a flat and on
// a sloped seabed, sliding with anisotropic friction, against central differences of Q.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "seaflex/elements/ancf_beam.hpp"
#include "seaflex/forces/seabed_contact.hpp"
#include "seaflex/hydro/seabed.hpp"
#include "seaflex/system/system.hpp"

using namespace seaflex;

namespace {
constexpr double kDeg = std::numbers::pi / 180.0;
}

TEST(Seabed, FlatAndPlane) {
  const auto flat = hydro::Seabed::flat(200.0);
  const auto p = flat.at(13.0, -4.0);
  EXPECT_EQ(p.height, -200.0);
  EXPECT_EQ(p.normal(), Vec3(0, 0, 1));
  EXPECT_DOUBLE_EQ(p.penetration(Vec3(1, 2, -200.25)), 0.25);
  // a plane falling 10 deg towards 30 deg from x: the height along the downhill direction
  const auto plane = hydro::Seabed::plane(100.0, 10 * kDeg, 30 * kDeg);
  const Vec3 down(std::cos(30 * kDeg), std::sin(30 * kDeg), 0.0);
  const double s = 50.0;
  const auto q = plane.at(s * down.x(), s * down.y());
  EXPECT_NEAR(q.height, -100.0 - s * std::tan(10 * kDeg), 1e-12);
  // the normal leans uphill by the slope; the penetration is the distance to the plane
  EXPECT_NEAR(q.normal().z(), std::cos(10 * kDeg), 1e-15);
  // the normal leans downhill (the slope faces down the hill)
  EXPECT_NEAR(q.normal().dot(down), std::sin(10 * kDeg), 1e-15);
  const Vec3 on(s * down.x(), s * down.y(), q.height);
  const Vec3 below = on - 0.3 * q.normal();
  EXPECT_NEAR(plane.at(below.x(), below.y()).penetration(below), 0.3, 1e-12);
  // a point across the slope sits at the origin's depth
  const Vec3 across(-down.y(), down.x(), 0.0);
  EXPECT_NEAR(plane.at(40 * across.x(), 40 * across.y()).height, -100.0, 1e-12);
}

TEST(Seabed, GridIsBilinearAndHoldsItsEdges) {
  // depths of the plane d = 50 + 0.1 x - 0.2 y on a 3 x 2 grid: bilinear interpolation
  // reproduces a plane exactly, inside every cell
  const std::vector<double> xs{0, 10, 30}, ys{0, 20};
  std::vector<double> depths;
  for (double y : ys)
    for (double x : xs) depths.push_back(50 + 0.1 * x - 0.2 * y);
  const auto g = hydro::Seabed::grid(xs, ys, depths);
  for (const auto& [x, y] : {std::pair{3.0, 7.0}, {25.0, 19.0}, {10.0, 0.0}, {29.9, 0.1}}) {
    const auto p = g.at(x, y);
    EXPECT_NEAR(p.height, -(50 + 0.1 * x - 0.2 * y), 1e-12);
    EXPECT_NEAR(p.hx, -0.1, 1e-12);
    EXPECT_NEAR(p.hy, 0.2, 1e-12);
  }
  // outside, the edge value continues (no slope across the edge)
  const auto out = g.at(40.0, 10.0);
  EXPECT_NEAR(out.height, -(50 + 3.0 - 2.0), 1e-12);
  EXPECT_EQ(out.hx, 0.0);
  EXPECT_NEAR(out.hy, 0.2, 1e-12);
  // a twisted cell: the value at the centre is the mean of its corners
  const auto t = hydro::Seabed::grid({0, 1}, {0, 1}, {10, 20, 30, 60});
  EXPECT_NEAR(t.at(0.5, 0.5).height, -30.0, 1e-12);
  EXPECT_THROW(hydro::Seabed::grid({0, 1}, {0, 1}, {10, 20, 30}), std::invalid_argument);
  EXPECT_THROW(hydro::Seabed::grid({0, 0}, {0, 1}, {10, 20, 30, 40}), std::invalid_argument);
  EXPECT_THROW(hydro::Seabed::grid({0, 1}, {0, 1}, {10, -20, 30, 40}), std::invalid_argument);
  EXPECT_THROW(hydro::Seabed::flat(-1.0), std::invalid_argument);
}

namespace {

// a 4-element beam crossing the seabed (its start half buried, its end above), moving;
// its material is soft (E = 1 Pa) so that the contact's tangent is the whole matrix
struct ContactCase {
  std::unique_ptr<System> sys;
  State s;
};

ContactCase make_case(std::shared_ptr<const hydro::Seabed> seabed, double mu_a, double mu_l) {
  ContactCase c;
  c.sys = std::make_unique<System>();
  auto& beam = static_cast<AncfBeam&>(c.sys->add_body(std::make_unique<AncfBeam>(
      "line", BeamGeometry::straight(Vec3(0, 0, -100.4), Vec3(20, 3, -99.3), 4),
      BeamSection::pipe(0.3, 0.2, 1.0, 7850), BeamOptions{})));
  SeabedContactProperties p;
  p.normal_stiffness = 2e5;
  p.damping = 0.3;
  p.friction_axial = mu_a;
  p.friction_lateral = mu_l;
  p.slip_velocity = 0.05;
  c.sys->add_force(std::make_unique<SeabedContact>("line.seabed", beam, std::move(seabed), p, 0.3,
                                                   beam.section(0).mass_per_length()));
  c.sys->finalize();
  c.s = c.sys->initial_state();
  // a bent, moving configuration: slides at about the slip velocity, sinking and rising
  std::srand(7);
  c.s.q += 0.05 * VecX::Random(c.s.q.size());
  c.s.v = 0.08 * VecX::Random(c.s.v.size());
  return c;
}

// largest difference between the matrix (scale kq = -1 or kv = -1: +dQ/dq, +dQ/dv) and the
// central differences of Q, relative to the matrix's norm
double tangent_error(ContactCase& c, bool velocity) {
  DaeEval ev = c.sys->make_eval();
  const Index n = c.sys->num_coordinates();
  DaeRequest req;
  req.matrix = true;
  (velocity ? req.scales.kv : req.scales.kq) = -1.0;
  c.sys->evaluate(c.s, req, ev);
  const MatX A = MatX(ev.kkt.matrix()).topLeftCorner(n, n);
  MatX fd(n, n);
  DaeEval ev2 = c.sys->make_eval();
  DaeRequest fr;
  for (Index j = 0; j < n; ++j) {
    const double h = 1e-7;
    State sp = c.s, sm = c.s;
    (velocity ? sp.v : sp.q)[j] += h;
    (velocity ? sm.v : sm.q)[j] -= h;
    c.sys->evaluate(sp, fr, ev2);
    const VecX Qp = ev2.Q;
    c.sys->evaluate(sm, fr, ev2);
    fd.col(j) = (Qp - ev2.Q) / (2 * h);
  }
  EXPECT_GT(A.norm(), 0.0);
  return (A - fd).norm() / A.norm();
}

}  // namespace

// The matrix equals the central differences of Q to 1e-6 of its norm (h = 1e-7: the
// truncation error of the differences, ~h^2 times the third derivative, and their round-off
// ~1e-16 |Q|/h, are both below 1e-7 of the norm; the touchdown points move with q but the
// force vanishes there, so Q stays differentiable).
TEST(SeabedContactTangent, MatchesFiniteDifferences) {
  const auto flat = std::make_shared<const hydro::Seabed>(hydro::Seabed::flat(100.0));
  const auto sloped =
      std::make_shared<const hydro::Seabed>(hydro::Seabed::plane(100.0, 8 * kDeg, 200 * kDeg));
  for (const auto& seabed : {flat, sloped})
    for (const auto& [mu_a, mu_l] : {std::pair{0.0, 0.0}, {0.6, 0.6}, {0.3, 0.9}}) {
      ContactCase c = make_case(seabed, mu_a, mu_l);
      EXPECT_LT(tangent_error(c, false), 1e-6) << "dQ/dq, mu " << mu_a << " " << mu_l;
      EXPECT_LT(tangent_error(c, true), 1e-6) << "dQ/dv, mu " << mu_a << " " << mu_l;
    }
}
