// The floating hemisphere of the public WAMIT data set (tests/data/wamit/sphere: R = 5 m,
// CG 2 m below the waterline at the body origin, WAMIT g = 9.81) as a seaflex rigid body
// with the BEM loads of thesis eq. (173): A(inf) in the mass matrix, the .hst restoring
// matrix, the Cummins memory force and the RAO excitation. The same files give the
// reference numbers:
//  - free heave decay: the period of the root of w^2 (M + A33(w)) = C33 (1 %, the issue);
//  - convolution and state-space memory give the same decay (2 %, the issue);
//  - regular wave at that frequency: the steady heave amplitude
//    |X3| a / |C33 - w^2 (M + A33) + i w B33| (0.5 %, the issue).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <string>
#include <vector>

#include "seaflex/hydro/wamit_reader.hpp"
#include "seaflex/integrators/rk4_augmented.hpp"
#include "seaflex/io/model_loader.hpp"

using namespace seaflex;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kRho = 1025.0, kG = 9.81;
const double kVolume = 2.0 / 3.0 * kPi * 125.0;  // the hemisphere, m^3
const std::string kStem = std::string(SEAFLEX_SOURCE_DIR) + "/tests/data/wamit/sphere/sphere";

std::string sphere_model(const std::string& radiation, const std::string& waves) {
  const double mass = kRho * kVolume;  // floats with its flat side at the surface
  return fmt::format(R"(
environment:
  gravity: 9.81
  water: {{density: 1025, depth: 50}}
{}
bodies:
  sphere:
    type: rigid_body
    mass: {}
    inertia: [1.0e6, 1.0e6, 1.0e6]
    position: [0, 0, -2]
hydrodynamics:
  sphere:
    bem:
      wamit: {}
      radiation: {}
      memory: 20
      kernel_time_step: 0.01
      displaced_volume: {}
      still_water_position: [0, 0, -2]
)",
                     waves, mass, kStem, radiation, kVolume);
}

hydro::HydroDatabase database() {
  return hydro::read_wamit(kStem, {kRho, kG, 1.0});
}

// the heave natural frequency from the files: w^2 (M + A33(w)) = C33, by bisection
double heave_natural_frequency(const hydro::HydroDatabase& db) {
  const double M = kRho * kVolume, C = db.hydrostatic_stiffness(2, 2);
  double lo = 0.3, hi = 3.0;
  for (int i = 0; i < 100; ++i) {
    const double w = 0.5 * (lo + hi);
    (w * w * (M + db.added_mass_at(w)(2, 2)) > C ? hi : lo) = w;
  }
  return 0.5 * (lo + hi);
}

struct HeaveHistory {
  std::vector<double> t, z;
};

HeaveHistory simulate(const std::string& yaml, double dz, double duration, double h) {
  io::Model model = io::load_model_text(yaml, "sphere.yaml");
  System& sys = *model.system;
  State s = sys.initial_state();
  s.q[2] += dz;
  Rk4Augmented rk4;
  HeaveHistory run;
  sys.start(s);
  const long steps = std::lround(duration / h);
  for (long k = 0; k <= steps; ++k) {
    run.t.push_back(s.t);
    run.z.push_back(s.q[2] + 2.0);  // heave of the body origin
    if (k == steps) break;
    const StepReport r = rk4.step(sys, s, h);
    EXPECT_TRUE(r.ok) << r.message;
    if (!r.ok) break;
    s.t = static_cast<double>(k + 1) * h;
    sys.accept_step(s);
  }
  return run;
}

std::vector<double> upward_crossings(const HeaveHistory& r) {
  std::vector<double> c;
  for (std::size_t i = 1; i < r.z.size(); ++i)
    if (r.z[i - 1] < 0.0 && r.z[i] >= 0.0)
      c.push_back(r.t[i - 1] + (r.t[i] - r.t[i - 1]) * r.z[i - 1] / (r.z[i - 1] - r.z[i]));
  return c;
}

TEST(FloatingSphere, HeaveDecayPeriodFromCummins) {
  const hydro::HydroDatabase db = database();
  const double wn = heave_natural_frequency(db);
  const HeaveHistory conv = simulate(sphere_model("convolution", ""), 1.0, 16.0, 0.01);
  const auto c = upward_crossings(conv);
  ASSERT_GE(c.size(), 2u);
  const double period = c[1] - c[0];
  // the first zero-crossing interval of the decay differs from the root of
  // w^2 (M + A33(w)) = C33 by the memory's damping and frequency dependence (0.1 % here);
  // 1 % asked by the issue
  EXPECT_NEAR(period, 2 * kPi / wn, 0.01 * 2 * kPi / wn);
  std::printf("sphere heave: decay period %.4f s, w^2 (M + A33(w)) = C33 gives %.4f s\n", period,
              2 * kPi / wn);
  // the state-space memory reproduces the convolution's decay: 2 % of the initial offset
  const HeaveHistory ss = simulate(sphere_model("state_space", ""), 1.0, 16.0, 0.01);
  double diff = 0.0;
  for (std::size_t i = 0; i < conv.z.size(); ++i)
    diff = std::max(diff, std::abs(conv.z[i] - ss.z[i]));
  EXPECT_LT(diff, 0.02 * 1.0);
  std::printf("sphere heave: convolution vs state space, max difference %.3g m\n", diff);
}

TEST(FloatingSphere, SteadyHeaveInARegularWaveAtResonance) {
  const hydro::HydroDatabase db = database();
  const double w = heave_natural_frequency(db);
  const double T = 2 * kPi / w, a = 0.1;
  const std::string waves = fmt::format(
      "  waves: {{type: airy, height: {}, period: {}, ramp: {{duration: {}}}}}", 2 * a, T, 2 * T);
  const HeaveHistory r = simulate(sphere_model("state_space", waves), 0.0, 30 * T, T / 200);
  // amplitude over the last five periods
  double zmax = -1e9, zmin = 1e9;
  for (std::size_t i = 0; i < r.t.size(); ++i)
    if (r.t[i] > 25 * T) {
      zmax = std::max(zmax, r.z[i]);
      zmin = std::min(zmin, r.z[i]);
    }
  const double M = kRho * kVolume;
  const std::complex<double> X3 = db.excitation_at(w, 0.0)[2];
  const std::complex<double> Z(
      db.hydrostatic_stiffness(2, 2) - w * w * (M + db.added_mass_at(w)(2, 2)),
      w * db.damping_at(w)(2, 2));
  const double expected = std::abs(X3) * a / std::abs(Z);
  // the frequency-domain answer from the same files; 0.5 % asked by the issue
  EXPECT_NEAR(0.5 * (zmax - zmin), expected, 0.005 * expected);
  std::printf("sphere heave in a regular wave: amplitude %.6f m, frequency domain %.6f m\n",
              0.5 * (zmax - zmin), expected);
}

}  // namespace
