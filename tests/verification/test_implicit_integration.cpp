// Verification of generalized-alpha on whole models (issue 6):
// - the cantilever of thesis 3.1.1 vibrating freely in its first bending mode: the largest
//   tip error over 1 s against RK4 at h = 4e-5 s (fourth order) falls by 4 (+-20 %) each
//   time h halves from 0.02 s (second order), for rho_inf = 0.8 and 1, full and modified
//   Newton;
// - a snap load: a 1 t weight falls 1 m onto a slack rope whose tension grows a
//   thousand-fold over 5 cm of stretch. Fixed-step Newton fails at h = 0.1 s; the
//   adaptive step control halves the step through the snap, finishes, keeps the free
//   fall exact (generalized-alpha integrates a constant acceleration exactly), dissipates
//   energy rather than creating it, and its peak tension stays below the undamped
//   energy bound;
// - a floating body with radiation memory in waves agrees with RK4.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>

#include "memory_recorder.hpp"
#include "rigid_benchmarks.hpp"
#include "seaflex/core/errors.hpp"
#include "seaflex/forces/spring_damper.hpp"
#include "seaflex/integrators/generalized_alpha.hpp"
#include "seaflex/integrators/rk4_augmented.hpp"
#include "seaflex/io/model_loader.hpp"
#include "seaflex/simulation/simulation.hpp"
#include "seaflex/solvers/modal.hpp"
#include "seaflex/solvers/statics.hpp"

using namespace seaflex;
using seaflex::testing::MemoryRecorder;

namespace {

constexpr double kL = 10.0, kE = 210e9, kA = 0.01, kI = 8.33e-6, kRho = 7850;

const std::string kCantilever = fmt::format(R"(
environment: {{gravity: 0}}
bodies:
  beam: {{type: ancf_beam, start: [0, 0, 0], end: [{}, 0, 0], elements: 10, area: {}, second_moment: {},
          youngs_modulus: {}, density: {}}}
supports:
  - {{body: beam, node: start, type: clamped}}
)",
                                            kL, kA, kI, kE, kRho);

// the cantilever's tip z every 20 ms up to t_end, starting straight with the velocity of
// its first bending mode in z (tip velocity 0.1 m/s): the motion stays in that mode, so
// that the error measures the scheme, not unresolved higher modes
std::vector<double> tip_history(Integrator& integrator, double h, double t_end) {
  io::Model model = io::load_model_text(kCantilever, "cantilever");
  State s = model.system->initial_state();
  const Index tip = model.system->find_body("beam")->offset() + 60 + 2;
  const ModalResult modes = solve_modes(*model.system, s, 2);
  const int k = std::abs(modes.shapes(tip, 0)) > std::abs(modes.shapes(tip, 1)) ? 0 : 1;
  s.v = modes.shapes.col(k) * (0.1 / modes.shapes(tip, k));
  integrator.start(*model.system, s);
  const long n = std::lround(t_end / h), every = std::lround(0.02 / h);
  std::vector<double> out;
  for (long j = 1; j <= n; ++j) {
    const StepReport r = integrator.step(*model.system, s, h);
    EXPECT_TRUE(r.ok) << r.message;
    if (!r.ok) return {};
    if (j % every == 0) out.push_back(s.q[tip]);
  }
  return out;
}

double max_difference(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size() || a.empty()) return NAN;
  double d = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) d = std::max(d, std::abs(a[i] - b[i]));
  return d;
}

}  // namespace

TEST(GeneralizedAlphaBeam, CantileverFreeVibrationSecondOrder) {
  Rk4Augmented rk4;
  const std::vector<double> ref = tip_history(rk4, 4e-5, 1.0);  // RK4's limit: 5.7e-5 s
  ASSERT_EQ(ref.size(), 50u);
  // it vibrates: amplitude 0.1 / omega_1 = 0.019 m
  EXPECT_NEAR(*std::max_element(ref.begin(), ref.end()), 0.1 / 5.25, 0.002);
  for (const double rho : {0.8, 1.0}) {
    for (const NewtonMode mode : {NewtonMode::kFull, NewtonMode::kModified}) {
      std::vector<double> err;
      for (const double h : {0.02, 0.01, 0.005}) {
        GeneralizedAlphaSettings s = GeneralizedAlphaSettings::from_rho_inf(rho);
        s.newton = mode;
        GeneralizedAlpha ga(s);
        err.push_back(max_difference(tip_history(ga, h, 1.0), ref));
      }
      std::printf("  rho_inf %.1f, %s Newton: errors %.3e %.3e %.3e m, ratios %.3f %.3f\n", rho,
                  mode == NewtonMode::kFull ? "full" : "modified", err[0], err[1], err[2],
                  err[0] / err[1], err[1] / err[2]);
      EXPECT_NEAR(err[0] / err[1], 4.0, 0.8);
      EXPECT_NEAR(err[1] / err[2], 4.0, 0.8);
    }
  }
}

namespace {

std::string snap_model(const char* control) {
  return fmt::format(R"(
environment: {{gravity: 9.81}}
bodies:
  weight: {{type: rigid_body, mass: 1000, inertia: [100, 100, 100], position: [0, 0, -9]}}
connections:
  - {{name: rope, type: spring, from: {{body: ground, position: [0, 0, 0]}},
     to: {{body: weight, position: [0, 0, 0]}}, free_length: 10, slack: true, damping: 2.0e4,
     tension_table: [[0, 0], [0.01, 1.0e4], [0.02, 1.0e5], [0.03, 1.0e6], [0.04, 1.0e7], [0.05, 1.0e8]]}}
dynamics: {{integrator: generalized_alpha, time_step: 0.1, duration: 3, output_interval: 0.1,
           step_control: {}}}
)",
                     control);
}

}  // namespace

TEST(GeneralizedAlphaBeam, AdaptiveStepSurvivesSnapLoad) {
  {  // fixed step: Newton cannot follow the snap at h = 0.1 s
    io::Model model = io::load_model_text(snap_model("fixed"), "snap");
    auto ga = model.dynamics->make_integrator();
    Simulation sim(*model.system, model.system->channels(), *ga, model.dynamics->simulation());
    State s = model.system->initial_state();
    try {
      sim.run(s);
      ADD_FAILURE() << "fixed-step Newton was expected to fail at the snap";
    } catch (const SolverError& e) {
      EXPECT_NE(std::string(e.what()).find("Newton"), std::string::npos) << e.what();
      // the rope first snaps taut at t = sqrt(2/9.81) = 0.45 s, then at every bounce
      EXPECT_GT(e.time(), 0.45);
      EXPECT_LT(e.time(), 3.0);
    }
  }
  io::Model model = io::load_model_text(snap_model("adaptive"), "snap");
  auto ga = model.dynamics->make_integrator();
  Simulation sim(*model.system, model.system->channels(), *ga, model.dynamics->simulation());
  MemoryRecorder rec;
  sim.add_recorder(rec);
  State s = model.system->initial_state();
  const double e0 = model.system->energies(s).total();
  const SimulationReport rep = sim.run(s);
  std::printf("\n  snap: %ld steps, %ld rejected, smallest %.3g s\n", rep.steps, rep.rejected_steps,
              rep.min_step);
  EXPECT_NEAR(rep.end_time, 3.0, 1e-12);
  EXPECT_GT(rep.rejected_steps, 0);
  EXPECT_LT(rep.min_step, 0.1);
  // free fall before the snap (t <= 0.4 s), exact for a constant acceleration
  const std::size_t z = rec.column("weight.z"), tension = rec.column("rope.tension");
  for (std::size_t i = 0; i < rec.times.size() && rec.times[i] <= 0.4 + 1e-9; ++i)
    EXPECT_NEAR(rec.rows[i][z], -9.0 - 0.5 * 9.81 * rec.times[i] * rec.times[i], 1e-9);
  // the rope and the scheme dissipate: no energy is created
  EXPECT_LE(model.system->energies(s).total(), e0 + 1e-6 * 1000 * 9.81);
  // peak tension below the undamped bound: the stretch x at which the rope's strain
  // energy equals the weight's fall m g (1 + x)
  const SpringLaw law =
      SpringLaw::table({0, 0.01, 0.02, 0.03, 0.04, 0.05}, {0, 1e4, 1e5, 1e6, 1e7, 1e8});
  double lo = 0.0, hi = 1.0;
  for (int k = 0; k < 200; ++k) {
    const double x = 0.5 * (lo + hi);
    (law.energy(x) < 1000 * 9.81 * (1.0 + x) ? lo : hi) = x;
  }
  const double bound = law.tension(lo);
  double peak = 0.0;
  for (const auto& row : rec.rows) peak = std::max(peak, row[tension]);
  std::printf("  peak tension in the output rows %.4g N, undamped bound %.4g N\n", peak, bound);
  EXPECT_GT(peak, 1000 * 9.81);  // the rope did snap taut and hold the weight
  EXPECT_LE(peak, bound);
}

// A rigid body with BEM radiation memory in waves: the floating hemisphere of
// examples/hemisphere_in_waves.yaml (WAMIT data, state-space Cummins radiation, Airy
// waves at its heave resonance) run for 60 s with generalized-alpha (rho_inf = 1, h =
// 0.02 s) and with RK4 at the same step: the heave histories agree within 0.5 % of the
// steady amplitude (0.185 m; docs/verification.md section 8).
TEST(GeneralizedAlphaBeam, FloatingHemisphereAgreesWithRk4) {
  std::ifstream in(fmt::format("{}/examples/hemisphere_in_waves.yaml", SEAFLEX_SOURCE_DIR));
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  for (const auto& [from, to] :
       {std::pair<std::string, std::string>{"wamit: ../tests/",
                                            fmt::format("wamit: {}/tests/", SEAFLEX_SOURCE_DIR)},
        {"duration: 120", "duration: 60"}}) {
    ASSERT_NE(text.find(from), std::string::npos) << from;
    text.replace(text.find(from), from.size(), to);
  }
  std::vector<std::vector<double>> z;
  for (const char* integrator : {"rk4", "generalized_alpha\n  rho_inf: 1.0"}) {
    std::string model_text = text;
    const std::string key = "integrator: rk4";
    model_text.replace(model_text.find(key), key.size(), fmt::format("integrator: {}", integrator));
    io::Model model = io::load_model_text(model_text, "hemisphere_in_waves.yaml");
    auto method = model.dynamics->make_integrator();
    Simulation sim(*model.system, model.system->channels(), *method, model.dynamics->simulation());
    MemoryRecorder rec;
    sim.add_recorder(rec);
    State s = model.system->initial_state();
    sim.run(s);
    std::vector<double> zs;
    for (const auto& row : rec.rows) zs.push_back(row[rec.column("sphere.z")]);
    z.push_back(zs);
  }
  ASSERT_EQ(z[0].size(), z[1].size());
  double worst = 0.0, lo = 0.0, hi = -10.0;
  for (std::size_t i = 0; i < z[0].size(); ++i) {
    worst = std::max(worst, std::abs(z[0][i] - z[1][i]));
    if (i >= z[0].size() / 2) {
      lo = std::min(lo, z[0][i]);
      hi = std::max(hi, z[0][i]);
    }
  }
  const double amplitude = 0.5 * (hi - lo);
  std::printf("\n  hemisphere heave: amplitude %.4f m, largest difference %.3e m\n", amplitude,
              worst);
  EXPECT_GT(amplitude, 0.15);
  EXPECT_LT(worst, 0.005 * amplitude);
}

// rho_inf = 1 (no numerical damping) on a constrained system: the index-3 form lets the
// joint reaction's errors grow until Newton fails (Arnold & Bruls 2007); the default
// stabilized index-2 form runs the point pendulum of rigid_benchmarks.hpp for 20 s at
// h = 1e-3 s with its energy within 1e-5 of m g L (the trapezoidal scheme's bounded O(h^2)
// energy error is 5e-6 here) and its reaction within 1 % of the largest exact value, 3 m g
// at the bottom of the swing from the horizontal
TEST(GeneralizedAlphaBeam, UndampedPendulumNeedsTheIndex2Form) {
  using benchmarks::PointPendulum;
  for (const ConstraintLevel form :
       {ConstraintLevel::kStabilizedIndex2, ConstraintLevel::kIndex3}) {
    benchmarks::Benchmark b = PointPendulum::build();
    State s = b.system->initial_state();
    GeneralizedAlphaSettings st = GeneralizedAlphaSettings::from_rho_inf(1.0);
    st.constraints = form;
    GeneralizedAlpha ga(st);
    ga.start(*b.system, s);
    const double E0 = b.system->energies(s).total();
    double drift = 0.0, reaction = 0.0;
    bool ok = true;
    for (long k = 1; k <= 20000 && ok; ++k) {
      ok = ga.step(*b.system, s, 1e-3).ok;
      drift = std::max(drift, std::abs(b.system->energies(s).total() - E0));
      reaction = std::max(reaction, s.lambda.head(3).norm());
    }
    const double mgL = PointPendulum::m * benchmarks::kG * PointPendulum::L;
    std::printf(
        "  rho_inf = 1, %s: %s at t = %g s, max |E - E0| / (m g L) = %.2e, largest "
        "joint force %.4g N (3 m g = %.4g N)\n",
        form == ConstraintLevel::kIndex3 ? "index 3" : "index 2", ok ? "ran to the end" : "failed",
        s.t, drift / mgL, reaction, 3 * PointPendulum::m * benchmarks::kG);
    if (form == ConstraintLevel::kStabilizedIndex2) {
      EXPECT_TRUE(ok);
      EXPECT_LT(drift / mgL, 1e-5);
      EXPECT_NEAR(reaction, 3 * PointPendulum::m * benchmarks::kG, 0.01 * 3 * benchmarks::kG);
    } else {
      EXPECT_FALSE(ok && reaction < 10 * 3 * benchmarks::kG)
          << "the index-3 form was expected to go unstable at rho_inf = 1";
    }
  }
}
