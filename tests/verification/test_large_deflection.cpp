// Verification: large-deflection cantilever under a vertical tip load P (no gravity), the
// classic elastica benchmark (Bisshopp & Drucker 1945; Mattiasson 1981, Int. J. Numer.
// Meth. Eng. 17:145-153, Table 1). Exercises Newton statics with load stepping and line
// search at rotations up to 80 degrees. References: the independent shooting solution of
// analytic.hpp, and the published tip deflections for P L^2 / EI = 1 and 10.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cstdio>

#include "analytic.hpp"
#include "seaflex/io/model_loader.hpp"
#include "seaflex/solvers/statics.hpp"

using namespace seaflex;

namespace {

constexpr double kL = 10.0, kEI = 2.1e11 * 8.33e-6, kEA = 2.1e11 * 0.01;

struct Tip {
  double deflection;  // downward, m
  double shortening;  // towards the clamp, m
  int increments;
};

Tip solve(double alpha, int elements) {
  const double P = alpha * kEI / (kL * kL);
  const std::string text =
      fmt::format(R"(
environment: {{gravity: 0}}
bodies:
  beam: {{type: ancf_beam, start: [0, 0, 0], end: [{L}, 0, 0], elements: {n}, area: 0.01,
          second_moment: 8.33e-6, youngs_modulus: 2.1e11, density: 7850}}
supports:
  - {{body: beam, node: start, type: clamped}}
loads:
  - {{type: point_force, body: beam, node: end, force: [0, 0, {F}]}}
statics: {{load_steps: 4}}
)",
                  fmt::arg("L", kL), fmt::arg("n", elements), fmt::arg("F", -P));
  io::Model m = io::load_model_text(text, "tip_load");
  State s = m.system->initial_state();
  const StaticsReport rep = solve_statics(*m.system, s, m.statics);
  const Index tip = 6 * elements;
  return {-s.q[tip + 2], kL - s.q[tip], rep.increments};
}

}  // namespace

TEST(LargeDeflection, ElasticaReferenceMatchesPublishedValues) {
  // Mattiasson (1981): v/L = 0.30172 at P L^2/EI = 1, 0.81061 at 10
  EXPECT_NEAR(analytic::elastica_cantilever(0, 1, 1, 4000, 1.0).deflection, 0.30172, 1e-5);
  EXPECT_NEAR(analytic::elastica_cantilever(0, 1, 1, 4000, 10.0).deflection, 0.81061, 1e-5);
  EXPECT_NEAR(analytic::elastica_cantilever(0, 1, 1, 4000, 1.0).shortening, 0.05643, 1e-5);
}

// exact model, 20 elements: tip deflection and shortening within 0.1 % of L of the
// elastica; the residual difference is the axial stretch P/EA (~1e-5 L) and the mesh
TEST(LargeDeflection, ExactModelFollowsTheElastica) {
  std::printf(
      "\n  P L^2/EI   tip v/L (seaflex)  elastica   tip u/L (seaflex)  elastica  increments\n");
  for (double alpha : {1.0, 2.0, 5.0, 10.0}) {
    const Tip tip = solve(alpha, 20);
    const auto ref = analytic::elastica_cantilever(0, kL, kEI, 4000, alpha * kEI / (kL * kL));
    std::printf("  %8.1f   %17.5f  %8.5f   %17.5f  %8.5f  %d\n", alpha, tip.deflection / kL,
                ref.deflection / kL, tip.shortening / kL, ref.shortening / kL, tip.increments);
    EXPECT_NEAR(tip.deflection / kL, ref.deflection / kL, 1e-3) << alpha;
    EXPECT_NEAR(tip.shortening / kL, ref.shortening / kL, 1e-3) << alpha;
  }
  (void)kEA;
}
