// The thesis's barge (section 3.2, Table 5: 110 x 46 x 7.5 m, draft 3.75 m, 19,445.375 t)
// floating free, built from a model file: its draft in statics against Archimedes, and
// its heave and roll natural periods from free decays against the linear values
//   T3 = 2 pi sqrt((m + A33) / (rho g L B)),
//   T4 = 2 pi sqrt((Ixx + A44) / (rho g V GM)),  GM = z_B - z_G + B^2 / (12 T),
// with the added masses A33, A44 given in the model (hydrodynamics.barge.added_mass).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "seaflex/integrators/rk4_augmented.hpp"
#include "seaflex/io/model_loader.hpp"
#include "seaflex/math/rotation.hpp"
#include "seaflex/solvers/statics.hpp"

using namespace seaflex;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kRho = 1025.0, kG = 9.81;
constexpr double kL = 110.0, kB = 46.0, kH = 7.5;
constexpr double kMass = 19445375.0;  // Table 5
constexpr double kIxx = kMass * 18.0 * 18.0, kIyy = kMass * 30.0 * 30.0, kIzz = kMass * 32.0 * 32.0;
constexpr double kA33 = 1.2e7, kA44 = 1.5e9;

std::string barge_model(double b33 = 0.0) {
  // CG at the box's centre (KG = 3.75 m); a 6x6 added mass at the CG
  return "environment:\n  gravity: 9.81\n  water: {density: 1025, depth: 100}\n"
         "bodies:\n  barge:\n    type: rigid_body\n    mass: 19445375\n"
         "    inertia: [" +
         std::to_string(kIxx) + ", " + std::to_string(kIyy) + ", " + std::to_string(kIzz) +
         "]\n    position: [0, 0, 0]\n"
         "hydrodynamics:\n  barge:\n    hull:\n      - box: {center: [0, 0, 0], size: [110, 46, "
         "7.5]}\n"
         "    added_mass: [[0,0,0,0,0,0], [0,0,0,0,0,0], [0,0," +
         std::to_string(kA33) + ",0,0,0], [0,0,0," + std::to_string(kA44) +
         ",0,0], [0,0,0,0,0,0], [0,0,0,0,0,0]]\n"
         "    linear_damping: [[0,0,0,0,0,0], [0,0,0,0,0,0], [0,0," +
         std::to_string(b33) + ",0,0,0], [0,0,0,0,0,0], [0,0,0,0,0,0], [0,0,0,0,0,0]]\n";
}

// mean period from the upward zero crossings of x(t) - mean
double period_of(const std::vector<double>& t, const std::vector<double>& x, double mean) {
  std::vector<double> crossings;
  for (std::size_t i = 1; i < x.size(); ++i) {
    const double a = x[i - 1] - mean, b = x[i] - mean;
    if (a < 0.0 && b >= 0.0) crossings.push_back(t[i - 1] + (t[i] - t[i - 1]) * a / (a - b));
  }
  EXPECT_GE(crossings.size(), 3u);
  if (crossings.size() < 2) return 0.0;
  return (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
}

TEST(FloatingBox, DraftInStaticsMatchesArchimedes) {
  io::Model model = io::load_model_text(barge_model(), "barge.yaml");
  State s = model.system->initial_state();
  solve_statics(*model.system, s, model.statics);
  // draft = m / (rho L B); the CG sits kH/2 above the keel. The hull is exact and
  // statics converges to 1e-8 of the force scale: 1e-6 m (the issue asks 1 mm).
  const double draft = kMass / (kRho * kL * kB);
  const double keel = s.q[2] - kH / 2;
  EXPECT_NEAR(-keel, draft, 1e-6);
  EXPECT_NEAR(draft, 3.7492, 1e-4);  // Table 5's 3.75 m with rho = 1025 kg/m^3
  EXPECT_NEAR(s.q[0], 0.0, 1e-9);
  EXPECT_NEAR(s.q[1], 0.0, 1e-9);
}

struct Decay {
  std::vector<double> t, z, roll;
};

Decay free_decay(double dz, double droll_deg, double duration, double b33 = 0.0) {
  io::Model model = io::load_model_text(barge_model(b33), "barge.yaml");
  System& sys = *model.system;
  State s = sys.initial_state();
  solve_statics(sys, s, model.statics);
  s.q[2] += dz;
  s.q.segment<4>(3) = math::euler_parameters_from_rotation(
      math::rotation_from_roll_pitch_yaw(droll_deg * kPi / 180, 0, 0));
  s.v.setZero();
  Rk4Augmented rk4;
  const double h = 0.01;
  Decay d;
  sys.start(s);
  for (int k = 0; k <= static_cast<int>(duration / h); ++k) {
    d.t.push_back(s.t);
    d.z.push_back(s.q[2]);
    d.roll.push_back(math::roll_pitch_yaw_from_rotation(
        math::rotation_from_euler_parameters(s.q.segment<4>(3)))[0]);
    const StepReport r = rk4.step(sys, s, h);
    EXPECT_TRUE(r.ok) << r.message;
    if (!r.ok) break;
    s.t = (k + 1) * h;
    sys.accept_step(s);
  }
  return d;
}

TEST(FloatingBox, HeaveNaturalPeriod) {
  const double draft = kMass / (kRho * kL * kB);
  const double z_eq = kH / 2 - draft;
  const double T3 = 2 * kPi * std::sqrt((kMass + kA33) / (kRho * kG * kL * kB));
  const Decay d = free_decay(0.1, 0.0, 5 * T3);
  // wall-sided box: heave is exactly linear; RK4 with h = T/480 has a period error of
  // O((w h)^4) ~ 1e-8. 2 % asked by the issue; 1e-4 asserted (zero-crossing interpolation).
  EXPECT_NEAR(period_of(d.t, d.z, z_eq), T3, 1e-4 * T3);
  std::printf("barge heave period: %.5f s (analytic %.5f s)\n", period_of(d.t, d.z, z_eq), T3);
}

TEST(FloatingBox, RollNaturalPeriod) {
  const double draft = kMass / (kRho * kL * kB);
  const double V = kL * kB * draft;
  // CG at the box centre: z_G - z_B = (kH/2 - draft) - (-draft/2) in water axes
  const double GM = -(kH / 2 - draft / 2) + kB * kB / (12 * draft);
  const double T4 = 2 * kPi * std::sqrt((kIxx + kA44) / (kRho * kG * V * GM));
  const Decay d = free_decay(0.0, 2.0, 5 * T4);
  // at 2 deg the wall-sided GZ is sin(phi)(GM + BM tan^2(phi)/2): the restoring moment is
  // 0.06 % stiffer than linear, the period ~0.03 % shorter; asserted within 0.2 % (the
  // issue asks 2 %).
  EXPECT_NEAR(period_of(d.t, d.roll, 0.0), T4, 2e-3 * T4);
  std::printf("barge roll period: %.5f s (analytic %.5f s)\n", period_of(d.t, d.roll, 0.0), T4);
}

TEST(FloatingBox, LinearDampingGivesTheDampedOscillator) {
  // constant heave damping B33 and no memory: x'' (m + A33) + B33 x' + C33 x = 0, whose
  // free decay from x0 at rest is x0 e^{-z w t} (cos(wd t) + z/sqrt(1 - z^2) sin(wd t)).
  const double mt = kMass + kA33, C = kRho * kG * kL * kB;
  const double w = std::sqrt(C / mt), zeta = 0.1, b33 = 2 * zeta * std::sqrt(C * mt);
  const double wd = w * std::sqrt(1 - zeta * zeta), x0 = 0.1;
  const double z_eq = kH / 2 - kMass / (kRho * kL * kB);
  const Decay d = free_decay(x0, 0.0, 3 * 2 * kPi / w, b33);
  double err = 0.0;
  for (std::size_t i = 0; i < d.t.size(); ++i) {
    const double t = d.t[i];
    const double ref = x0 * std::exp(-zeta * w * t) *
                       (std::cos(wd * t) + zeta / std::sqrt(1 - zeta * zeta) * std::sin(wd * t));
    err = std::max(err, std::abs(d.z[i] - z_eq - ref));
  }
  // RK4 with h = T/500: global error ~ (w h)^4 ~ 2e-7 of x0; 1e-5 x0 asserted
  EXPECT_LT(err, 1e-5 * x0);
}

}  // namespace
