// Verification of rigid bodies (Euler parameters) and joints, models built through the
// C++ API: the torque-free asymmetric body (Dzhanibekov flips, Landau & Lifshitz sec. 37),
// a spatial double pendulum (energy, joint drift), a slider-crank (closed-form kinematics,
// no redundant rows), a cantilever ANCF beam carrying a body on a fixed joint (Euler-
// Bernoulli superposition, elastica, joint reaction), a body hanging at rest (reaction from
// the multipliers) and a compound pendulum on a revolute joint (small-amplitude period).
// Prints the numbers of docs/verification.md.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "analytic.hpp"
#include "seaflex/constraints/coordinate_lock.hpp"
#include "seaflex/constraints/joint.hpp"
#include "seaflex/elements/ancf_beam.hpp"
#include "seaflex/elements/rigid_body.hpp"
#include "seaflex/forces/gravity.hpp"
#include "seaflex/integrators/rk4_augmented.hpp"
#include "seaflex/solvers/statics.hpp"
#include "seaflex/system/system.hpp"

using namespace seaflex;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = 180.0 / kPi;
constexpr double kG = 9.81;

RigidBody& add_rigid(System& sys, const std::string& name, double mass, const Mat3& inertia,
                     const RigidBodyInitial& init) {
  return static_cast<RigidBody&>(
      sys.add_body(std::make_unique<RigidBody>(name, mass, inertia, init)));
}

// adds a joint and returns it (the System owns it)
Joint& add_joint(System& sys, const std::string& name, JointType type, std::unique_ptr<Marker> from,
                 std::unique_ptr<Marker> to) {
  auto joint = std::make_unique<Joint>(name, type, std::move(from), std::move(to));
  Joint& ref = *joint;
  sys.add_constraint(std::move(joint));
  return ref;
}

std::unique_ptr<Marker> ground(const Vec3& p, const Mat3& frame = Mat3::Identity()) {
  return std::make_unique<GroundMarker>(p, frame);
}

std::unique_ptr<Marker> on(const RigidBody& b, const Vec3& u,
                           const Mat3& frame = Mat3::Identity()) {
  return std::make_unique<RigidBodyMarker>(b, u, frame);
}

// first multiplier row of a constraint: rows are numbered in order of addition
Index row_offset(const System& sys, const Constraint& c) {
  Index off = 0;
  for (const auto& k : sys.constraints()) {
    if (k.get() == &c) return off;
    off += k->num_rows();
  }
  ADD_FAILURE() << "constraint not in the system";
  return -1;
}

// slender rod of mass m and length l along body axis `axis`, radius rad
Mat3 rod_inertia(double m, double l, double rad, int axis) {
  const double t = m * (3 * rad * rad + l * l) / 12.0;
  Mat3 J = Vec3::Constant(t).asDiagonal();
  J(axis, axis) = 0.5 * m * rad * rad;
  return J;
}

}  // namespace

// 1. Torque-free asymmetric body, principal inertias 1, 2, 3 kg m^2, mass 1 kg, no gravity,
// spun at 1 rad/s about the intermediate axis with a 0.02 rad/s perturbation on the other
// two: the intermediate axis is unstable and the body flips periodically (Dzhanibekov).
// The intermediate axis is put on body z (inertia diag(1, 3, 2)) and the angular momentum
// along world z, so the angle theta of the body z axis to world z is the middle Z-X-Z
// Euler angle of thesis eq. (136); each flip drives it from ~0 to ~180 deg, through both
// singular attitudes of that parametrization (theta = 0, pi: the angle rates ~ 1/sin theta
// blow up). Euler parameters have no such attitude.
// Asserted over 100 s of RK4, h = 2e-3 s, projection:
// - kinetic energy and the world angular momentum vector to 1e-6 relative (RK4's local
//   error ~ (w h)^5 / 120 ~ 3e-16 per step at w ~ 1 rad/s, and the projection onto
//   |p| = 1, p.p' = 0 changes v by the drift only: the conservation is near round-off);
// - at least 3 flips (6 occur: one every 17.1 s), theta within 3 deg of 0 and 180 deg
//   (its extremes are 1.4 deg from them: the angle of the intermediate axis to the
//   momentum at the turning points, set by the perturbation);
// - the mean time between flips (sign changes of the intermediate axis' component along
//   the momentum, interpolated linearly) equals 2 K(k) / (dtau/dt) of the elliptic-function
//   solution within 1e-5 relative: the period is a function of the conserved E and M^2
//   only (their errors, ~1e-12, reach k'^2 amplified by M^2 / (M^2 - 2 E I2) ~ 5e3, and
//   K(k) changes by half the relative change of k'^2), and the linear interpolation of a
//   crossing is exact to O(h^2 w2'') with w2'' = 0 at a crossing of sn.
TEST(RigidBodies, TorqueFreeIntermediateAxisFlips) {
  const Mat3 J = Vec3(1.0, 3.0, 2.0).asDiagonal();  // intermediate (2) on body z
  const double eps = 0.02;
  const Vec3 wb(eps, eps, 1.0);  // body axes
  const Vec3 Lb = J * wb;
  // initial attitude: the momentum along world z (A0 Lb = |L| e_z)
  const Mat3 A0 = math::frame_from_axis(Lb).transpose();
  System sys;
  RigidBodyInitial init;
  init.orientation = A0;
  init.angular_velocity = A0 * wb;
  const RigidBody& body = add_rigid(sys, "top", 1.0, J, init);
  sys.finalize();
  State s = sys.initial_state();
  Rk4Augmented rk4;
  const double T0 = sys.energies(s).kinetic;
  const Vec3 L0 = body.angular_momentum(s);
  ASSERT_NEAR(L0.normalized().z(), 1.0, 1e-14);
  const Vec3 Lhat = L0.normalized();

  const double h = 2e-3, duration = 100.0;
  const long steps = std::lround(duration / h);
  double dE = 0.0, dL = 0.0, theta_min = 180.0, theta_max = 0.0;
  std::vector<double> flips;
  double prev = (body.orientation(s).col(2)).dot(Lhat);
  for (long k = 1; k <= steps; ++k) {
    const StepReport rep = rk4.step(sys, s, h);
    ASSERT_TRUE(rep.ok) << rep.message;
    dE = std::max(dE, std::abs(sys.energies(s).kinetic - T0) / T0);
    dL = std::max(dL, (body.angular_momentum(s) - L0).norm() / L0.norm());
    const Mat3 A = body.orientation(s);
    const double c = A.col(2).dot(Lhat);  // the intermediate axis along the momentum
    const double theta = std::acos(std::clamp(A(2, 2), -1.0, 1.0)) * kDeg;  // Z-X-Z theta
    theta_min = std::min(theta_min, theta);
    theta_max = std::max(theta_max, theta);
    if ((c > 0) != (prev > 0)) flips.push_back(s.t - h * c / (c - prev));
    prev = c;
  }
  // principal axes sorted: I1 = 1 (body x), I2 = 2 (body z), I3 = 3 (body y)
  const double T_flip = analytic::torque_free_flip_interval(1.0, 2.0, 3.0, wb.x(), wb.z(), wb.y());
  ASSERT_GE(flips.size(), 3u);
  const double T_mean = (flips.back() - flips.front()) / static_cast<double>(flips.size() - 1);
  std::printf(
      "\n  torque-free body, 100 s, h = %g s: max |dT|/T = %.2e, max |dL|/|L| = %.2e; %zu flips, "
      "Z-X-Z theta from %.3f to %.3f deg; mean flip interval %.6f s, elliptic-function "
      "solution %.6f s (%+.2e)\n",
      h, dE, dL, flips.size(), theta_min, theta_max, T_mean, T_flip, T_mean / T_flip - 1);
  EXPECT_LT(dE, 1e-6);
  EXPECT_LT(dL, 1e-6);
  EXPECT_GE(flips.size(), 3u);
  EXPECT_LT(theta_min, 3.0);
  EXPECT_GT(theta_max, 177.0);
  EXPECT_NEAR(T_mean / T_flip, 1.0, 1e-5);
}

// 2. Spatial double pendulum: two rods (1 m, 2 kg and 0.8 m, 1.5 kg, radius 2 cm, full rod
// inertia), ball joint to ground and ball joint between them, gravity -9.81 z, started in a
// 3-D configuration with angular velocities out of every plane (chaotic motion). 20 s of RK4,
// h = 1e-3 s, projection. Asserted: total energy (kinetic + gravity) within 0.1 % of the
// energy scale m1 g L1/2 + m2 g (L1 + L2/2) (the depth of the hanging chain, 30.4 J) at
// every step; both joints' separation |p_to - p_from| below 1e-8 m at every step (the
// projection holds it at ~1e-15 m).
TEST(RigidBodies, SpatialDoublePendulumConservesEnergy) {
  const double L1 = 1.0, m1 = 2.0, L2 = 0.8, m2 = 1.5, rad = 0.02;
  const Mat3 A1 = math::rotation_from_roll_pitch_yaw(0.9, 0.4, 0.0);
  const Mat3 A2 = math::rotation_from_roll_pitch_yaw(-1.2, 0.7, 0.5);
  const Vec3 w1(0.5, -1.0, 2.0), w2(-1.5, 2.0, 0.7);  // rad/s, world
  // rods along body z; the top end of each rod is its joint
  RigidBodyInitial i1, i2;
  i1.orientation = A1;
  i1.position = -A1 * Vec3(0, 0, 0.5 * L1);
  const Vec3 P1 = i1.position + A1 * Vec3(0, 0, -0.5 * L1);  // elbow
  i1.angular_velocity = w1;
  i1.velocity = w1.cross(i1.position);
  i2.orientation = A2;
  i2.position = P1 - A2 * Vec3(0, 0, 0.5 * L2);
  i2.angular_velocity = w2;
  i2.velocity = w1.cross(P1) + w2.cross(i2.position - P1);

  System sys;
  const RigidBody& b1 = add_rigid(sys, "upper", m1, rod_inertia(m1, L1, rad, 2), i1);
  const RigidBody& b2 = add_rigid(sys, "lower", m2, rod_inertia(m2, L2, rad, 2), i2);
  const Joint& j1 =
      add_joint(sys, "shoulder", JointType::kBall, ground(Vec3::Zero()), on(b1, {0, 0, 0.5 * L1}));
  const Joint& j2 = add_joint(sys, "elbow", JointType::kBall, on(b1, {0, 0, -0.5 * L1}),
                              on(b2, {0, 0, 0.5 * L2}));
  sys.add_force(std::make_unique<Gravity>(Vec3(0, 0, -kG), std::vector<const Body*>{&b1, &b2}));
  sys.finalize();
  State s = sys.initial_state();
  Rk4Augmented rk4;
  const double E0 = sys.energies(s).total();
  const double scale = m1 * kG * 0.5 * L1 + m2 * kG * (L1 + 0.5 * L2);
  double dE = 0.0, gap = 0.0, kin_max = 0.0, z_min = 0.0, z_max = -10.0;
  const double h = 1e-3;
  for (long k = 1; k <= 20000; ++k) {
    const StepReport rep = rk4.step(sys, s, h);
    ASSERT_TRUE(rep.ok) << rep.message;
    const Energies e = sys.energies(s);
    dE = std::max(dE, std::abs(e.total() - E0));
    kin_max = std::max(kin_max, e.kinetic);
    for (const Joint* j : {&j1, &j2})
      gap = std::max(gap, (j->to().position(s) - j->from().position(s)).norm());
    const double z = 2 * b2.position(s).z() - j2.to().position(s).z();  // lower rod's free end
    z_min = std::min(z_min, z);
    z_max = std::max(z_max, z);
  }
  std::printf(
      "\n  spatial double pendulum, 20 s, h = %g s: max |E - E0| = %.3e J = %.2e %% of %.2f J "
      "(max kinetic %.2f J); max joint gap %.2e m; free end z in [%.2f, %.2f] m\n",
      h, dE, 100 * dE / scale, scale, kin_max, gap, z_min, z_max);
  EXPECT_LT(dE / scale, 1e-3);
  EXPECT_LT(gap, 1e-8);
  EXPECT_GT(kin_max, 0.2 * scale);  // a large motion
}

// 3. Slider-crank in the vertical x-y plane (gravity -9.81 y): crank r = 0.1 m on a
// revolute joint to ground (axis z), connecting rod l = 0.4 m with a ball joint at the crank
// pin and a universal joint at the slider, slider on a prismatic joint along x at offset
// e = 0.03 m. Rows: revolute 5 + ball 3 + universal 4 + prismatic 5 = 17 on 3 x 6 = 18
// degrees of freedom: 1 left, the crank angle. With a ball joint at both rod ends the rod
// would spin freely about its own axis (2 dof; that spin has no stiffness and only the
// rod's tiny axial inertia, 1e-4 kg m^2); the universal joint's cross row (slider axis
// along world z . rod's in-plane normal n) removes exactly that spin: it blocks relative
// rotation about n x z, the rod axis, and lets the rod turn about z. Planar R-R-R-P joints would
// instead give 5 + 5 + 5 + 5 = 20 rows on 18 dof: 3 redundant. Asserted: C_q has full row
// rank (20 incl. the 3 normalization rows, on 21 coordinates).
// Free motion for 2 s from a crank rate of 40 rad/s, initial velocities of all bodies from
// the closed-form kinematics; RK4, h = 1e-3 s. Asserted at every step, with theta the
// crank angle of the simulation: slider x = r cos(theta) + sqrt(l^2 - (r sin(theta) - e)^2)
// within 1e-6 m and its rate within 1e-6 m/s (a kinematic identity: the projection keeps
// the joints closed at ~1e-15 m); total energy within 1e-5 relative (RK4's local error
// ~ (w h)^5 / 120 ~ 3e-9 at the fastest crank rate, 48 rad/s, over 2000 steps).
TEST(RigidBodies, SliderCrankFollowsClosedFormKinematics) {
  const double r = 0.1, l = 0.4, e = 0.03, th0 = 0.3, om0 = 40.0;
  const double mc = 1.0, mr = 2.0, ms = 3.0;
  auto slider_x = [&](double th) {
    return r * std::cos(th) + std::sqrt(l * l - std::pow(r * std::sin(th) - e, 2));
  };
  auto slider_v = [&](double th, double om) {
    const double a = r * std::sin(th) - e;
    return -r * std::sin(th) * om - a * r * std::cos(th) * om / std::sqrt(l * l - a * a);
  };
  const Vec3 z = Vec3::UnitZ();
  // crank: body x along the crank, CG at mid-length
  RigidBodyInitial ic, ir, is;
  const Vec3 dc(std::cos(th0), std::sin(th0), 0);
  ic.orientation = math::rotation_from_roll_pitch_yaw(0, 0, th0);
  ic.position = 0.5 * r * dc;
  ic.angular_velocity = om0 * z;
  ic.velocity = ic.angular_velocity.cross(ic.position);
  // connecting rod: body x from the crank pin to the slider pin
  const Vec3 pin = r * dc, xs(slider_x(th0), e, 0);
  const Vec3 dr = (xs - pin) / l;
  const double phi = std::atan2(dr.y(), dr.x());
  const double phid = -r * std::cos(th0) * om0 / (l * std::cos(phi));  // l sin(phi) = e - r sin(th)
  ir.orientation = math::rotation_from_roll_pitch_yaw(0, 0, phi);
  ir.position = pin + 0.5 * l * dr;
  ir.angular_velocity = phid * z;
  ir.velocity = (om0 * z).cross(pin) + ir.angular_velocity.cross(0.5 * l * dr);
  // slider
  is.position = xs;
  is.velocity = Vec3(slider_v(th0, om0), 0, 0);
  ASSERT_NEAR((ir.velocity + ir.angular_velocity.cross(0.5 * l * dr) - is.velocity).norm(), 0.0,
              1e-12);  // the closed-form rates close the loop

  System sys;
  const RigidBody& crank = add_rigid(sys, "crank", mc, rod_inertia(mc, r, 0.01, 0), ic);
  const RigidBody& rod = add_rigid(sys, "rod", mr, rod_inertia(mr, l, 0.01, 0), ir);
  const RigidBody& slider =
      add_rigid(sys, "slider", ms, Vec3(0.01, 0.012, 0.014).asDiagonal().toDenseMatrix(), is);
  // frames: revolute about z_from = z_to; universal: x_from (slider) = world z, y_to = the
  // rod's in-plane normal; prismatic along z_from = world x, twist row x_from . y_to
  Mat3 zxy;  // columns world z, x, y
  zxy << 0, 1, 0, 0, 0, 1, 1, 0, 0;
  Mat3 yzx;  // columns world y, z, x
  yzx << 0, 0, 1, 1, 0, 0, 0, 1, 0;
  add_joint(sys, "main bearing", JointType::kRevolute, ground(Vec3::Zero()),
            on(crank, {-0.5 * r, 0, 0}));
  add_joint(sys, "crank pin", JointType::kBall, on(crank, {0.5 * r, 0, 0}),
            on(rod, {-0.5 * l, 0, 0}));
  add_joint(sys, "wrist pin", JointType::kUniversal, on(slider, Vec3::Zero(), zxy),
            on(rod, {0.5 * l, 0, 0}));
  add_joint(sys, "guide", JointType::kPrismatic, ground(Vec3(0, e, 0), yzx),
            on(slider, Vec3::Zero(), yzx));
  sys.add_force(
      std::make_unique<Gravity>(Vec3(0, -kG, 0), std::vector<const Body*>{&crank, &rod, &slider}));
  sys.finalize();
  State s = sys.initial_state();
  ASSERT_EQ(sys.num_coordinates() - sys.num_constraints(), 1);
  {
    DaeEval ev = sys.make_eval();
    DaeRequest req;
    req.forces = false;
    req.matrix = true;
    sys.evaluate(s, req, ev);
    ASSERT_LT(ev.C.lpNorm<Eigen::Infinity>(), 1e-14);
    ASSERT_LT(ev.Cdot.lpNorm<Eigen::Infinity>(), 1e-12);  // consistent velocities
    const MatX Cq =
        MatX(ev.kkt.matrix())
            .block(sys.num_coordinates(), 0, sys.num_constraints(), sys.num_coordinates());
    EXPECT_EQ(Eigen::FullPivLU<MatX>(Cq).rank(), sys.num_constraints());
  }
  Rk4Augmented rk4;
  const double E0 = sys.energies(s).total();
  const double h = 1e-3;
  double dx = 0.0, dv = 0.0, dE = 0.0, turns = 0.0, om_min = 1e9, om_max = 0.0;
  double th_prev = th0;
  for (long k = 1; k <= 2000; ++k) {
    const StepReport rep = rk4.step(sys, s, h);
    ASSERT_TRUE(rep.ok) << rep.message;
    const Mat3 A = crank.orientation(s);
    const double th = std::atan2(A(1, 0), A(0, 0));
    const double om = crank.angular_velocity(s).z();
    dx = std::max(dx, std::abs(slider.position(s).x() - slider_x(th)));
    dv = std::max(dv, std::abs(slider.velocity(s).x() - slider_v(th, om)));
    dE = std::max(dE, std::abs(sys.energies(s).total() - E0));
    turns += std::remainder(th - th_prev, 2 * kPi) / (2 * kPi);
    th_prev = th;
    om_min = std::min(om_min, om);
    om_max = std::max(om_max, om);
  }
  std::printf(
      "\n  slider-crank, 2 s, h = %g s: %.2f crank turns, crank rate %.2f..%.2f rad/s; max slider "
      "position error %.2e m, velocity error %.2e m/s; max |E - E0| = %.2e J of %.2f J\n",
      h, turns, om_min, om_max, dx, dv, dE, E0);
  EXPECT_LT(dx, 1e-6);
  EXPECT_LT(dv, 1e-6);
  EXPECT_LT(dE / E0, 1e-5);
  EXPECT_GT(turns, 5.0);            // the crank revolves: every angle is visited
  EXPECT_GT(om_max - om_min, 5.0);  // and unevenly (the slider's inertia)
}

// 4. Cantilever ANCF beam (section of the thesis cantilever, 3.1.1: E = 210 GPa,
// A = 0.01 m^2, I = 8.33e-6 m^4, rho = 7850 kg/m^3, 10 elements, clamped by a
// CoordinateLock on r and r' of the root node as the model loader does; L = 4 m instead
// of 10 m, whose own weight alone bends it 0.24 % away from linear theory) carrying a
// 200 kg body on a fixed joint at the tip node. The body's centre of gravity lies e = 1 m
// beyond the tip and c = 0.05 m below the beam axis, so its weight P = m g loads the tip
// with a moment M = m g e as well. (c > 0 makes the body hang: the cable element has no
// torsion, so the fixed joint leaves the body's spin about the beam axis free, and only
// the weight acting below the axis holds it; with c = 0 that spin would have no stiffness.)
// Statics with gravity on beam and body. Linear Euler-Bernoulli superposition:
//   w = P L^3/(3EI) + M L^2/(2EI) + q L^4/(8EI),  slope = P L^2/(2EI) + M L/EI + q L^3/(6EI)
// (q = rho A g, the beam's own weight, 770 N/m against P = 1962 N). Asserted: tip
// deflection and slope within 0.5 % of these. Geometric nonlinearity stays below 0.1 %: the
// tip slope is 0.018 rad, so the load arms shorten by O(slope^2) ~ 3e-4, and the body's
// lever turns with the tip, which changes M by c slope / e ~ 1e-3 of M, a quarter of the
// slope's total. Quantified by the independent elastica with the same loads (M(L) =
// m g (e cos(theta_L) - c sin(theta_L))): it differs from linear theory by less than 0.1 %
// (asserted), and the beam matches it within 0.05 % (mesh error of 10 cubic elements
// under a quartic load, and axial stretch, ~1e-5). The body turns with the beam's tip slope
// (fixed joint) to 1e-9 rad. The joint's reaction on the body is minus its weight, and its
// moment about the attachment point balances the weight's moment about that point,
// m g x (lever in the deformed configuration), to 1e-6 relative (the statics tolerance is
// 1e-8 of the largest force); the lever's horizontal part is e cos(slope) - c sin(slope).
TEST(RigidBodies, CantileverCarryingBodyOnFixedJoint) {
  const double L = 4.0, E = 210e9, A = 0.01, I = 8.33e-6, rho = 7850.0;
  const double m = 200.0, e = 1.0, c = 0.05;
  const int n = 10;
  System sys;
  BeamSection sec;
  sec.area = A;
  sec.second_moment = I;
  sec.youngs_modulus = E;
  sec.density = rho;
  const auto& beam = static_cast<const AncfBeam&>(sys.add_body(std::make_unique<AncfBeam>(
      "beam", BeamGeometry::straight(Vec3::Zero(), Vec3(L, 0, 0), n), sec, BeamOptions{})));
  RigidBodyInitial ib;
  ib.position = Vec3(L + e, 0, -c);
  const Mat3 Jb = Vec3(20.0, 30.0, 25.0).asDiagonal();
  const RigidBody& body = add_rigid(sys, "mass", m, Jb, ib);
  sys.add_constraint(std::make_unique<CoordinateLock>(
      "support beam.n0", beam, std::vector<Index>{0, 1, 2, 3, 4, 5},
      std::vector<double>{0, 0, 0, 1, 0, 0},
      std::vector<std::string>{"x", "y", "z", "r'x", "r'y", "r'z"}));
  // the body marker's z axis along the beam slope (world x); beam named first: the joint
  // swaps internally and still reports the reaction on the body
  Mat3 yzx;  // columns world y, z, x
  yzx << 0, 0, 1, 1, 0, 0, 0, 1, 0;
  const Joint& joint = add_joint(sys, "tip", JointType::kFixed, BeamMarker::at_node(beam, n),
                                 on(body, Vec3(-e, 0, c), yzx));
  sys.add_force(std::make_unique<Gravity>(Vec3(0, 0, -kG), std::vector<const Body*>{&beam, &body}));
  sys.finalize();
  State s = sys.initial_state();
  // Initial multipliers: the body's own equilibrium at the start, C_q^T mu = Q on its 7
  // coordinates (normalization row and the joint's 5 rows; 7 equations, consistent). From
  // mu = 0 the first Newton tangent has no stiffness against the body's spin about the beam
  // axis (that stiffness is the weight acting through the joint, i.e. the multipliers):
  // it is singular, and statics would rest on a round-off pivot.
  {
    DaeEval ev = sys.make_eval();
    DaeRequest req;
    req.matrix = true;
    sys.evaluate(s, req, ev);
    const MatX K(ev.kkt.matrix());
    const Index nq = sys.num_coordinates(), b0 = body.offset();
    const Index r_norm = nq + row_offset(sys, *sys.constraints().front());
    const Index r_joint = nq + row_offset(sys, joint);
    MatX B(6, 7);
    B.row(0) = K.block(r_norm, b0, 1, 7);
    B.bottomRows(5) = K.block(r_joint, b0, 5, 7);
    const VecX Qb = ev.Q.segment(b0, 7);
    const VecX mu = B.transpose().colPivHouseholderQr().solve(Qb);
    ASSERT_LT((B.transpose() * mu - Qb).norm(), 1e-9 * m * kG);
    s.lambda[r_norm - nq] = mu[0];
    s.lambda.segment(r_joint - nq, 5) = mu.tail(5);
  }
  const StaticsReport rep = solve_statics(sys, s, StaticsSettings{});

  const double EI = E * I, q = rho * A * kG, P = m * kG, M = P * e;
  const double w_lin =
      P * std::pow(L, 3) / (3 * EI) + M * L * L / (2 * EI) + q * std::pow(L, 4) / (8 * EI);
  const double t_lin = P * L * L / (2 * EI) + M * L / EI + q * std::pow(L, 3) / (6 * EI);
  const auto el = analytic::elastica_cantilever(
      q, L, EI, 4000, P, [&](double th) { return P * (e * std::cos(th) - c * std::sin(th)); });
  const Index tip = beam.node_index(n);
  const double w = -s.q[tip + 2];
  const double slope = std::atan2(-s.q[tip + 5], s.q[tip + 3]);
  const Mat3 Ab = body.orientation(s);
  const double body_angle = std::atan2(-Ab(2, 0), Ab(0, 0));
  std::printf(
      "\n  cantilever + tip body (%d increments, %d iterations): tip deflection %.7f m, linear "
      "%.7f m (%+.3f %%), elastica %.7f m (%+.1e); tip slope %.7f rad, linear %.7f "
      "(%+.3f %%), elastica %.7f (%+.1e); elastica vs linear %+.3f %% (w), %+.3f %% "
      "(slope); body rotation - tip slope %.1e rad\n",
      rep.increments, rep.iterations, w, w_lin, 100 * (w / w_lin - 1), el.deflection,
      w / el.deflection - 1, slope, t_lin, 100 * (slope / t_lin - 1), el.angle,
      slope / el.angle - 1, 100 * (el.deflection / w_lin - 1), 100 * (el.angle / t_lin - 1),
      body_angle - slope);
  EXPECT_NEAR(w / w_lin, 1.0, 5e-3);
  EXPECT_NEAR(slope / t_lin, 1.0, 5e-3);
  EXPECT_NEAR(el.deflection / w_lin, 1.0, 1e-3);
  EXPECT_NEAR(el.angle / t_lin, 1.0, 1e-3);
  EXPECT_NEAR(w / el.deflection, 1.0, 5e-4);
  EXPECT_NEAR(slope / el.angle, 1.0, 5e-4);
  EXPECT_NEAR(body_angle, slope, 1e-9);

  // reaction on the body (the joint's "to"), moment about the attachment point
  const auto [F, Mr] =
      joint.reaction(s, s.lambda.segment(row_offset(sys, joint), joint.num_rows()));
  const Vec3 weight(0, 0, -P);
  const Vec3 lever = body.position(s) - joint.to().position(s);
  const Vec3 M_expected = -lever.cross(weight);  // the joint balances the weight's moment
  std::printf(
      "  joint reaction on the body: F = (%.6g, %.6g, %.6g) N, M = (%.6g, %.6g, %.6g) N m; "
      "m g = %.6g N, m g x lever = %.6g N m (lever %.6f m; undeformed m g e = %.6g N m)\n",
      F.x(), F.y(), F.z(), Mr.x(), Mr.y(), Mr.z(), P, M_expected.y(), lever.x(), M);
  EXPECT_LT((F + weight).norm(), 1e-6 * P);
  EXPECT_LT((Mr - M_expected).norm(), 1e-6 * P * e);
  EXPECT_NEAR(lever.x(), e * std::cos(slope) - c * std::sin(slope), 1e-9);
}

// 5. A body (50 kg, full inertia tensor with products, arbitrary attitude) hanging at rest
// on a ball joint from ground, its centre of gravity 2 m straight below the joint. The
// multipliers of the augmented system (Rk4Augmented::update_multipliers) give the joint's
// reaction on the body: (0, 0, m g) to 1e-9 relative (one LU solve of an 11 x 11 system:
// round-off ~1e-15), moment 0 to 1e-9 m g L (a ball joint transmits none). After 1 s of RK4
// (h = 1e-3 s) from rest the body still hangs: q unchanged to 1e-9 (the accelerations
// vanish to round-off at the equilibrium, and it is stable).
TEST(RigidBodies, HangingBodyReactionFromMultipliers) {
  const double m = 50.0, L = 2.0;
  const Vec3 pivot(1.0, 2.0, 3.0);
  const Mat3 A0 = math::rotation_from_roll_pitch_yaw(0.3, -0.5, 1.1);
  Mat3 J;
  J << 12.0, 0.8, -0.5, 0.8, 9.0, 0.3, -0.5, 0.3, 15.0;
  RigidBodyInitial init;
  init.position = pivot - Vec3(0, 0, L);
  init.orientation = A0;
  System sys;
  const RigidBody& body = add_rigid(sys, "bob", m, J, init);
  const Joint& joint = add_joint(sys, "hook", JointType::kBall, ground(pivot),
                                 on(body, A0.transpose() * Vec3(0, 0, L)));
  sys.add_force(std::make_unique<Gravity>(Vec3(0, 0, -kG), std::vector<const Body*>{&body}));
  sys.finalize();
  State s = sys.initial_state();
  const Index off = row_offset(sys, joint);
  EXPECT_EQ(off, 1);  // after the body's normalization row
  Rk4Augmented rk4;
  rk4.update_multipliers(sys, s);
  const auto [F, M] = joint.reaction(s, s.lambda.segment(off, joint.num_rows()));
  const Vec3 expected(0, 0, m * kG);
  std::printf("\n  hanging body: reaction F = (%.3e, %.3e, %.12g) N, |M| = %.2e N m\n", F.x(),
              F.y(), F.z(), M.norm());
  EXPECT_LT((F - expected).norm(), 1e-9 * m * kG);
  EXPECT_LT(M.norm(), 1e-9 * m * kG * L);

  const VecX q0 = s.q;
  for (int k = 0; k < 1000; ++k) ASSERT_TRUE(rk4.step(sys, s, 1e-3).ok);
  const double dq = (s.q - q0).lpNorm<Eigen::Infinity>();
  std::printf("  after 1 s of RK4: max |q - q0| = %.2e, max |v| = %.2e\n", dq,
              s.v.lpNorm<Eigen::Infinity>());
  EXPECT_LT(dq, 1e-9);
}

// 6. Compound pendulum on a revolute joint (horizontal hinge along world y): 3 kg, centre
// of gravity d = 0.6 m below the hinge, inertia about the centre of gravity with products
// (I_yy = 0.25 kg m^2 about the hinge direction; the products load the hinge's moment
// rows). Released from 0.02 rad. The mean period over 5 swings (downward zero crossings,
// interpolated) equals 2 pi sqrt(I_pivot / (m g d)), I_pivot = I_yy + m d^2, within 0.1 %
// (the finite amplitude adds theta0^2/16 = 2.5e-5); with that correction within 1e-6
// (next term 11 theta0^4/3072 ~ 6e-10; RK4 at h = 1e-3 s, w h = 3.6e-3: phase error ~1e-12).
TEST(RigidBodies, CompoundPendulumSmallAmplitudePeriod) {
  const double m = 3.0, d = 0.6, th0 = 0.02;
  Mat3 J;
  J << 0.2, 0.03, 0.01, 0.03, 0.25, 0.02, 0.01, 0.02, 0.15;
  const Mat3 hinge = math::frame_from_axis(Vec3::UnitY());  // z column = world y
  RigidBodyInitial init;
  init.orientation = math::rotation_from_roll_pitch_yaw(0, th0, 0);
  init.position = init.orientation * Vec3(0, 0, -d);
  System sys;
  const RigidBody& body = add_rigid(sys, "pendulum", m, J, init);
  add_joint(sys, "hinge", JointType::kRevolute, ground(Vec3::Zero(), hinge),
            on(body, Vec3(0, 0, d), hinge));
  sys.add_force(std::make_unique<Gravity>(Vec3(0, 0, -kG), std::vector<const Body*>{&body}));
  sys.finalize();
  State s = sys.initial_state();
  Rk4Augmented rk4;
  const double Ip = J(1, 1) + m * d * d;
  const double T0 = 2 * kPi * std::sqrt(Ip / (m * kG * d));
  const double h = 1e-3;
  auto angle = [&](const State& st) {
    const Mat3 A = body.orientation(st);
    return std::atan2(A(0, 2), A(2, 2));
  };
  std::vector<double> crossings;
  double prev = angle(s);
  while (crossings.size() < 6) {
    ASSERT_TRUE(rk4.step(sys, s, h).ok);
    const double th = angle(s);
    if (prev > 0 && th <= 0) crossings.push_back(s.t - h * th / (th - prev));
    prev = th;
    ASSERT_LT(s.t, 20.0);
  }
  const double T = (crossings.back() - crossings.front()) / 5.0;
  const double T_amp = T0 * (1 + th0 * th0 / 16);
  std::printf(
      "\n  compound pendulum: period %.9f s; 2 pi sqrt(I_pivot/(m g d)) = %.9f s (%+.2e), "
      "with the amplitude correction %.9f s (%+.2e)\n",
      T, T0, T / T0 - 1, T_amp, T / T_amp - 1);
  EXPECT_NEAR(T / T0, 1.0, 1e-3);
  EXPECT_NEAR(T / T_amp, 1.0, 1e-6);
}
