// Seabed contact verified against hand calculations (docs/verification.md section
// "Seabed"): a pipe lying on a flat seabed carries its submerged weight per length w on
// the contact (k d = w, so it sinks d = w/k), and a laid pipe pulled along or across
// its axis slides against Coulomb friction mu w L, or creeps (held) below it.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "memory_recorder.hpp"
#include "model_channel.hpp"
#include "seaflex/io/model_loader.hpp"
#include "seaflex/simulation/simulation.hpp"
#include "seaflex/solvers/statics.hpp"

using namespace seaflex;
using seaflex::testing::channel;
using seaflex::testing::MemoryRecorder;

namespace {

constexpr double kPi = std::numbers::pi;
// steel pipe OD 0.3 m, ID 0.2 m (empty) in sea water, on a seabed of 1e5 N/m/m^2
constexpr double kOd = 0.3, kId = 0.2, kRhoSteel = 7850, kRhoWater = 1025, kG = 9.81;
constexpr double kStiffnessArea = 1e5;
const double kMass = kRhoSteel * kPi / 4 * (kOd * kOd - kId * kId);     // kg/m
const double kWeight = (kMass - kRhoWater * kPi / 4 * kOd * kOd) * kG;  // submerged, N/m
const double kStiffness = kStiffnessArea * kOd;                         // N/m/m
const double kSink = kWeight / kStiffness;                              // m

// a 100 m pipe along x at depth z0 on a flat seabed at 100 m
std::string model(double z0, const std::string& extra) {
  return fmt::format(R"(
environment:
  gravity: {g}
  water: {{density: {rw}, depth: 100}}
  seabed:
    normal_stiffness: {k}
    friction: {{axial: 0.3, lateral: 0.6}}
    slip_velocity: 0.01
bodies:
  line:
    type: ancf_beam
    start: [0, 0, {z0}]
    end: [100, 0, {z0}]
    elements: 20
    outer_diameter: {od}
    inner_diameter: {id}
    youngs_modulus: 2.0e11
    density: {rs}
hydrodynamics:
  line: {{cd: 0, cm: 0}}
{extra})",
                     fmt::arg("g", kG), fmt::arg("rw", kRhoWater), fmt::arg("k", kStiffnessArea),
                     fmt::arg("z0", z0), fmt::arg("od", kOd), fmt::arg("id", kId),
                     fmt::arg("rs", kRhoSteel), fmt::arg("extra", extra));
}

}  // namespace

// Statics of the pipe held horizontally at its ends (x and y at the start, y at the end):
// the contact force per length equals w (the statics tolerance: 1e-6 relative), every
// node sinks w/k below the seabed (1e-6 of d), the whole length is laid.
TEST(SeabedContact, LaidLineCarriesItsSubmergedWeight) {
  io::Model m = io::load_model_text(model(-100.05, R"(
supports:
  - {body: line, node: start, type: fixed, fix: [x, y]}
  - {body: line, node: end, type: fixed, fix: [y]}
)"),
                                    "seabed.yaml");
  State s = m.system->initial_state();
  solve_statics(*m.system, s, m.statics);
  const double force = channel(m, s, "line.seabed.force");
  std::printf("submerged weight %.6f N/m, contact %.6f N/m; sink %.9f m (w/k %.9f m)\n", kWeight,
              force / 100.0, -100.0 - channel(m, s, "line.n10.z"), kSink);
  EXPECT_NEAR(force / 100.0, kWeight, 1e-6 * kWeight);
  for (int k = 0; k <= 20; ++k)
    EXPECT_NEAR(channel(m, s, fmt::format("line.n{}.z", k)), -100.0 - kSink, 1e-6 * kSink) << k;
  EXPECT_NEAR(channel(m, s, "line.seabed.laid_length"), 100.0, 1e-9);
  EXPECT_NEAR(channel(m, s, "line.seabed.friction"), 0.0, 1e-9);  // at rest
}

namespace {

// the free pipe, laid at its equilibrium depth, under a load per length q (N/m) along dir
// from t = 0: the rows of 2 s of generalized-alpha
MemoryRecorder pull(const Vec3& q) {
  io::Model m = io::load_model_text(model(-100.0 - kSink, fmt::format(R"(
loads:
  - {{type: distributed_load, body: line, load: [{}, {}, {}]}}
dynamics:
  integrator: generalized_alpha
  time_step: 0.01
  duration: 2
  output_interval: 0.1
)",
                                                                      q.x(), q.y(), q.z())),
                                    "seabed.yaml");
  State s = m.system->initial_state();
  auto integrator = m.dynamics->make_integrator();
  MemoryRecorder rec;
  Simulation sim(*m.system, io::model_channels(m), *integrator, m.dynamics->simulation());
  sim.add_recorder(rec);
  sim.run(s);
  return rec;
}

}  // namespace

// Pulled by twice its friction limit the pipe slides: the friction is mu w L (the
// regularization leaves mu w L v_s^2/(2 v^2) < 1e-5 of it once v > 2 m/s), and the pipe
// accelerates at a = (q - mu w)/m: the second difference of its position over the last
// second, x(2) - 2 x(1.5) + x(1), equals a (0.5 s)^2 (tolerance 1e-4; generalized-alpha is
// exact for a constant acceleration, and the start-up, where the regularized law gives
// less than mu w for about v_s/a = 2 ms, only shifts x and v). Across the axis mu = 0.6,
// along it 0.3.
TEST(SeabedContact, LaidLineSlidesAtTheFrictionLimit) {
  for (const auto& [dir, mu] : {std::pair{Vec3(0, 1, 0), 0.6}, {Vec3(1, 0, 0), 0.3}}) {
    const MemoryRecorder rec = pull(2.0 * mu * kWeight * dir);
    const auto& last = rec.rows.back();
    const double friction = last[rec.column("line.seabed.friction")];
    const std::size_t c = rec.column(dir.x() != 0.0 ? "line.n10.x" : "line.n10.y");
    auto at = [&](double t) {
      for (std::size_t i = 0; i < rec.times.size(); ++i)
        if (std::abs(rec.times[i] - t) < 1e-9) return rec.rows[i][c];
      ADD_FAILURE() << "no row at t = " << t;
      return 0.0;
    };
    const double second = at(2.0) - 2.0 * at(1.5) + at(1.0);
    const double expected = mu * kWeight / kMass * 0.25;
    std::printf("mu %.1f: friction %.3f N (mu w L %.3f N), a dt^2 %.9f m (%.9f m)\n", mu, friction,
                mu * kWeight * 100, second, expected);
    EXPECT_NEAR(friction, mu * kWeight * 100, 1e-5 * mu * kWeight * 100);
    EXPECT_NEAR(second, expected, 1e-4 * expected);
    EXPECT_NEAR(last[rec.column("line.seabed.force")], kWeight * 100, 1e-6 * kWeight * 100);
  }
}

// Pulled across its axis by half its friction limit the pipe holds: the friction equals
// the pull (1e-6), and the regularized law lets it creep at v = v_s r/sqrt(1 - r^2),
// r = 0.5 (5.77 mm/s), below the slip velocity (asserted within 1 %).
TEST(SeabedContact, LaidLineHoldsBelowTheFrictionLimit) {
  const double mu = 0.6, r = 0.5, vs = 0.01;
  const MemoryRecorder rec = pull(Vec3(0, r * mu * kWeight, 0));
  const auto& last = rec.rows.back();
  const double t = rec.times.back();
  const double friction = last[rec.column("line.seabed.friction")];
  const double moved = last[rec.column("line.n10.y")];
  const double creep = vs * r / std::sqrt(1 - r * r);
  std::printf("friction %.6f N (pull %.6f N), crept %.6e m (%.6e m)\n", friction,
              r * mu * kWeight * 100, moved, creep * t);
  EXPECT_NEAR(friction, r * mu * kWeight * 100, 1e-6 * mu * kWeight * 100);
  EXPECT_NEAR(moved, creep * t, 0.01 * creep * t);
}
