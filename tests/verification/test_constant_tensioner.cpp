// The constant-tension tensioner (connection type `tensioner`, constant_tensioner.hpp)
// verified against closed forms (docs/verification.md, section "Constant-tension
// tensioner"). A rigid body of mass m hangs below a fixed point on the tensioner and slides
// on a vertical prismatic joint to ground; the tensioner's stroke s = L - L_ref is the
// body's drop below its initial position, and its equation of motion is
//   m s'' = m g - T0 - k s - c s' - k_stop (s - s_max) [s > s_max].
//   - statics: s = (m g - T0) / k, and on the upper stop
//     s = s_max + (m g - T0 - k s_max) / (k + k_stop);
//   - free vibration about it: period 2 pi / (w_n sqrt(1 - zeta^2)), w_n = sqrt(k / m),
//     zeta = c / (2 sqrt(k m)) (a linear oscillator, e.g. Thomson & Dahleh, Theory of
//     Vibration with Applications, 5th ed., sec. 2.6);
//   - k = 0: constant acceleration (m g - T0) / m down to the stop, then a half-oscillation
//     on k_stop and back; energy (kinetic + gravity + tensioner potential) conserved.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>

#include "memory_recorder.hpp"
#include "seaflex/io/model_loader.hpp"
#include "seaflex/simulation/simulation.hpp"
#include "seaflex/solvers/statics.hpp"

using namespace seaflex;
using seaflex::testing::MemoryRecorder;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kG = 9.81, kM = 1000.0, kL = 10.0;  // gravity, mass, reference length

struct Tensioner {
  double T0 = 0.0, k = 0.0, c = 0.0;
  std::optional<std::pair<double, double>> limits;
  double k_stop = 0.0;
  double reference_length = 0.0;  // 0: not given (the distance at the start, kL)
};

// the body hangs kL below the fixed point at the start: L_ref = kL, stroke 0
std::string model_text(const Tensioner& t, const std::string& dynamics) {
  std::string stops;
  if (t.limits)
    stops = fmt::format("\n    stroke_limits: [{}, {}]\n    stop_stiffness: {}", t.limits->first,
                        t.limits->second, t.k_stop);
  if (t.reference_length > 0.0)
    stops += fmt::format("\n    reference_length: {}", t.reference_length);
  return fmt::format(R"(
environment: {{gravity: {g}}}
bodies:
  mass: {{type: rigid_body, mass: {m}, inertia: [10, 10, 10], position: [0, 0, {z0}]}}
joints:
  - {{name: guide, type: prismatic, from: {{body: ground, position: [0, 0, {z0}], axis: [0, 0, 1]}},
     to: {{body: mass, position: [0, 0, 0], axis: [0, 0, 1]}}}}
connections:
  - name: top
    type: tensioner
    from: {{body: ground, position: [0, 0, 0]}}
    to: {{body: mass, position: [0, 0, 0]}}
    tension: {T0}
    stiffness: {k}
    damping: {c}{stops}
{dynamics}
)",
                     fmt::arg("g", kG), fmt::arg("m", kM), fmt::arg("z0", -kL),
                     fmt::arg("T0", t.T0), fmt::arg("k", t.k), fmt::arg("c", t.c),
                     fmt::arg("stops", stops), fmt::arg("dynamics", dynamics));
}

struct Recorded {
  MemoryRecorder rec;
  std::vector<double> col(const std::string& name) const {
    const std::size_t c = rec.column(name);
    std::vector<double> v;
    for (const auto& row : rec.rows) v.push_back(row[c]);
    return v;
  }
};

// the dynamics from the model's geometry at rest, every step in memory, with the total
// energy as the channel "energy"
void simulate(const std::string& text, Recorded& out) {
  io::Model m = io::load_model_text(text, "tensioner.yaml");
  System& sys = *m.system;
  ChannelList channels = io::model_channels(m);
  channels.push_back({"energy", [&sys](const State& s) { return sys.energies(s).total(); }});
  auto integrator = m.dynamics->make_integrator();
  Simulation sim(sys, channels, *integrator, m.dynamics->simulation());
  sim.add_recorder(out.rec);
  State s = sys.initial_state();
  sim.run(s);
}

// the times at which x - x0 changes sign upwards, linearly interpolated
std::vector<double> up_crossings(const std::vector<double>& t, const std::vector<double>& x,
                                 double x0) {
  std::vector<double> out;
  for (std::size_t i = 1; i < x.size(); ++i)
    if (x[i - 1] - x0 < 0.0 && x[i] - x0 >= 0.0)
      out.push_back(t[i - 1] + (t[i] - t[i - 1]) * (x0 - x[i - 1]) / (x[i] - x[i - 1]));
  return out;
}

// the local maxima of x, refined by the parabola through the three samples around each
std::vector<double> peaks(const std::vector<double>& x) {
  std::vector<double> out;
  for (std::size_t i = 1; i + 1 < x.size(); ++i)
    if (x[i] > x[i - 1] && x[i] >= x[i + 1]) {
      const double a = 0.5 * (x[i - 1] + x[i + 1]) - x[i], b = 0.5 * (x[i + 1] - x[i - 1]);
      out.push_back(a < 0.0 ? x[i] - b * b / (4.0 * a) : x[i]);
    }
  return out;
}

}  // namespace

// Statics with the full load in one increment: Newton on a piecewise linear problem lands
// on the equilibrium (one iteration on the slope k; one more after crossing the stop). The
// statics tolerance (relative residual 1e-8 of the largest force, m g) bounds the stroke's
// error by 1e-8 m g / k = 1e-8 m here, and the tolerance is 2e-8 m. The tension balances
// the weight, m g, to 1e-8 relative for the same reason.
TEST(ConstantTensioner, StaticsStrokeWithAndWithoutTheStop) {
  const double k = 1e4, T0 = 0.8 * kM * kG, k_stop = 1e5, s_max = 0.1;
  struct Case {
    const char* label;
    Tensioner t;
    double expected;
  };
  const std::vector<Case> cases = {
      {"free stroke", {T0, k, 50.0, std::nullopt, 0.0}, (kM * kG - T0) / k},
      {"unlimited range, not reached",
       {T0, k, 0.0, std::make_pair(-1.0, 1.0), k_stop},
       (kM * kG - T0) / k},
      {"on the upper stop",
       {T0, k, 0.0, std::make_pair(-0.05, s_max), k_stop},
       s_max + (kM * kG - T0 - k * s_max) / (k + k_stop)},
      {"reference length 9.9 m given, on the upper stop",
       {T0, k, 0.0, std::make_pair(-0.05, s_max), k_stop, kL - 0.1},
       s_max + (kM * kG - T0 - k * s_max) / (k + k_stop)},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.label);
    io::Model m = io::load_model_text(model_text(c.t, ""), "tensioner.yaml");
    State s = m.system->initial_state();
    const StaticsReport rep = solve_statics(*m.system, s, m.statics);  // throws if it fails
    double stroke = 0.0, tension = 0.0, length = 0.0, z = 0.0;
    for (const auto& ch : io::model_channels(m)) {
      if (ch.name == "top.stroke") stroke = ch.value(s);
      if (ch.name == "top.tension") tension = ch.value(s);
      if (ch.name == "top.length") length = ch.value(s);
      if (ch.name == "mass.z") z = ch.value(s);
    }
    EXPECT_NEAR(stroke, c.expected, 2e-8);
    // the body hangs the reference length plus the stroke below the fixed point
    const double L_ref = c.t.reference_length > 0.0 ? c.t.reference_length : kL;
    EXPECT_NEAR(-z, L_ref + c.expected, 2e-8);
    EXPECT_NEAR(length, L_ref + c.expected, 2e-8);
    EXPECT_NEAR(tension, kM * kG, 1e-8 * kM * kG);
    std::printf("statics, %s: stroke %.9f m (closed form %.9f m), %d iterations\n", c.label, stroke,
                c.expected, rep.iterations);
  }
  // the stop case really is on the stop (1.09 times s_max), the others below s_max
  EXPECT_GT(cases[2].expected, 1.08 * s_max);
}

// Free vibration from rest at zero stroke about the equilibrium s_e = (m g - T0) / k
// (amplitude s_e = 0.196 m): w_n = sqrt(k/m) = 3.16 rad/s, undamped and zeta = 0.05.
// Generalized-alpha (rho_inf 0.8) at h = 1 ms, w_n h = 3.2e-3: its period error is
// O((w_n h)^2), about (w_n h)^2 / 12 = 8e-7 relative (measured 8.8e-7), and its numerical
// damping ratio O((w_n h)^3), 3e-8. The period is the mean spacing of the crossings of s_e
// in one direction (linear interpolation between steps, exact to O(h^3) where the curve is
// nearly straight), held to 1e-5 relative (ten times the scheme's error); the damping ratio
// from the logarithmic decrement of the first and last peaks (parabola-refined: peak error
// ~ (w_n h)^3 of the amplitude) to 1e-4 relative (measured 2e-6), and the undamped
// amplitude stays s_e to 1e-4 relative (the scheme conserves it to O((w_n h)^3)).
TEST(ConstantTensioner, FreeVibrationPeriodAndDampingRatio) {
  const double k = 1e4, T0 = 0.8 * kM * kG, wn = std::sqrt(k / kM);
  const double s_e = (kM * kG - T0) / k;
  for (double zeta : {0.0, 0.05}) {
    SCOPED_TRACE("zeta " + std::to_string(zeta));
    const double c = 2.0 * zeta * std::sqrt(k * kM);
    Recorded run;
    simulate(
        model_text({T0, k, c, std::nullopt, 0.0},
                   "dynamics: {integrator: generalized_alpha, time_step: 0.001, duration: 10}"),
        run);
    const auto s = run.col("top.stroke");
    // crossings of s_e in one direction are whole periods apart
    const auto tc = up_crossings(run.rec.times, s, s_e);
    ASSERT_GE(tc.size(), 4u);
    const double period = (tc.back() - tc.front()) / static_cast<double>(tc.size() - 1);
    const double expected = 2 * kPi / (wn * std::sqrt(1.0 - zeta * zeta));
    EXPECT_NEAR(period / expected, 1.0, 1e-5) << period << " s, closed form " << expected;
    const auto pk = peaks(s);  // maxima of the stroke: s_e + A_i
    ASSERT_GE(pk.size(), 3u);
    if (zeta == 0.0) {
      for (double p : pk) EXPECT_NEAR(p - s_e, s_e, 1e-4 * s_e);
      EXPECT_NEAR(period / (2 * kPi * std::sqrt(kM / k)), 1.0, 1e-5);
    } else {
      // delta = ln(A_i / A_{i+1}) = 2 pi zeta / sqrt(1 - zeta^2), averaged over the run
      const double n = static_cast<double>(pk.size() - 1);
      const double delta = std::log((pk.front() - s_e) / (pk.back() - s_e)) / n;
      const double measured = delta / std::sqrt(4 * kPi * kPi + delta * delta);
      EXPECT_NEAR(measured / zeta, 1.0, 1e-4) << "damping ratio " << measured;
      std::printf("damped: damping ratio %.8f (c / (2 sqrt(k m)) = %.8f)\n", measured, zeta);
    }
    std::printf("zeta %.2f: period %.7f s (closed form %.7f s, error %.2e)\n", zeta, period,
                expected, period / expected - 1.0);
  }
}

// Constant tension (k = 0) at T0 = 0.9 m g with the stops at -/+0.5 m (k_stop = 1e6 N/m) and
// no damping: from rest at s = 0 the body sinks at a = (m g - T0) / m = 0.981 m/s^2, reaches
// s_max at t* = sqrt(2 s_max / a) with v* = a t*, then moves on the stop about
// s_s = s_max + (m g - T0) / k_stop with w = sqrt(k_stop / m) = 31.6 rad/s and amplitude
// R = sqrt(((m g - T0) / k_stop)^2 + (v* / w)^2), leaving it after (pi + 2 atan(w (m g -
// T0) / (k_stop v*))) / w, and rises back to s = 0 at rest. Generalized-alpha at h = 1 ms
// (w h = 0.032 on the stop):
//   - the fall is a constant acceleration, which the scheme integrates exactly: s = a t^2/2
//     to 1e-9 m (the Newton tolerance's share);
//   - t* from the interpolated crossing of s_max, to 1e-6 s (the crossing lies on the exact
//     parabola; linear interpolation over a 1 ms chord of it errs by a h^2 / 8 / v* ~ 1e-7 s);
//   - the deepest stroke s_s + R to 5e-4 of R: the entry into the stop falls inside a step
//     where the force has a kink, a first-order error of about (v* h)^2 k_stop / (m v*^2) =
//     h^2 k_stop / m = 1e-3 of the impact energy, 5e-4 of R (R^2 goes with the energy;
//     measured 1.2e-4);
//   - the time it leaves the stop to 1e-4 s (a tenth of a step; measured 1e-5 s);
//   - the energy to 1e-3 of the impact's kinetic energy m v*^2 / 2 (the same kink error at
//     each of the two crossings; rho_inf 0.8 damps w h = 0.032 by ~1e-6 per cycle; measured
//     2.5e-4);
//   - the bounce returns to s = 0 (to 1e-3 m: the energy tolerance over m g).
TEST(ConstantTensioner, ConstantTensionFallsOntoTheStopAndConservesEnergy) {
  const double T0 = 0.9 * kM * kG, s_max = 0.5, k_stop = 1e6;
  const double a = (kM * kG - T0) / kM, t_star = std::sqrt(2 * s_max / a), v_star = a * t_star;
  const double w = std::sqrt(k_stop / kM), delta = (kM * kG - T0) / k_stop;
  const double R = std::hypot(delta, v_star / w), deepest = s_max + delta + R;
  const double t_off = t_star + (kPi + 2 * std::atan(w * delta / v_star)) / w;
  const double t_back = t_off + t_star;
  Recorded run;
  simulate(model_text({T0, 0.0, 0.0, std::make_pair(-s_max, s_max), k_stop},
                      fmt::format("dynamics: {{integrator: generalized_alpha, time_step: 0.001, "
                                  "duration: {:.3f}}}",
                                  std::ceil((t_back + 0.1) * 1000.0) / 1000.0)),
           run);
  const auto& t = run.rec.times;
  const auto s = run.col("top.stroke"), T = run.col("top.tension"), E = run.col("energy");
  // the fall
  double fall_err = 0.0;
  for (std::size_t i = 0; i < t.size() && t[i] < t_star - 1e-3; ++i) {
    fall_err = std::max(fall_err, std::abs(s[i] - 0.5 * a * t[i] * t[i]));
    EXPECT_NEAR(T[i], T0, 1e-9 * T0);  // constant tension while the stroke is free
  }
  EXPECT_LT(fall_err, 1e-9);
  // onto the stop (s rising through s_max) and off it (s falling through s_max)
  const auto on = up_crossings(t, s, s_max);
  std::vector<double> neg(s.size());
  for (std::size_t i = 0; i < s.size(); ++i) neg[i] = -s[i];
  const auto off = up_crossings(t, neg, -s_max);
  ASSERT_GE(on.size(), 1u);
  ASSERT_GE(off.size(), 1u);
  EXPECT_NEAR(on.front(), t_star, 1e-6);
  EXPECT_NEAR(off.front(), t_off, 1e-4);
  const auto pk = peaks(s);
  ASSERT_GE(pk.size(), 1u);
  const double s_deep = *std::max_element(pk.begin(), pk.end());
  EXPECT_NEAR(s_deep, deepest, 5e-4 * R);
  // energy
  double e_err = 0.0;
  for (double e : E) e_err = std::max(e_err, std::abs(e - E.front()));
  const double e_impact = 0.5 * kM * v_star * v_star;
  EXPECT_LT(e_err, 1e-3 * e_impact);
  // back up to the start at rest, near t_back
  std::size_t top = 0;
  for (std::size_t i = 0; i < t.size(); ++i)
    if (t[i] > t_star + 0.5 && (top == 0 || s[i] < s[top])) top = i;
  EXPECT_NEAR(s[top], 0.0, 1e-3);
  EXPECT_NEAR(t[top], t_back, 0.05);  // a flat apex: 1e-3 m of s is 0.045 s of time
  std::printf(
      "stop: fall error %.2e m, t* %.7f s (closed form %.7f s), deepest %.7f m (closed form "
      "%.7f m, error %.2e of R), off at %.7f s (%.7f s), energy drift %.2e of the impact energy, "
      "back at %.4f s (%.4f s) to %.2e m\n",
      fall_err, on.front(), t_star, s_deep, deepest, (s_deep - deepest) / R, off.front(), t_off,
      e_err / e_impact, t[top], t_back, s[top]);
}
