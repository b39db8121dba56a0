// Imposed motion (model/motion.hpp, table_motion.hpp, moving_marker.hpp) and the rheonomic
// constraints that follow it: every time derivative is checked against central finite
// differences of the function itself (kernel identities, DESIGN.md section 5, rung 1).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "seaflex/constraints/joint.hpp"
#include "seaflex/constraints/prescribed_coordinates.hpp"
#include "seaflex/elements/ancf_beam.hpp"
#include "seaflex/elements/rigid_body.hpp"
#include "seaflex/forces/winch.hpp"
#include "seaflex/math/rotation.hpp"
#include "seaflex/model/moving_marker.hpp"
#include "seaflex/model/table_motion.hpp"
#include "seaflex/system/system.hpp"

using namespace seaflex;

namespace {

Vec6 six(double a, double b, double c, double d, double e, double f) {
  return (Vec6() << a, b, c, d, e, f).finished();
}

// a motion with every degree of freedom moving and large angles
std::shared_ptr<const Motion> busy_motion() {
  return std::make_shared<HarmonicMotion>(six(1.0, -0.5, 2.0, 0.4, -0.3, 0.8),
                                          six(7.0, 5.0, 9.0, 6.0, 8.0, 11.0),
                                          six(0.1, 0.2, 0.3, 0.4, 0.5, 0.6));
}

}  // namespace

// R and its derivatives: R equals the roll-pitch-yaw rotation of math/rotation.hpp, R_t and
// R_tt equal central differences (step 1e-5 s: truncation ~1e-10, round-off ~1e-11)
TEST(Motion, PoseDerivativesMatchFiniteDifferences) {
  const auto m = busy_motion();
  const double h = 1e-5;
  for (double t : {0.3, 2.1, 7.7}) {
    const MotionSample s = m->sample(t);
    const MotionPose p = compute_motion_pose(s);
    EXPECT_LT((p.R - math::rotation_from_roll_pitch_yaw(s.x[3], s.x[4], s.x[5])).norm(), 1e-14);
    const MotionPose a = compute_motion_pose(m->sample(t - h));
    const MotionPose b = compute_motion_pose(m->sample(t + h));
    EXPECT_LT((p.R_t - (b.R - a.R) / (2 * h)).norm(), 1e-8);
    EXPECT_LT((p.R_tt - (b.R_t - a.R_t) / (2 * h)).norm(), 1e-8);
    EXPECT_LT((p.p_t - (b.p - a.p) / (2 * h)).norm(), 1e-8);
    EXPECT_LT((p.p_tt - (b.p_t - a.p_t) / (2 * h)).norm(), 1e-8);
  }
}

// Motion::pose remembers the last few (motion, t) per thread: it must give every motion its own
// pose, bit for bit compute_motion_pose(sample(t)), however the calls interleave: six motions
// (more than the cache's four entries) asked in turn at repeated and new times, a copy of a
// motion (its own identity), and motions made after others were destroyed (a new object at a
// freed address must not find the old one's entry)
TEST(Motion, CachedPoseEqualsTheComputedOne) {
  auto expect_same = [](const MotionPose& a, const MotionPose& b) {
    EXPECT_EQ(a.p, b.p);
    EXPECT_EQ(a.p_t, b.p_t);
    EXPECT_EQ(a.p_tt, b.p_tt);
    EXPECT_EQ(a.R, b.R);
    EXPECT_EQ(a.R_t, b.R_t);
    EXPECT_EQ(a.R_tt, b.R_tt);
  };
  std::vector<std::shared_ptr<const Motion>> motions;
  for (int i = 0; i < 6; ++i)
    motions.push_back(std::make_shared<HarmonicMotion>(six(1.0 + i, -0.5, 2.0, 0.4, -0.3 * i, 0.8),
                                                       six(7.0, 5.0, 9.0 + i, 6.0, 8.0, 11.0),
                                                       six(0.1 * i, 0.2, 0.3, 0.4, 0.5, 0.6)));
  for (int round = 0; round < 3; ++round)
    for (double t : {0.5, 0.5, 1.25, 0.5})
      for (const auto& m : motions) expect_same(m->pose(t), compute_motion_pose(m->sample(t)));
  const HarmonicMotion original(six(1, 2, 3, 0.1, 0.2, 0.3), six(5, 6, 7, 8, 9, 10),
                                six(0, 0, 0, 0, 0, 0));
  HarmonicMotion copy = original;
  expect_same(copy.pose(2.0), compute_motion_pose(original.sample(2.0)));
  copy = HarmonicMotion(six(3, 2, 1, 0.3, 0.2, 0.1), six(5, 6, 7, 8, 9, 10), six(1, 1, 1, 1, 1, 1));
  expect_same(copy.pose(2.0), compute_motion_pose(copy.sample(2.0)));
  for (int i = 0; i < 20; ++i) {
    auto m = std::make_shared<HarmonicMotion>(six(0.1 * i, 0, 0, 0, 0, 0.01 * i),
                                              six(3, 3, 3, 3, 3, 3), six(0, 0, 0, 0, 0, 0));
    expect_same(m->pose(1.0), compute_motion_pose(m->sample(1.0)));
  }
}

// the quintic ramp: zero displacement, velocity and acceleration at t = 0, the inner motion
// after the ramp, and derivatives equal to central differences inside it
TEST(Motion, RampStartsFromRestAndIsSmooth) {
  const RampedMotion m(busy_motion(), 4.0);
  const MotionSample s0 = m.sample(0.0);
  EXPECT_EQ(s0.x.norm() + s0.x_t.norm() + s0.x_tt.norm(), 0.0);
  const MotionSample after = m.sample(5.0), inner = busy_motion()->sample(5.0);
  EXPECT_EQ((after.x - inner.x).norm(), 0.0);
  const double h = 1e-5;
  for (double t : {0.5, 2.0, 3.9}) {
    const MotionSample s = m.sample(t), a = m.sample(t - h), b = m.sample(t + h);
    EXPECT_LT((s.x_t - (b.x - a.x) / (2 * h)).norm(), 1e-8);
    EXPECT_LT((s.x_tt - (b.x_t - a.x_t) / (2 * h)).norm(), 1e-8);
  }
}

// the natural cubic spline: exact for linear data, through every knot, with continuous
// first and second derivatives at the knots (the property the constraint's gamma needs)
TEST(Motion, TableSplineIsTwiceContinuouslyDifferentiable) {
  std::vector<double> t{0.0, 1.0, 2.5, 3.0, 5.0};
  std::vector<Vec6> v;
  for (double ti : t) v.push_back(six(std::sin(ti), ti * ti, 2.0 * ti + 1.0, 0.1 * ti, 0.0, -ti));
  const TableMotion m(t, v);
  for (std::size_t i = 0; i < t.size(); ++i)
    EXPECT_LT((m.sample(t[i]).x - v[i]).norm(), 1e-12) << "knot " << i;
  EXPECT_NEAR(m.sample(1.7).x[2], 2.0 * 1.7 + 1.0, 1e-12);  // linear data: exact
  EXPECT_NEAR(m.sample(1.7).x_t[2], 2.0, 1e-12);
  EXPECT_NEAR(m.sample(1.7).x_tt[2], 0.0, 1e-12);
  const double e = 1e-9;
  for (std::size_t i = 1; i + 1 < t.size(); ++i) {
    const MotionSample a = m.sample(t[i] - e), b = m.sample(t[i] + e);
    EXPECT_LT((a.x_t - b.x_t).norm(), 1e-7) << "knot " << i;
    EXPECT_LT((a.x_tt - b.x_tt).norm(), 1e-7) << "knot " << i;
  }
  const double h = 1e-5;
  const MotionSample s = m.sample(2.0), a = m.sample(2.0 - h), b = m.sample(2.0 + h);
  EXPECT_LT((s.x_t - (b.x - a.x) / (2 * h)).norm(), 1e-8);
  EXPECT_LT((s.x_tt - (b.x_t - a.x_t) / (2 * h)).norm(), 1e-7);
  EXPECT_THROW(TableMotion({0.0, 0.0}, {Vec6::Zero(), Vec6::Zero()}), std::invalid_argument);
  EXPECT_THROW(TableMotion({0.0}, {Vec6::Zero()}), std::invalid_argument);
}

// a fixed joint from a moving marker to a rigid body: along a trajectory q(t) = q0 + v t +
// a t^2 / 2, dC/dt = C_q v + C_t and d2C/dt2 = C_q a - gamma (thesis eq. 133), by central
// differences of C itself (step 1e-4 s: errors ~1e-7 of O(1) values)
TEST(Motion, MovingMarkerJointTimeDerivatives) {
  System sys;
  RigidBodyInitial init;
  init.position = Vec3(1.0, 2.0, -3.0);
  init.orientation = math::rotation_from_roll_pitch_yaw(0.1, 0.2, 0.3);
  auto body =
      std::make_unique<RigidBody>("vessel", 1000.0, Mat3(Vec3(10, 20, 30).asDiagonal()), init);
  const RigidBody& b = *body;
  sys.add_body(std::move(body));
  auto from = std::make_unique<MovingMarker>(busy_motion(), Vec3(0.5, 0.0, 0.0), init.position,
                                             init.orientation);
  auto to = std::make_unique<RigidBodyMarker>(b, Vec3(0.0, 0.0, 0.0));
  sys.add_constraint(
      std::make_unique<Joint>("m", JointType::kFixed, std::move(from), std::move(to)));
  sys.finalize();
  State s0 = sys.initial_state();
  const Index n = sys.num_coordinates();
  VecX v(n), a(n);
  for (Index i = 0; i < n; ++i) {
    v[i] = 0.3 * std::sin(1.0 + i);
    a[i] = 0.2 * std::cos(2.0 + i);
  }
  const double t0 = 1.3, h = 1e-4;
  auto at = [&](double dt) {
    State s = s0;
    s.t = t0 + dt;
    s.q = s0.q + v * dt + 0.5 * a * dt * dt;
    s.v = v + a * dt;
    return s;
  };
  DaeEval e = sys.make_eval(), ea = sys.make_eval(), eb = sys.make_eval();
  DaeRequest req;
  req.forces = false;
  req.matrix = true;
  sys.evaluate(at(0.0), req, e);
  sys.evaluate(at(-h), req, ea);
  sys.evaluate(at(h), req, eb);
  const MatX K = MatX(e.kkt.matrix());
  const VecX Cq_a = K.bottomLeftCorner(sys.num_constraints(), n) * a;
  const VecX C0 = e.C;
  const VecX dC = (eb.C - ea.C) / (2 * h);
  const VecX ddC = (eb.C - 2.0 * C0 + ea.C) / (h * h);
  EXPECT_LT((e.Cdot - dC).lpNorm<Eigen::Infinity>(), 1e-6);
  EXPECT_LT((Cq_a - e.gamma - ddC).lpNorm<Eigen::Infinity>(), 1e-5);
  // C_t alone: at frozen q the rate of C is C_t
  State f0 = at(0.0), fa = f0, fb = f0;
  fa.t -= h;
  fb.t += h;
  fa.v.setZero();
  f0.v.setZero();
  sys.evaluate(f0, req, e);
  sys.evaluate(fa, req, ea);
  sys.evaluate(fb, req, eb);
  EXPECT_LT((e.Cdot - (eb.C - ea.C) / (2 * h)).lpNorm<Eigen::Infinity>(), 1e-6);
}

// a beam support on a motion: C = q - f(t), C_t = -f', gamma = f'' (points and slopes)
TEST(Motion, PrescribedCoordinatesTimeDerivatives) {
  System sys;
  BeamSection section = BeamSection::pipe(0.3, 0.2, 2e11, 7850.0);
  auto beam = std::make_unique<AncfBeam>(
      "riser", BeamGeometry::straight(Vec3(0, 0, -10), Vec3(3, 0, 0), 2), section, BeamOptions{});
  const AncfBeam& bm = *beam;
  sys.add_body(std::move(beam));
  const auto& g = bm.initial_geometry();
  std::vector<PrescribedCoordinates::Row> rows;
  for (int c = 0; c < 6; ++c)
    rows.push_back({12 + c, c < 3, c < 3 ? g.positions[2] : g.slopes[2], c % 3, "c"});
  sys.add_constraint(std::make_unique<PrescribedCoordinates>("riser.n2.support", bm, rows,
                                                             busy_motion(), Vec3(1, 0, 0)));
  sys.finalize();
  State s = sys.initial_state();
  s.v.setZero();
  const double t0 = 2.2, h = 1e-4;
  DaeEval e = sys.make_eval(), ea = sys.make_eval(), eb = sys.make_eval();
  DaeRequest req;
  req.forces = false;
  auto eval_at = [&](double t, DaeEval& out) {
    s.t = t;
    sys.evaluate(s, req, out);
  };
  eval_at(t0, e);
  eval_at(t0 - h, ea);
  eval_at(t0 + h, eb);
  EXPECT_LT((e.Cdot - (eb.C - ea.C) / (2 * h)).lpNorm<Eigen::Infinity>(), 1e-6);
  // C_q a = gamma with a = 0 at frozen q: d2C/dt2 = -gamma
  EXPECT_LT((-e.gamma - (eb.C - 2.0 * e.C + ea.C) / (h * h)).lpNorm<Eigen::Infinity>(), 1e-5);
}

// the winch: a constant rate from its start, and a table whose rate is the spline's slope
TEST(Motion, WinchLengthAndRate) {
  const Winch w = Winch::constant_rate(-0.4, 2.0);
  EXPECT_EQ(w.change(1.0), 0.0);
  EXPECT_DOUBLE_EQ(w.change(4.5), -1.0);
  EXPECT_DOUBLE_EQ(w.rate(4.5), -0.4);
  const Winch t = Winch::table({0.0, 10.0, 20.0}, {0.0, 5.0, 10.0});
  EXPECT_NEAR(t.change(13.0), 6.5, 1e-12);
  EXPECT_NEAR(t.rate(13.0), 0.5, 1e-12);
}
