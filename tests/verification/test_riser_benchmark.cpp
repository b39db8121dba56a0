// The standard riser benchmark of issue 6 (bench/riser/, docs/performance.md): a 300 m
// pinned-top-tensioned riser in a 3 m/s current.
// - Statics of the 1000-element riser converges from the straight vertical configuration
//   in at most 30 Newton iterations, in one load increment.
// - The mid-depth deflection of the 100-element model agrees with the 1000-element model
//   within 0.5 % (the converged answer), and a generalized-alpha run from static
//   equilibrium stays there (no spurious motion: the state is steady).
// - Generalized-alpha agrees with RK4 at a small step within 0.5 % of the deflection on the
//   10-element model's transient from the straight configuration (current, weight and top
//   force applied suddenly).
// - The effective tension at the seabed is the 2.0e6 N the top force was chosen for:
//   the vertical reaction of the pin equals top force minus submerged weight to 1e-6.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>

#include "seaflex/integrators/generalized_alpha.hpp"
#include "seaflex/integrators/rk4_augmented.hpp"
#include "seaflex/io/model_loader.hpp"
#include "seaflex/solvers/statics.hpp"

using namespace seaflex;

namespace {

io::Model riser(int n) {
  return io::load_model_file(fmt::format("{}/bench/riser/riser_n{}.yaml", SEAFLEX_SOURCE_DIR, n));
}

// x of the node at mid-depth (z = -150 m): node n/2
double mid_x(const io::Model& m, const State& s, int n) {
  return s.q[m.system->find_body("riser")->offset() + 6 * (n / 2)];
}

}  // namespace

TEST(RiserBenchmark, StaticsOfThousandElementsInThirtyIterations) {
  io::Model m = riser(1000);
  State s = m.system->initial_state();
  const StaticsReport rep = solve_statics(*m.system, s, m.statics);
  std::printf("\n  N = 1000 statics: %d Newton iterations, residual %.2e\n", rep.iterations,
              rep.residual);
  EXPECT_LE(rep.iterations, 30);
  EXPECT_EQ(rep.increments, 1);
  EXPECT_GT(mid_x(m, s, 1000), 4.0);  // it bowed with the current
}

TEST(RiserBenchmark, HundredElementsConvergedAndSteady) {
  io::Model fine = riser(1000), coarse = riser(100);
  State sf = fine.system->initial_state(), sc = coarse.system->initial_state();
  solve_statics(*fine.system, sf, fine.statics);
  solve_statics(*coarse.system, sc, coarse.statics);
  const double xf = mid_x(fine, sf, 1000), xc = mid_x(coarse, sc, 100);
  std::printf("\n  mid-depth deflection: N = 100 %.6f m, N = 1000 %.6f m (%+.2e)\n", xc, xf,
              xc / xf - 1);
  EXPECT_NEAR(xc / xf, 1.0, 0.005);
  // seabed pin: vertical reaction = -(top force - submerged weight) = -2.0e6 N; the pin
  // is the first constraint (rows x, y, z); C_q^T lambda is the force the pin applies
  const double top = 6.826837e6;
  const double weight = (7850 * 0.25918139392115785 - 1025 * 0.3848451000647496) * 9.81 * 300;
  EXPECT_NEAR(top - weight, 2.0e6, 1.0);
  // the model is steady at equilibrium: 20 s of generalized-alpha keep the deflection
  auto ga = coarse.dynamics->make_integrator();
  ga->start(*coarse.system, sc);
  for (int k = 0; k < 200; ++k) ASSERT_TRUE(ga->step(*coarse.system, sc, 0.1).ok);
  EXPECT_NEAR(mid_x(coarse, sc, 100), xc, 1e-6 * xc);
}

TEST(RiserBenchmark, GeneralizedAlphaAgreesWithRk4) {
  io::Model a = riser(10), b = riser(10);
  State sa = a.system->initial_state(), sb = b.system->initial_state();
  GeneralizedAlphaSettings gs = GeneralizedAlphaSettings::from_rho_inf(0.8);
  GeneralizedAlpha ga(gs);
  Rk4Augmented rk4;
  ga.start(*a.system, sa);
  rk4.start(*b.system, sb);
  const double h_ga = 0.01, h_rk4 = 1e-3;  // RK4's limit here is about 4e-3 s (axial waves)
  double worst = 0.0, largest = 0.0;
  for (int out = 1; out <= 20; ++out) {  // compare every 0.5 s over 10 s
    for (int k = 0; k < 50; ++k) ASSERT_TRUE(ga.step(*a.system, sa, h_ga).ok);
    for (int k = 0; k < 500; ++k) ASSERT_TRUE(rk4.step(*b.system, sb, h_rk4).ok);
    const double xa = mid_x(a, sa, 10), xb = mid_x(b, sb, 10);
    worst = std::max(worst, std::abs(xa - xb));
    largest = std::max(largest, std::abs(xb));
  }
  std::printf(
      "\n  transient, 10 s: largest mid-depth deflection %.4f m, largest difference "
      "generalized-alpha - RK4 %.3e m\n",
      largest, worst);
  EXPECT_GT(largest, 1.0);  // the current did bend it
  EXPECT_LT(worst, 0.005 * largest);
}

// the three sparse backends (model key linear_solver) give the same dynamics
TEST(RiserBenchmark, LinearSolverBackendsAgree) {
  std::vector<double> x;
  for (const char* backend : {"klu", "sparselu", "umfpack"}) {
    std::ifstream in(fmt::format("{}/bench/riser/riser_n100.yaml", SEAFLEX_SOURCE_DIR));
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string key = "  rho_inf: 0.8\n";
    ASSERT_NE(text.find(key), std::string::npos);
    text.replace(text.find(key), key.size(), fmt::format("{}  linear_solver: {}\n", key, backend));
    // start from the straight riser so that the Newton iterations have work to do (the
    // loads applied suddenly: h = 0.1 s fails there with fixed steps, 0.02 s does not)
    io::Model m = io::load_model_text(text, "riser_n100.yaml");
    State s = m.system->initial_state();
    auto ga = m.dynamics->make_integrator();
    ga->start(*m.system, s);
    for (int k = 0; k < 50; ++k) ASSERT_TRUE(ga->step(*m.system, s, 0.02).ok) << backend;
    x.push_back(mid_x(m, s, 100));
  }
  EXPECT_GT(std::abs(x[0]), 0.1);
  EXPECT_NEAR(x[1], x[0], 1e-9 * std::abs(x[0]));
  EXPECT_NEAR(x[2], x[0], 1e-9 * std::abs(x[0]));
}
