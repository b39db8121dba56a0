// Seabed contact of rigid-body points verified against hand calculations
// (docs/verification.md section "Seabed contact of rigid-body points"): a clump weight (a
// 2 m x 2 m x 0.5 m steel box touching the seabed at its four lower corners) rests on a
// flat seabed with its submerged weight W on the contact, each corner sinking W/(4k), in
// statics and after a drop; on a plane sloping by theta it holds (creeping at the speed the
// regularized friction allows) while tan(theta) < mu, and slides with the acceleration
// g' (sin(theta) - mu cos(theta)), g' = W/m, when tan(theta) > mu.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
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

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kG = 9.81, kRhoWater = 1025.0, kDepth = 100.0;
// the box: 2 x 2 x 0.5 m of steel (7850 kg/m^3), corners 1 m from its centre, 0.25 m below
constexpr double kMass = 7850.0 * 2.0, kVolume = 2.0, kHalfHeight = 0.25;
const double kWeight = (kMass - kRhoWater * kVolume) * kG;  // submerged, N
const double kGravity = kWeight / kMass;                    // g' (m/s^2)
// the seabed's 1e6 N/m/m^2 on a contact area of 1 m^2 per corner
constexpr double kStiffness = 1e6;  // N/m per corner
constexpr double kMu = 0.5, kSlip = 0.01;

// the box at CG position (x, z) turned by pitch (deg), on a seabed `shape` (YAML keys)
std::string model(const std::string& shape, double x, double z, double pitch,
                  const std::string& extra) {
  return fmt::format(R"(
environment:
  gravity: {g}
  water: {{density: {rw}, depth: {depth}}}
  seabed:
    {shape}
    normal_stiffness: 1.0e6
    damping: 0.3
    friction: {mu}
    slip_velocity: {vs}
    points:
      - body: clump
        points: [[1, 1, -0.25], [-1, 1, -0.25], [-1, -1, -0.25], [1, -1, -0.25]]
        area: 1.0
bodies:
  clump:
    type: rigid_body
    mass: {m}
    inertia: [5560.4, 5560.4, 10466.7]
    position: [{x}, 0, {z}]
    orientation: [0, {pitch}, 0]
hydrodynamics:
  clump:
    hull:
      - box: {{center: [0, 0, 0], size: [2, 2, 0.5]}}
{extra})",
                     fmt::arg("g", kG), fmt::arg("rw", kRhoWater), fmt::arg("depth", kDepth),
                     fmt::arg("shape", shape), fmt::arg("mu", kMu), fmt::arg("vs", kSlip),
                     fmt::arg("m", kMass), fmt::arg("x", x), fmt::arg("z", z),
                     fmt::arg("pitch", pitch), fmt::arg("extra", extra));
}

MemoryRecorder run(const std::string& text, double duration) {
  io::Model m = io::load_model_text(text + fmt::format(R"(
dynamics:
  integrator: generalized_alpha
  time_step: 0.01
  duration: {}
  output_interval: 0.1
)",
                                                       duration),
                                    "clump.yaml");
  State s = m.system->initial_state();
  auto integrator = m.dynamics->make_integrator();
  MemoryRecorder rec;
  Simulation sim(*m.system, io::model_channels(m), *integrator, m.dynamics->simulation());
  sim.add_recorder(rec);
  sim.run(s);
  return rec;
}

double at(const MemoryRecorder& rec, const std::string& name, double t) {
  const std::size_t c = rec.column(name);
  for (std::size_t i = 0; i < rec.times.size(); ++i)
    if (std::abs(rec.times[i] - t) < 1e-9) return rec.rows[i][c];
  ADD_FAILURE() << "no row at t = " << t;
  return 0.0;
}

}  // namespace

// Statics on a flat seabed, from the box just touching it: the contact carries the
// submerged weight (1e-6 relative, the statics tolerance of 1e-8 of the largest force term
// leaves ~1e-8), a quarter on each corner, and the box sinks W/(4k) (1e-6 of it), level.
// x, y and yaw have no stiffness and no load: statics leaves them where they are.
TEST(RigidBodySeabedContact, ClumpRestsOnItsSubmergedWeight) {
  io::Model m =
      io::load_model_text(model("shape: flat", 0.0, -kDepth + kHalfHeight, 0.0, ""), "clump.yaml");
  State s = m.system->initial_state();
  solve_statics(*m.system, s, m.statics);
  const double sink = kWeight / (4 * kStiffness);
  const double force = channel(m, s, "clump.seabed.force");
  const double z = channel(m, s, "clump.z");
  std::printf("submerged weight %.6f N, contact %.6f N; sink %.9f m (W/4k %.9f m)\n", kWeight,
              force, -kDepth + kHalfHeight - z, sink);
  EXPECT_NEAR(force, kWeight, 1e-6 * kWeight);
  for (int i = 0; i < 4; ++i)
    EXPECT_NEAR(channel(m, s, fmt::format("clump.seabed.p{}.force", i)), kWeight / 4,
                1e-6 * kWeight / 4)
        << i;
  EXPECT_NEAR(z, -kDepth + kHalfHeight - sink, 1e-6 * sink);
  EXPECT_NEAR(channel(m, s, "clump.roll"), 0.0, 1e-9);
  EXPECT_NEAR(channel(m, s, "clump.pitch"), 0.0, 1e-9);
  EXPECT_NEAR(channel(m, s, "clump.seabed.friction"), 0.0, 1e-9);  // at rest
}

// Dropped from 0.5 m above the seabed (it hits at about 2.9 m/s), the box bounces on the
// damped contact (zeta = 0.3) and settles after 10 s at the statics penetration W/(4k)
// (1e-6 of it), at rest (1e-6 m/s), with the contact force W (1e-6); the impact pressed
// it deeper than that and the contact never pulled.
TEST(RigidBodySeabedContact, DroppedClumpSettles) {
  const MemoryRecorder rec =
      run(model("shape: flat", 0.0, -kDepth + kHalfHeight + 0.5, 0.0, ""), 10.0);
  const double sink = kWeight / (4 * kStiffness);
  const auto& last = rec.rows.back();
  const double z = last[rec.column("clump.z")];
  double deepest = 0.0, largest = 0.0;
  for (const auto& row : rec.rows) {
    deepest = std::max(deepest, -kDepth + kHalfHeight - row[rec.column("clump.z")]);
    largest = std::max(largest, row[rec.column("clump.seabed.force")]);
    EXPECT_GE(row[rec.column("clump.seabed.force")], 0.0);
  }
  std::printf("settled: sink %.9f m (W/4k %.9f m), deepest %.4f m, largest force %.0f N\n",
              -kDepth + kHalfHeight - z, sink, deepest, largest);
  EXPECT_NEAR(z, -kDepth + kHalfHeight - sink, 1e-6 * sink);
  EXPECT_NEAR(last[rec.column("clump.vz")], 0.0, 1e-6);
  EXPECT_NEAR(last[rec.column("clump.seabed.force")], kWeight, 1e-6 * kWeight);
  EXPECT_GT(deepest, 1.5 * sink);
  EXPECT_GT(largest, 1.5 * kWeight);
}

namespace {

// the box laid on a plane falling by theta (deg) along x, its bottom parallel to the plane
// and pressed in by W cos(theta)/(4k), for `duration` s: (rows, the downhill unit vector)
MemoryRecorder on_slope(double theta, double duration) {
  const double t = theta * kDeg;
  const Vec3 n(std::sin(t), 0.0, std::cos(t));  // the plane's normal
  const double sink = kWeight * std::cos(t) / (4 * kStiffness);
  const Vec3 cg = Vec3(0, 0, -kDepth) + (kHalfHeight - sink) * n;
  return run(model(fmt::format("shape: plane\n    slope: {}\n    direction: 0", theta), cg.x(),
                   cg.z(), theta, ""),
             duration);
}

// the distance travelled downhill (m) at time t
double downhill(const MemoryRecorder& rec, double theta, double t) {
  const double a = theta * kDeg;
  return at(rec, "clump.x", t) * std::cos(a) - at(rec, "clump.z", t) * std::sin(a);
}
double downhill_speed(const MemoryRecorder& rec, double theta, double t) {
  const double a = theta * kDeg;
  return at(rec, "clump.vx", t) * std::cos(a) - at(rec, "clump.vz", t) * std::sin(a);
}

}  // namespace

// Below the friction angle (theta = 15 deg, tan(theta) = 0.268 < mu = 0.5) the box holds:
// the friction carries the downhill pull W sin(theta) (1e-6 relative) and the normal force is
// W cos(theta) (1e-6), and it only creeps, at v_s r/sqrt(1 - r^2) with r = tan(theta)/mu
// (6.35 mm/s for v_s = 0.01 m/s): the regularized law's steady speed, asserted within 1e-4.
// From t = 1 s on it never exceeds that bound (by more than 1e-4): in the start-up the
// friction's moment shifts load from the uphill to the downhill corners, and the box pitches
// by 0.13 deg through the damped contact, the speed peaking at 13.9 mm/s at 0.06 s; that is
// over (to 1e-5 of the creep speed) before 1 s.
TEST(RigidBodySeabedContact, ClumpHoldsBelowTheFrictionAngle) {
  const double theta = 15.0, a = theta * kDeg;
  const MemoryRecorder rec = on_slope(theta, 3.0);
  const double r = std::tan(a) / kMu;
  const double creep = kSlip * r / std::sqrt(1 - r * r);
  const double v = downhill_speed(rec, theta, 3.0);
  const double friction = at(rec, "clump.seabed.friction", 3.0);
  std::printf("creep %.9f m/s (bound %.9f m/s); friction %.6f N (W sin %.6f N)\n", v, creep,
              friction, kWeight * std::sin(a));
  EXPECT_NEAR(v, creep, 1e-4 * creep);
  EXPECT_NEAR(friction, kWeight * std::sin(a), 1e-6 * kWeight);
  EXPECT_NEAR(at(rec, "clump.seabed.force", 3.0), kWeight * std::cos(a), 1e-6 * kWeight);
  for (std::size_t i = 0; i < rec.times.size(); ++i) {
    if (rec.times[i] < 1.0 - 1e-9) continue;
    EXPECT_LE(downhill_speed(rec, theta, rec.times[i]), creep * (1 + 1e-4)) << rec.times[i];
  }
  // from 1 s to 3 s it crept 2 s x 6.35 mm/s (1e-4)
  const double crept = downhill(rec, theta, 3.0) - downhill(rec, theta, 1.0);
  EXPECT_NEAR(crept, 2.0 * creep, 1e-4 * 2.0 * creep);
}

// Above the friction angle (theta = 35 deg, tan(theta) = 0.70 > mu = 0.5) the box slides
// with a = g' (sin(theta) - mu cos(theta)) = 1.399 m/s^2: the second difference of its
// downhill position s(3) - 2 s(2.5) + s(2) equals a (0.5 s)^2 within 1e-4 relative
// (generalized-alpha is exact for a constant acceleration; the regularization lowers the
// friction by mu N v_s^2/(2 v^2), below 1e-5 of a once v > 2.8 m/s at t = 2 s; the
// corners' loads have settled through the damped contact long before).
TEST(RigidBodySeabedContact, ClumpSlidesAboveTheFrictionAngle) {
  const double theta = 35.0, a = theta * kDeg;
  const MemoryRecorder rec = on_slope(theta, 3.0);
  const double expected = kGravity * (std::sin(a) - kMu * std::cos(a));
  const double second =
      downhill(rec, theta, 3.0) - 2 * downhill(rec, theta, 2.5) + downhill(rec, theta, 2.0);
  std::printf(
      "a dt^2 %.9f m (g' (sin - mu cos) dt^2 = %.9f m); friction %.3f N (mu W cos %.3f N)\n",
      second, expected * 0.25, at(rec, "clump.seabed.friction", 3.0), kMu * kWeight * std::cos(a));
  EXPECT_NEAR(second, expected * 0.25, 1e-4 * expected * 0.25);
  EXPECT_NEAR(at(rec, "clump.seabed.friction", 3.0), kMu * kWeight * std::cos(a),
              1e-5 * kMu * kWeight * std::cos(a));
  EXPECT_NEAR(at(rec, "clump.seabed.force", 3.0), kWeight * std::cos(a), 1e-6 * kWeight);
}
