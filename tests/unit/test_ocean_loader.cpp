// The ocean's model-file input (io/load_ocean.cpp, io/load_bem.cpp): valid models build
// the expected forces and channels; bad input is rejected with file, line, column and key.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "seaflex/core/errors.hpp"
#include "seaflex/forces/rigid_body_load.hpp"
#include "seaflex/io/model_loader.hpp"

using namespace seaflex;

namespace {

const std::string kSphere = std::string(SEAFLEX_SOURCE_DIR) + "/tests/data/wamit/sphere/sphere";

const std::string kPipe = R"(environment:
  gravity: 9.81
  water: {density: 1025, depth: 100}
  current: {speed: 1.0, direction: 90}
bodies:
  pipe:
    type: ancf_beam
    start: [0, 0, -20]
    end: [30, 0, -20]
    elements: 3
    outer_diameter: 0.7
    inner_diameter: 0.4
    youngs_modulus: 210e9
    density: 7850
hydrodynamics:
  pipe: {cd: 0.65, cm: 1.6}
)";

std::string replace(std::string text, const std::string& from, const std::string& to) {
  const auto pos = text.find(from);
  EXPECT_NE(pos, std::string::npos) << from;
  if (pos != std::string::npos) text.replace(pos, from.size(), to);
  return text;
}

std::string error_of(const std::string& text) {
  try {
    io::load_model_text(text, "m.yaml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::string floating(const std::string& hydro, const std::string& env = "") {
  return "environment:\n  gravity: 9.81\n  water: {density: 1025, depth: 50}\n" + env +
         "bodies:\n  buoy:\n    type: rigid_body\n    mass: 268350\n    inertia: [1e6, 1e6, "
         "1e6]\n    position: [0, 0, -2]\nhydrodynamics:\n  buoy:\n" +
         hydro;
}

TEST(OceanLoader, BuildsMorisonForceAndWaveChannel) {
  const io::Model m = io::load_model_text(
      replace(kPipe, "  current:", "  wave_probes: {bow: [10, 2]}\n  current:"), "m.yaml");
  ASSERT_TRUE(m.ocean);
  EXPECT_DOUBLE_EQ(m.ocean->rho(), 1025.0);
  EXPECT_DOUBLE_EQ(m.ocean->depth(), 100.0);
  EXPECT_NEAR(m.ocean->current().velocity(-50).y(), 1.0, 1e-15);
  bool found = false;
  for (const auto& f : m.system->forces()) found = found || f->name() == "pipe.morison";
  EXPECT_TRUE(found);
  const ChannelList ch = io::model_channels(m);
  ASSERT_GE(ch.size(), 2u);
  EXPECT_EQ(ch[ch.size() - 2].name, "wave.eta");
  EXPECT_EQ(ch.back().name, "wave.eta.bow");
  EXPECT_EQ(ch.back().value(m.system->initial_state()), 0.0);  // still water
}

TEST(OceanLoader, DeepWaterAndIrregularSea) {
  const io::Model m = io::load_model_text(
      replace(replace(kPipe, "depth: 100", "depth: infinite"),
              "  current: {speed: 1.0, direction: 90}",
              "  waves: {type: jonswap, hs: 3, tp: 9, gamma: 2.5, seed: 7, components: 50}"),
      "m.yaml");
  EXPECT_TRUE(std::isinf(m.ocean->depth()));
  EXPECT_EQ(m.ocean->waves().components().size(), 50u);
}

TEST(OceanLoader, RejectsBadSeaStates) {
  EXPECT_EQ(error_of(replace(kPipe, "  water: {density: 1025, depth: 100}\n", "")),
            "m.yaml:3:12: environment.current: needs environment.water (density and depth)\n"
            "m.yaml:15:3: hydrodynamics: needs environment.water (density and depth): there is no "
            "sea to act");
  EXPECT_EQ(error_of(replace(kPipe, "  current: {speed: 1.0, direction: 90}",
                             "  waves: {type: jonswap, hs: -1, tp: 9}")),
            "m.yaml:4:30: environment.waves.hs: must be greater than 0 m, got -1");
  EXPECT_EQ(error_of(replace(kPipe, "  current: {speed: 1.0, direction: 90}",
                             "  waves: {type: jonswap, hs: 2, tp: 9, gamma: 0.5}")),
            "m.yaml:4:47: environment.waves.gamma: must be between 1 and 20, got 0.5");
  EXPECT_EQ(error_of(replace(kPipe, "  current: {speed: 1.0, direction: 90}",
                             "  waves: {type: pierson_moskowitz, hs: 2, tp: 0}")),
            "m.yaml:4:47: environment.waves.tp: must be greater than 0 s, got 0");
  EXPECT_EQ(error_of(replace(kPipe, "  current: {speed: 1.0, direction: 90}",
                             "  waves: {type: stokes5, height: 2, period: 9}")),
            "m.yaml:4:17: environment.waves.type: unknown value 'stokes5'; expected one of: airy, "
            "jonswap, pierson_moskowitz");
  EXPECT_EQ(error_of(replace(kPipe, "{speed: 1.0, direction: 90}",
                             "{profile: [[-50, 1.0, 0], [5, 1.2, 0]]}")),
            "m.yaml:4:22: environment.current.profile: z must be <= 0 (the mean surface is z = 0), "
            "got 5 m");
  EXPECT_EQ(error_of(replace(kPipe, "{speed: 1.0, direction: 90}", "{direction: 90}")),
            "m.yaml:4:12: environment.current.speed: give either speed (m/s) and direction (deg) "
            "for a uniform current, or profile [[z, speed, direction], ...]");
  EXPECT_EQ(error_of(replace(kPipe, "depth: 100", "depth: -3")),
            "m.yaml:3:33: environment.water.depth: must be greater than 0 m, got -3");
}

TEST(OceanLoader, RejectsBadHydrodynamics) {
  EXPECT_EQ(error_of(replace(kPipe, "  pipe: {cd: 0.65, cm: 1.6}", "  pipes: {cd: 0.65}")),
            "m.yaml:16:3: hydrodynamics.pipes: no body named 'pipes'; did you mean 'pipe'?");
  EXPECT_EQ(error_of(replace(kPipe, "cm: 1.6}", "cm: 1.6, cdd: 1}")),
            "m.yaml:16:29: hydrodynamics.pipe.cdd: unknown key; did you mean 'cd'?");
  EXPECT_EQ(error_of(floating("    hull:\n      - box: {center: [0, 0, 0], size: [10, 0, 2]}\n")),
            "m.yaml:13:40: hydrodynamics.buoy.hull[0].box.size: every edge must be > 0 m, got [10, "
            "0, 2]");
  EXPECT_EQ(error_of(floating("    hull:\n      - sphere: {center: [0, 0, 0]}\n")),
            "m.yaml:13:9: hydrodynamics.buoy.hull[0]: a hull piece is box: {...} or cylinder: "
            "{...}, got sphere");
  EXPECT_EQ(error_of(floating("    added_mass: [[1, 2, 3]]\n")),
            "m.yaml:12:17: hydrodynamics.buoy.added_mass: expected a 6x6 matrix (six rows of six "
            "numbers, kg, kg m, kg m^2; modes surge, sway, heave, roll, pitch, yaw)");
  EXPECT_EQ(error_of(floating("    morison:\n      - {end_a: [0, 0, 0], end_b: [0, 0, 0], "
                              "diameter: 1}\n")),
            "m.yaml:13:35: hydrodynamics.buoy.morison[0].end_b: coincides with end_a: a member "
            "needs a length");
  EXPECT_EQ(
      error_of(replace(floating("    hull:\n      - box: {center: [0, 0, 0], size: [10, 10, 2]}\n"),
                       "  water: {density: 1025, depth: 50}\n", "")),
      "m.yaml:10:3: hydrodynamics: needs environment.water (density and depth): there is no sea to "
      "act");
}

TEST(OceanLoader, BemFilesAndTheirErrors) {
  const std::string bem =
      "    bem:\n      wamit: " + kSphere +
      "\n      displaced_volume: 261.8\n      still_water_position: [0, 0, -2]\n";
  const io::Model m = io::load_model_text(floating(bem), "m.yaml");
  int n = 0;
  for (const auto& f : m.system->forces())
    n += f->name() == "buoy.radiation" || f->name() == "buoy.hydro_matrices";
  EXPECT_EQ(n, 2);
  EXPECT_TRUE(m.warnings.empty());
  // no excitation force without waves; with waves outside the tabulated range: a warning
  const io::Model w = io::load_model_text(
      floating(bem, "  waves: {type: airy, height: 1, period: 0.5}\n"), "m.yaml");
  ASSERT_EQ(w.warnings.size(), 1u);
  EXPECT_EQ(w.warnings[0],
            "m.yaml:14:7: hydrodynamics.buoy.bem: a wave frequency 12.57 rad/s lies outside the "
            "BEM range [0.02, 8.4] rad/s of " +
                kSphere + "; the RAO of the nearest tabulated frequency is used");
  // a missing database and a malformed one
  EXPECT_EQ(error_of(floating("    bem:\n      wamit: /nonexistent/hull\n")),
            "m.yaml:13:14: hydrodynamics.buoy.bem.wamit: /nonexistent/hull.1: cannot read the "
            "WAMIT file: no such file");
  const auto dir = std::filesystem::temp_directory_path() / "seaflex_ocean_loader";
  std::filesystem::create_directories(dir);
  {
    std::ifstream in(kSphere + ".1");
    std::ofstream out(dir / "bad.1");
    std::string line;
    for (int i = 0; std::getline(in, line); ++i)
      out << (i == 5 ? " -1.000000E+00     1     x  1.0" : line) << "\n";
  }
  EXPECT_EQ(error_of(floating("    bem:\n      wamit: " + (dir / "bad").string() + "\n")),
            "m.yaml:13:14: hydrodynamics.buoy.bem.wamit: " + (dir / "bad").string() +
                ".1:6: mode j: expected an integer mode (1 to 6), got 'x'");
  EXPECT_EQ(error_of(floating("    bem:\n      wamit: " + kSphere + "\n      radiation: fast\n")),
            "m.yaml:14:18: hydrodynamics.buoy.bem.radiation: unknown value 'fast'; expected one "
            "of: convolution, state_space, none");
}

}  // namespace

namespace {

TEST(OceanLoader, DampingMatricesAtTheReferencePoint) {
  // f = -B1 v - B2 |v| v on the six body-axis velocities of the reference point u; the
  // force acts at u: the moment about the CG adds u x f. Exact arithmetic: 1e-9 relative.
  const std::string hydro =
      "    reference_point: [3, 0, 0]\n"
      "    linear_damping: [[1e4,0,0,0,0,0], [0,2e4,0,0,0,0], [0,0,3e4,0,0,0], "
      "[0,0,0,0,0,0], [0,0,0,0,0,0], [0,0,0,0,0,5e6]]\n"
      "    quadratic_damping: [[0,0,0,0,0,0], [0,0,0,0,0,0], [0,0,7e4,0,0,0], "
      "[0,0,0,0,0,0], [0,0,0,0,0,0], [0,0,0,0,0,0]]\n";
  const io::Model m = io::load_model_text(floating(hydro), "m.yaml");
  const RigidBodyLoad* load = nullptr;
  for (const auto& f : m.system->forces())
    if (f->name() == "buoy.hydro_matrices") load = dynamic_cast<const RigidBodyLoad*>(f.get());
  ASSERT_NE(load, nullptr);
  State s = m.system->initial_state();
  s.v.head<3>() = Vec3(0.5, 0.0, -0.2);  // CG velocity
  // yaw rate 0.1 rad/s: p' = 1/2 G^T w for p = (1, 0, 0, 0)
  s.v.segment<4>(3) = Eigen::Vector4d(0, 0, 0, 0.05);
  const Wrench W = load->wrench_at(s);
  // the point u = (3, 0, 0) moves at v + w x u = (0.5, 0.3, -0.2)
  const Vec3 f(-1e4 * 0.5, -2e4 * 0.3, -3e4 * -0.2 - 7e4 * 0.2 * -0.2);
  EXPECT_NEAR((W.force - f).norm(), 0.0, 1e-9 * f.norm());
  const Vec3 moment = Vec3(0, 0, -5e6 * 0.1) + Vec3(3, 0, 0).cross(f);
  EXPECT_NEAR((W.moment - moment).norm(), 0.0, 1e-9 * moment.norm());
}

}  // namespace

namespace {

TEST(OceanLoader, BemHeadingsMemoryAndDoubleBuoyancy) {
  const std::string bem = "    bem:\n      wamit: " + kSphere + "\n";
  // the sphere's data hold the 0 deg heading only: a 30 deg wave warns once
  const io::Model w = io::load_model_text(
      floating(bem, "  waves: {type: airy, height: 1, period: 5, direction: 30}\n"), "m.yaml");
  ASSERT_EQ(w.warnings.size(), 1u);
  EXPECT_EQ(w.warnings[0],
            "m.yaml:14:7: hydrodynamics.buoy.bem: a wave heading of 30 deg relative "
            "to the body lies outside the headings of " +
                kSphere + "; the RAO of the nearest tabulated heading is used");
  EXPECT_EQ(error_of(floating(bem + "      memory: 0.01\n")),
            "m.yaml:14:15: hydrodynamics.buoy.bem.memory: must be at least kernel_time_step (0.05 "
            "s), got 0.01 s");
  const io::Model d = io::load_model_text(
      floating("    hull:\n      - box: {center: [0, 0, 0], size: [10, 10, 4]}\n" + bem +
               "      displaced_volume: 200\n"),
      "m.yaml");
  ASSERT_EQ(d.warnings.size(), 1u);
  EXPECT_EQ(d.warnings[0],
            "m.yaml:15:7: hydrodynamics.buoy.bem: both a hull and a BEM "
            "displaced_volume give buoyancy: it is counted twice; drop one of them");
  EXPECT_EQ(error_of(floating("    hull:\n      - {box: {center: [0, 0, 0], size: [1, 1, 1]}, "
                              "cylinder: {end_a: [0, 0, 0], end_b: [0, 0, 1], diameter: 1}}\n")),
            "m.yaml:13:9: hydrodynamics.buoy.hull[0]: a hull piece is a box or a cylinder, not "
            "both: give each as its own item");
}

}  // namespace
