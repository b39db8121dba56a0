// Imposed motion verified against closed forms (docs/verification.md section "Imposed
// motion"): a base-excited damped oscillator, a rigid body that follows a six-degree-of-
// freedom motion in statics, RK4 and generalized-alpha, the reaction wrench of a prescribed
// body (Newton-Euler), and a winch paying out under a hanging mass (Bessel functions).
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "memory_recorder.hpp"
#include "seaflex/io/model_loader.hpp"
#include "seaflex/math/rotation.hpp"
#include "seaflex/model/motion.hpp"
#include "seaflex/simulation/simulation.hpp"
#include "seaflex/solvers/statics.hpp"

using namespace seaflex;
using seaflex::testing::MemoryRecorder;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;

struct Recorded {
  MemoryRecorder rec;
  std::vector<double> col(const std::string& name) const {
    const std::size_t c = rec.column(name);
    std::vector<double> v;
    for (const auto& row : rec.rows) v.push_back(row[c]);
    return v;
  }
};

// statics at t = 0 (when the model asks for it), then the dynamics, every row in memory
void run(const std::string& text, Recorded& out, bool statics = true) {
  io::Model m = io::load_model_text(text, "motion.yaml");
  State s = m.system->initial_state();
  if (statics) solve_statics(*m.system, s, m.statics);
  auto integrator = m.dynamics->make_integrator();
  Simulation sim(*m.system, io::model_channels(m), *integrator, m.dynamics->simulation());
  sim.add_recorder(out.rec);
  sim.run(s);
}

// least-squares fit x = a sin(w t) + b cos(w t) + c over rows with t >= t0:
// (amplitude, phase lead)
std::pair<double, double> fit(const std::vector<double>& t, const std::vector<double>& x, double w,
                              double t0) {
  Eigen::Matrix3d N = Eigen::Matrix3d::Zero();
  Eigen::Vector3d r = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (t[i] < t0) continue;
    const Eigen::Vector3d f(std::sin(w * t[i]), std::cos(w * t[i]), 1.0);
    N += f * f.transpose();
    r += f * x[i];
  }
  const Eigen::Vector3d p = N.ldlt().solve(r);
  return {std::hypot(p[0], p[1]), std::atan2(p[1], p[0])};
}

}  // namespace

// A mass m on a spring k and damper c whose top end moves y = Y sin(w t) (after a ramp):
// the steady response is x = X sin(w t + phi) with (e.g. Thomson & Dahleh, Theory of
// Vibration with Applications, 5th ed., sec. 3.5, base excitation)
//   X / Y = sqrt(k^2 + (c w)^2) / sqrt((k - m w^2)^2 + (c w)^2),
//   phi = atan2(c w, k) - atan2(c w, k - m w^2).
// The fit over the last 6 s (4 periods; the transient has decayed by e^-15) must match to
// 0.5 % in amplitude and 0.005 rad in phase (the issue's tolerance; the integrators' phase
// error at w h = 0.008 is ~1e-5).
TEST(PrescribedMotion, BaseExcitedOscillatorRk4AndGeneralizedAlpha) {
  const double m = 1000.0, wn = 2 * kPi, zeta = 0.1, k = m * wn * wn, c = 2 * zeta * m * wn;
  const double Y = 0.5, Tb = 1.5, w = 2 * kPi / Tb;
  const double X = Y * std::hypot(k, c * w) / std::hypot(k - m * w * w, c * w);
  const double phi = std::atan2(c * w, k) - std::atan2(c * w, k - m * w * w);
  for (const char* integrator : {"rk4", "generalized_alpha"}) {
    const std::string text =
        fmt::format(R"(
environment: {{gravity: 0}}
bodies:
  mass: {{type: rigid_body, mass: {m}, inertia: [10, 10, 10], position: [0, 0, 0]}}
connections:
  - name: spring
    type: spring
    from: {{body: ground, position: [0, 0, 10],
           motion: {{type: harmonic, amplitude: [0, 0, {Y}, 0, 0, 0], period: {Tb}, ramp: 3}}}}
    to: {{body: mass, position: [0, 0, 0]}}
    stiffness: {k}
    damping: {c}
    free_length: 10
dynamics: {{integrator: {integrator}, time_step: 0.002, duration: 30, output_interval: 0.01}}
)",
                    fmt::arg("m", m), fmt::arg("Y", Y), fmt::arg("Tb", Tb), fmt::arg("k", k),
                    fmt::arg("c", c), fmt::arg("integrator", integrator));
    Recorded r;
    run(text, r, false);
    const auto [amp, ph] = fit(r.rec.times, r.col("mass.z"), w, 24.0);
    EXPECT_NEAR(amp / X, 1.0, 0.005)
        << integrator << ": amplitude " << amp << " m, closed form " << X << " m";
    EXPECT_NEAR(ph, phi, 0.005) << integrator;
    std::printf("%s: amplitude %.6f m (closed form %.6f m, error %.2e), phase error %.2e rad\n",
                integrator, amp, X, amp / X - 1.0, ph - phi);
  }
}

// A rigid body with `motion: harmonic` in all six degrees of freedom (angles up to 20 deg,
// not small): statics at t = 0 puts it on the motion (which starts displaced, no ramp), and
// RK4 (with projection) and generalized-alpha keep it there to the constraint tolerance
// (1e-7 m and 1e-5 deg over 10 s: the Newton tolerance of generalized-alpha is 1e-8
// relative; RK4's projection holds C to 1e-12).
TEST(PrescribedMotion, RigidBodyFollowsTheMotionInStaticsRk4AndGeneralizedAlpha) {
  const Vec6 A = (Vec6() << 1.0, -0.5, 2.0, 10.0 * kDeg, -20.0 * kDeg, 15.0 * kDeg).finished();
  const Vec6 T = (Vec6() << 7.0, 5.0, 9.0, 6.0, 8.0, 11.0).finished();
  const Vec6 P = (Vec6() << 10.0, 20.0, 30.0, 40.0, 50.0, 60.0).finished() * kDeg;
  const HarmonicMotion motion(A, T, P);
  const Vec3 p0(5.0, 0.0, -2.0);
  for (const char* integrator : {"rk4", "generalized_alpha"}) {
    const std::string text = fmt::format(R"(
bodies:
  vessel:
    type: rigid_body
    mass: 1.0e5
    inertia: [1.0e6, 2.0e6, 2.5e6]
    position: [5, 0, -2]
    motion: {{type: harmonic, amplitude: [1.0, -0.5, 2.0, 10, -20, 15], period: [7, 5, 9, 6, 8, 11],
             phase: [10, 20, 30, 40, 50, 60]}}
dynamics: {{integrator: {}, time_step: 0.01, duration: 10, output_interval: 0.1}}
)",
                                         integrator);
    Recorded r;
    run(text, r, true);
    const char* names[] = {"vessel.x",    "vessel.y",     "vessel.z",
                           "vessel.roll", "vessel.pitch", "vessel.yaw"};
    for (int j = 0; j < 6; ++j) {
      const auto v = r.col(names[j]);
      double worst = 0.0;
      for (std::size_t i = 0; i < v.size(); ++i) {
        const MotionSample s = motion.sample(r.rec.times[i]);
        const double expect = j < 3 ? p0[j] + s.x[j] : s.x[j] / kDeg;
        worst = std::max(worst, std::abs(v[i] - expect));
      }
      EXPECT_LT(worst, j < 3 ? 1e-7 : 1e-5) << integrator << " " << names[j];
      std::printf("%s %s: largest deviation %.2e\n", integrator, names[j], worst);
    }
  }
}

namespace {

// The vessel of the reaction-wrench tests run with the given dynamics line: the largest
// errors of vessel.motion.fx ... mz against Newton-Euler (below), relative to the force's and
// the moment's norm at each row.
std::pair<double, double> reaction_wrench_errors(const std::string& dynamics) {
  const double mass = 2.0e5;
  const Mat3 I = Vec3(3.0e6, 4.0e6, 5.0e6).asDiagonal();
  const Vec6 A = (Vec6() << 1.0, 0.5, 2.0, 8.0 * kDeg, -6.0 * kDeg, 12.0 * kDeg).finished();
  const Vec6 T = (Vec6() << 9.0, 7.0, 10.0, 8.0, 6.5, 12.0).finished();
  const HarmonicMotion motion(A, T, Vec6::Zero());
  const std::string text = R"(
environment: {gravity: 9.81}
bodies:
  vessel:
    type: rigid_body
    mass: 2.0e5
    inertia: [3.0e6, 4.0e6, 5.0e6]
    position: [0, 0, 0]
    motion: {type: harmonic, amplitude: [1.0, 0.5, 2.0, 8, -6, 12], period: [9, 7, 10, 8, 6.5, 12]}
)" + dynamics + "\n";
  Recorded r;
  run(text, r, false);
  const char* names[] = {"vessel.motion.fx", "vessel.motion.fy", "vessel.motion.fz",
                         "vessel.motion.mx", "vessel.motion.my", "vessel.motion.mz"};
  std::vector<std::vector<double>> cols;
  for (const char* n : names) cols.push_back(r.col(n));
  EXPECT_GT(r.rec.times.size(), 10u);
  double worst_f = 0.0, worst_m = 0.0;
  for (std::size_t i = 1; i < r.rec.times.size(); ++i) {
    const MotionPose p = compute_motion_pose(motion.sample(r.rec.times[i]));
    const Vec3 F = mass * (p.p_tt - Vec3(0, 0, -9.81));
    const Mat3 W = p.R_t * p.R.transpose(),
               Wd = p.R_tt * p.R.transpose() + p.R_t * p.R_t.transpose();
    const Vec3 w(W(2, 1), W(0, 2), W(1, 0)), wd(Wd(2, 1), Wd(0, 2), Wd(1, 0));
    const Mat3 Iw = p.R * I * p.R.transpose();
    const Vec3 M = Iw * wd + w.cross(Iw * w);
    for (int j = 0; j < 3; ++j) {
      worst_f = std::max(worst_f, std::abs(cols[j][i] - F[j]) / F.norm());
      worst_m = std::max(worst_m, std::abs(cols[3 + j][i] - M[j]) / M.norm());
    }
  }
  return {worst_f, worst_m};
}

}  // namespace

// The reaction wrench of a prescribed body (channels vessel.motion.fx ... mz: what the motion
// exerts on the body, moment about the body's reference point, the centre of gravity) equals
// Newton-Euler: F = m a - m g, M = I_w w' + w x I_w w, with a, w, w' from the motion's pose
// (w~ = R' R^T, w~' = R'' R^T + R' R'^T, I_w = R I R^T). RK4's multipliers come from the
// augmented system with the exact gamma, so the match is to round-off: 1e-6 relative (the
// issue's tolerance).
TEST(PrescribedMotion, ReactionWrenchIsMassTimesAccelerationMinusLoads) {
  const auto [worst_f, worst_m] = reaction_wrench_errors(
      "dynamics: {integrator: rk4, time_step: 0.01, duration: 6, output_interval: 0.5}");
  EXPECT_LT(worst_f, 1e-6);
  EXPECT_LT(worst_m, 1e-6);
  std::printf("reaction wrench: largest relative error %.2e (force), %.2e (moment)\n", worst_f,
              worst_m);
}

// The rows that hold a body by themselves (System::reaction_only_rows): a vessel on an imposed
// motion (its fixed joint to the moving ground marker, 6 rows, and its Euler-parameter row)
// and a block clamped to the ground (the same, 7 rows) are; a ring on a prismatic joint to the
// vessel (5 rows on both bodies) and a beam's pinned end (3 rows of its 12 coordinates) are not.
TEST(PrescribedMotion, RowsThatHoldABodyByThemselvesAreReactionOnly) {
  const std::string text = R"(
bodies:
  vessel:
    type: rigid_body
    mass: 1.0e5
    inertia: [1.0e6, 2.0e6, 2.5e6]
    position: [0, 0, 0]
    motion: {type: harmonic, amplitude: [0, 0, 0.5, 0, 0, 0], period: [8, 8, 9, 8, 7, 8],
             phase: [0, 0, 90, 0, 0, 0]}
  ring: {type: rigid_body, mass: 100, inertia: [10, 10, 10], position: [0, 0, 2]}
  block: {type: rigid_body, mass: 50, inertia: [5, 5, 5], position: [10, 0, 0]}
  pipe: {type: ancf_beam, start: [20, 0, 0], end: [25, 0, 0], elements: 1, outer_diameter: 0.1,
         youngs_modulus: 2e11, density: 7850}
supports:
  - {body: pipe, node: start, type: pinned}
joints:
  - {name: guide, type: prismatic, from: {body: vessel, position: [0, 0, 2], axis: [0, 0, 1]},
     to: {body: ring, axis: [0, 0, 1]}}
  - {name: clamp, type: fixed, from: {body: ground, position: [10, 0, 0]}, to: {body: block}}
dynamics: {integrator: generalized_alpha, time_step: 0.01, duration: 1}
)";
  io::Model m = io::load_model_text(text, "held.yaml");
  const std::vector<Index> rows = m.system->reaction_only_rows();
  std::vector<std::string> names;
  for (const Index r : rows) names.push_back(m.system->constraint_name(r));
  ASSERT_EQ(rows.size(), 14u) << fmt::format("{}", fmt::join(names, "; "));
  int vessel = 0, block = 0;
  for (const auto& n : names) {
    vessel += n.rfind("vessel", 0) == 0;
    block += n.rfind("clamp", 0) == 0 || n.rfind("block", 0) == 0;
    EXPECT_EQ(n.find("guide"), std::string::npos) << n;
    EXPECT_EQ(n.find("ring"), std::string::npos) << n;
    EXPECT_EQ(n.find("pipe"), std::string::npos) << n;
  }
  EXPECT_EQ(vessel, 7);
  EXPECT_EQ(block, 7);
}

// Generalized-alpha leaves the reaction-only multipliers out of its convergence measure; they
// still converge with the accelerations: the reaction wrench of the previous test's vessel from
// generalized-alpha (rho_inf 0.8, h = 0.01 s, the default tolerance 1e-10) against Newton-Euler.
// The scheme's true accelerations a_{n+1} carry its own O(h^2) error, (w h)^2 ~ 1e-4 at w ~ 1
// rad/s; measured 3.1e-7 (force) and 1.0e-5 (moment) relative to the wrench's norm, held to
// 1e-4. A step whose iterations stopped with the reaction unconverged would be off by the
// hull's inertia force change per step, 1e-2 of the wrench.
TEST(PrescribedMotion, ReactionWrenchFromGeneralizedAlpha) {
  const auto [worst_f, worst_m] = reaction_wrench_errors(
      "dynamics: {integrator: generalized_alpha, rho_inf: 0.8, time_step: 0.01, duration: 6,\n"
      "           output_interval: 0.5}");
  EXPECT_LT(worst_f, 1e-4);
  EXPECT_LT(worst_m, 1e-4);
  std::printf(
      "generalized-alpha reaction wrench: largest relative error %.2e (force), %.2e "
      "(moment)\n",
      worst_f, worst_m);
}

// A mass m hangs from a rope (EA, free length L00, attached 0.5 m above its centre of
// gravity) at its static equilibrium (stretch m g L00 / EA, placed so in the model); at t = 0
// the winch starts paying out at rate r, L0(t) = L00 + r t. The stretch s = L - L0 obeys m s'' = m
// g - EA s / L0(t): s = m g L0(t) / EA + s_h with s_h'' + (c^2 / L0) s_h = 0, c^2 = EA / m, whose
// solutions are sqrt(x) Z1(2 kappa sqrt(x)), x = L0(t), kappa = c / r (Bessel functions of order 1;
// ds_h/dt = c Z0). From rest: s_h(0) = 0, s_h'(0) = -r (1 + m g / EA). Tension T = m g + EA s_h /
// L0(t), within 0.5 % of its largest value (the issue's tolerance; RK4 at h = 1 ms is far more
// accurate).
TEST(PrescribedMotion, WinchPayingOutUnderAHangingMass) {
  const double m = 1000.0, g = 9.81, EA = 1.0e6, L00 = 10.0, rate = 0.5;
  const std::string text =
      fmt::format(R"(
environment: {{gravity: {g}}}
bodies:
  load: {{type: rigid_body, mass: {m}, inertia: [10, 10, 10], position: [0, 0, {z0}]}}
connections:
  - name: wire
    type: rope
    path: [{{body: ground, position: [0, 0, 0]}}, {{body: load, position: [0, 0, 0.5]}}]
    axial_stiffness: {EA}
    free_length: {L}
    winch: {{rate: {r}}}
dynamics: {{integrator: rk4, time_step: 0.001, duration: 10, output_interval: 0.01}}
)",
                  fmt::arg("z0", -(L00 + m * g * L00 / EA) - 0.5), fmt::arg("g", g),
                  fmt::arg("m", m), fmt::arg("EA", EA), fmt::arg("L", L00), fmt::arg("r", rate));
  Recorded run_;
  run(text, run_, false);  // placed at its static equilibrium (the stretch m g L00 / EA)
  const auto T = run_.col("wire.tension"), L0 = run_.col("wire.free_length");
  const double c = std::sqrt(EA / m), kappa = c / rate;
  const double z0 = 2 * kappa * std::sqrt(L00);
  const double v0 = -rate * (1 + m * g / EA);
  // A J1(z0) + B Y1(z0) = 0, c (A J0(z0) + B Y0(z0)) = v0
  const double j1 = std::cyl_bessel_j(1.0, z0), y1 = std::cyl_neumann(1.0, z0);
  const double j0 = std::cyl_bessel_j(0.0, z0), y0 = std::cyl_neumann(0.0, z0);
  const double det = j1 * y0 - y1 * j0;
  const double Acoef = -y1 * (v0 / c) / det, Bcoef = j1 * (v0 / c) / det;
  double worst = 0.0, largest = 0.0;
  for (std::size_t i = 0; i < T.size(); ++i) {
    const double t = run_.rec.times[i], x = L00 + rate * t, z = 2 * kappa * std::sqrt(x);
    EXPECT_NEAR(L0[i], x, 1e-12 * x);
    const double sh =
        std::sqrt(x) * (Acoef * std::cyl_bessel_j(1.0, z) + Bcoef * std::cyl_neumann(1.0, z));
    const double exact = m * g + EA * sh / x;
    worst = std::max(worst, std::abs(T[i] - exact));
    largest = std::max(largest, exact);
  }
  EXPECT_LT(worst, 0.005 * largest) << "largest tension " << largest << " N";
  std::printf("winch: largest tension %.1f N, largest error %.3g N (%.2e)\n", largest, worst,
              worst / largest);
  // the oscillation is really there (amplitude ~ EA r / (c sqrt(L00)) = 5 kN)
  EXPECT_GT(largest - m * g, 3000.0);
}
