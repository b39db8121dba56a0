// S-N curves of DNV-RP-C203 (2016) (post/sn_curve.hpp): the formula of eq. (2.4.1) at several
// stress ranges for every tabulated curve, the typed table values against the table's own
// fatigue-limit column, the knee, user curves, and the thickness factor of eq. (2.4.3).
#include <gtest/gtest.h>

#include <cmath>

#include "seaflex/post/fatigue_damage.hpp"
#include "seaflex/post/sn_curve.hpp"

namespace seaflex::post {
namespace {

constexpr double kMpa = 1e6;

// eq. (2.4.1): log N = log a - m log dsigma, the first segment while N <= N_knee
double expected_cycles(const SnCurve& c, double s_mpa) {
  const double n1 = std::pow(10.0, c.log_a1 - c.m1 * std::log10(s_mpa));
  if (c.n_knee == 0.0 || n1 <= c.n_knee) return n1;
  return std::pow(10.0, c.log_a2 - c.m2 * std::log10(s_mpa));
}

TEST(SnCurve, FormulaForEveryTabulatedCurve) {
  EXPECT_EQ(dnv_curve_names().size(), 15u);
  for (const auto& name : dnv_curve_names())
    for (auto env :
         {SnEnvironment::kAir, SnEnvironment::kSeawaterCp, SnEnvironment::kFreeCorrosion}) {
      const auto c = dnv_curve(name, env);
      ASSERT_TRUE(c) << name;
      for (double s : {5.0, 20.0, 40.0, 60.0, 100.0, 250.0, 600.0}) {
        const double N = c->cycles(s * kMpa);
        // 1e-9 relative: the same formula, evaluated in another order
        EXPECT_NEAR(N, expected_cycles(*c, s), 1e-9 * N) << name << " " << s << " MPa";
        EXPECT_DOUBLE_EQ(c->damage(s * kMpa), 1.0 / N);
      }
    }
}

// The table's last column, the fatigue limit (stress range at 1e7 cycles, MPa), against the
// typed log a values: the stress at 1e7 on both segments in air, on the second segment with
// cathodic protection. Tolerance: the rounding of the printed values, log a to 3 decimals
// (2 for T: a relative ln(10) * 0.0005 / m) and the limit to 2 decimals (0.005 MPa). A typo
// in any digit but the last of log a, or in the limit, fails.
TEST(SnCurve, TableAgainstItsFatigueLimitColumn) {
  for (const auto& name : dnv_curve_names()) {
    const auto air = dnv_curve(name, SnEnvironment::kAir);
    const auto cp = dnv_curve(name, SnEnvironment::kSeawaterCp);
    ASSERT_TRUE(air && cp);
    const double limit = air->fatigue_limit_mpa;
    EXPECT_EQ(cp->fatigue_limit_mpa, limit);
    const double half_digit = name == "T" ? 0.005 : 0.0005;
    const auto tol = [&](double m) { return limit * std::log(10.0) * half_digit / m + 0.005; };
    const double s1 = std::pow(10.0, (air->log_a1 - 7.0) / air->m1);
    const double s2 = std::pow(10.0, (air->log_a2 - 7.0) / air->m2);
    EXPECT_NEAR(s1, limit, tol(air->m1)) << name;
    EXPECT_NEAR(s2, limit, tol(air->m2)) << name;
    const double s2cp = std::pow(10.0, (cp->log_a2 - 7.0) / cp->m2);
    EXPECT_NEAR(s2cp, limit, tol(cp->m2)) << name;
    // the segments meet at the knee (1e7 air, 1e6 CP, 1.8e6 T with CP), same tolerance
    const double k1 = cp->knee_stress() / kMpa;
    const double k2 = std::pow(10.0, (cp->log_a2 - std::log10(cp->n_knee)) / cp->m2);
    EXPECT_NEAR(k1, k2, k2 * std::log(10.0) * half_digit * (1.0 / cp->m1 + 1.0 / cp->m2)) << name;
    EXPECT_EQ(air->n_knee, 1e7);
    EXPECT_EQ(cp->n_knee, name == "T" ? 1.8e6 : 1e6);
  }
  // spot values typed from the standard: D in air 52.63 MPa, log a1 12.164; F with CP 11.455
  EXPECT_EQ(dnv_curve("D", SnEnvironment::kAir)->fatigue_limit_mpa, 52.63);
  EXPECT_EQ(dnv_curve("F", SnEnvironment::kSeawaterCp)->log_a1, 11.455);
  EXPECT_EQ(dnv_curve("D", SnEnvironment::kFreeCorrosion)->log_a1, 11.687);
  EXPECT_EQ(dnv_curve("D", SnEnvironment::kFreeCorrosion)->n_knee, 0.0);
  EXPECT_FALSE(dnv_curve("X9", SnEnvironment::kAir));
}

TEST(SnCurve, UserBilinearCurveMeetsAtItsKnee) {
  const SnCurve c = user_curve(3.0, 12.164, 5.0, 15.606);
  // the knee: log s* = (12.164 - 15.606) / (3 - 5) = 1.721, N* = 10^(12.164 - 3 * 1.721)
  EXPECT_NEAR(std::log10(c.n_knee), 12.164 - 3.0 * 1.721, 1e-12);
  EXPECT_NEAR(c.cycles(c.knee_stress() * (1 + 1e-12)), c.n_knee, 1e-9 * c.n_knee);
  EXPECT_NEAR(c.cycles(30 * kMpa), std::pow(10.0, 15.606 - 5 * std::log10(30.0)), 1.0);
  const SnCurve one = user_curve(4.0, 15.0);
  EXPECT_NEAR(one.cycles(100 * kMpa), 1e7, 1e-9 * 1e7);
  EXPECT_THROW(user_curve(3.0, 12.0, 3.0, 13.0), std::invalid_argument);
}

// DNV-RP-C203 (2016) eq. (2.4.3): (t/t_ref)^k above t_ref, 1 below; with SCF the stress
// range becomes SCF (t/t_ref)^k dsigma. D curve (k = 0.20, t_ref 25 mm), t = 50 mm:
// factor 2^0.2 = 1.148698355; with SCF 1.3 a nominal 40 MPa range is 59.73231446 MPa and
// N = 10^(12.164 - 3 log10(59.73231446)) = 6.8710e5 (hand calculation).
TEST(SnCurve, ThicknessCorrectionAndScf) {
  const SnCurve d = *dnv_curve("D", SnEnvironment::kAir);
  EXPECT_EQ(d.k, 0.20);
  EXPECT_EQ(d.t_ref, 0.025);
  EXPECT_NEAR(thickness_factor(0.050, d.t_ref, d.k), 1.148698355, 1e-9);
  EXPECT_EQ(thickness_factor(0.020, d.t_ref, d.k), 1.0);
  const double factor = 1.3 * thickness_factor(0.050, d.t_ref, d.k);
  EXPECT_NEAR(factor * 40.0, 59.73231446, 1e-8);
  const double N = std::pow(10.0, 12.164) / std::pow(59.73231446, 3);
  EXPECT_NEAR(d.cycles(factor * 40.0 * kMpa), N, 1e-8 * N);
  // FatigueDamage applies the factor to each range: one cycle 0 -> 40 -> 0 MPa
  FatigueDamage fd(1, d, factor);
  for (double s : {0.0, 40.0, 0.0, 40.0, 0.0}) {
    const double x = s * kMpa;
    fd.add(std::span<const double>(&x, 1));
  }
  fd.finish();
  EXPECT_NEAR(fd.damage(0), 2.0 / N, 1e-9 / N);  // half + full + half cycles: 2 cycles
  // T curve: k = 0.30 above SCF 10, t_ref 16 mm
  EXPECT_EQ(dnv_curve("T", SnEnvironment::kAir, 12.0)->k, 0.30);
  EXPECT_EQ(dnv_curve("T", SnEnvironment::kAir, 5.0)->k, 0.25);
  EXPECT_EQ(dnv_curve("T", SnEnvironment::kAir)->t_ref, 0.016);
}

// Stresses around the circumference: a vertical pipe (t = z) with M = M_x x: at theta
// from e1 = x, sigma = T/A + (z x M_x x).n r/I = T/A + M_x r/I sin(theta).
TEST(PipeFibreStresses, AxialPlusBiaxialBending) {
  const double T = 1e6, A = 0.01, I = 2e-4, r = 0.2, Mx = 3e4, My = -1e4;
  std::vector<double> s(8);
  pipe_fibre_stresses(T, Vec3(Mx, My, 0), Vec3(0, 0, 2.0), circumference_reference(Vec3::UnitZ()),
                      A, I, r, s);
  for (int j = 0; j < 8; ++j) {
    const double th = 2 * M_PI * j / 8;
    // z x (Mx x + My y) = Mx y - My x: sigma_b = (Mx sin - My cos) r / I
    const double expected = T / A + (Mx * std::sin(th) - My * std::cos(th)) * r / I;
    EXPECT_NEAR(s[static_cast<std::size_t>(j)], expected, 1e-9 * std::abs(expected)) << j;
  }
}

}  // namespace
}  // namespace seaflex::post
