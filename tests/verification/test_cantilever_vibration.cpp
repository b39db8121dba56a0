// Verification: free vibration of the cantilever of thesis 3.1.1 (no gravity). The first
// three bending frequencies against Euler-Bernoulli theory, beta_n L = 1.8751, 4.6941,
// 7.8548, within 1 % with 10 elements, for every bending model; and the first period in
// the time domain (RK4 on the augmented equations) against the modal value.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "analytic.hpp"
#include "seaflex/integrators/rk4_augmented.hpp"
#include "seaflex/io/model_loader.hpp"
#include "seaflex/solvers/modal.hpp"
#include "seaflex/solvers/statics.hpp"

using namespace seaflex;

namespace {

constexpr double kL = 10.0, kE = 210e9, kA = 0.01, kI = 8.33e-6, kRho = 7850;

std::string yaml(int elements, const char* axial, const char* bending,
                 const std::string& extra = "") {
  return fmt::format(R"(
environment: {{gravity: 0}}
bodies:
  beam: {{type: ancf_beam, start: [0, 0, 0], end: [{}, 0, 0], elements: {}, area: {}, second_moment: {},
          youngs_modulus: {}, density: {}, axial_model: {}, bending_model: {}}}
supports:
  - {{body: beam, node: start, type: clamped}}
{})",
                     kL, elements, kA, kI, kE, kRho, axial, bending, extra);
}

// Bending frequencies (rad/s): the section bends alike in both planes, so every bending
// frequency is a degenerate pair (y and z); axial modes are single. The pairs, in order.
std::vector<double> bending_omegas(const io::Model& model) {
  const State s = model.system->initial_state();
  const ModalResult modes = solve_modes(*model.system, s, 0);
  std::vector<double> out;
  for (Index k = 0; k + 1 < modes.omega.size(); ++k)
    if (std::abs(modes.omega[k + 1] - modes.omega[k]) <= 1e-8 * modes.omega[k + 1]) {
      out.push_back(0.5 * (modes.omega[k] + modes.omega[k + 1]));
      ++k;
    }
  return out;
}

}  // namespace

TEST(CantileverVibration, FirstThreeBendingFrequencies) {
  std::printf("\n  bending frequencies (Hz), 10 elements\n");
  for (const auto& [axial, bending] :
       {std::pair{"exact", "exact"}, std::pair{"L1", "T1"}, std::pair{"L2", "T2"}}) {
    const io::Model model = io::load_model_text(yaml(10, axial, bending), "cantilever");
    const auto omega = bending_omegas(model);
    ASSERT_GE(omega.size(), 3u);
    for (int n = 0; n < 3; ++n) {
      const double ref = analytic::cantilever_omega(n, kE * kI, kRho * kA, kL);
      std::printf("  %-5s/%-5s mode %d: %.5f Hz, Euler-Bernoulli %.5f Hz (%+.3f%%)\n", axial,
                  bending, n + 1, omega[n] / (2 * std::numbers::pi), ref / (2 * std::numbers::pi),
                  100 * (omega[n] / ref - 1));
      EXPECT_NEAR(omega[n] / ref, 1.0, 0.01) << axial << "/" << bending << " mode " << n + 1;
    }
  }
}

// release from the static shape under a tip load and time the zero crossings of the tip:
// the mean period must equal the first modal period within 1 % (higher modes, excited
// at ~1/40 of the first, shift single crossings slightly)
TEST(CantileverVibration, TimeDomainPeriodMatchesModal) {
  // a 1 kN tip load at t = 0 (statics), gone for t > 0
  const std::string load = R"(loads:
  - {type: point_force, body: beam, node: end, force: [0, 0, -1000], factor_table: [[0, 1], [1e-9, 0]]}
)";
  io::Model model = io::load_model_text(yaml(10, "exact", "exact", load), "cantilever");
  State s = model.system->initial_state();
  solve_statics(*model.system, s, model.statics);
  const Index tip = model.system->find_body("beam")->offset() + 60 + 2;
  Rk4Augmented rk4;
  const double h = 4e-5;  // RK4 limit 2 sqrt(2) / omega_max = 5.7e-5 s for this mesh
  std::vector<double> crossings;
  double z_prev = s.q[tip];
  while (s.t < 4.0) {
    const double t_prev = s.t;
    rk4.step(*model.system, s, h);
    const double z = s.q[tip];
    if ((z_prev < 0) != (z < 0)) crossings.push_back(t_prev + h * z_prev / (z_prev - z));
    z_prev = z;
  }
  ASSERT_GE(crossings.size(), 5u);
  const double period = 2.0 * (crossings.back() - crossings.front()) / (crossings.size() - 1);
  const double ref = 2 * std::numbers::pi / analytic::cantilever_omega(0, kE * kI, kRho * kA, kL);
  std::printf("  time-domain period %.5f s, Euler-Bernoulli %.5f s\n", period, ref);
  EXPECT_NEAR(period / ref, 1.0, 0.01);
}
