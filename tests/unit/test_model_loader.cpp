// The model loader: a valid model builds the expected system; every malformed input is
// rejected before solving with the exact message (file:line:column: key: what), all
// problems of a file at once.
#include "seaflex/io/model_loader.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <numbers>
#include <regex>
#include <stdexcept>

#include "seaflex/constraints/joint.hpp"
#include "seaflex/core/errors.hpp"
#include "seaflex/elements/ancf_beam.hpp"
#include "seaflex/elements/rigid_body.hpp"
#include "seaflex/forces/rotational_spring.hpp"
#include "seaflex/math/rotation.hpp"

using namespace seaflex;

namespace {

const std::string kBase = R"(bodies:
  beam:
    type: ancf_beam
    start: [0, 0, 0]
    end: [10, 0, 0]
    elements: 10
    area: 0.01
    second_moment: 8.33e-6
    youngs_modulus: 210e9
    density: 7850
supports:
  - {body: beam, node: start, type: clamped}
)";

// a beam clamped at x = 0 carrying a rigid body on a fixed joint at its tip (the body
// marker's z axis along the beam's slope)
const std::string kRigid = R"(bodies:
  beam:
    type: ancf_beam
    start: [0, 0, 0]
    end: [10, 0, 0]
    elements: 10
    area: 0.01
    second_moment: 8.33e-6
    youngs_modulus: 210e9
    density: 7850
  box:
    type: rigid_body
    mass: 1000
    inertia: [100, 200, 250]
    position: [11, 0, 0]
markers:
  tip: {body: beam, node: end}
  face: {body: box, position: [-1, 0, 0], axis: [1, 0, 0]}
supports:
  - {body: beam, node: start, type: clamped}
joints:
  - {name: weld, type: fixed, from: face, to: tip}
)";

// a spring from the body to a point 5 m above the beam's tip
const std::string kSpring =
    "connections:\n  - {name: s, type: spring, from: face, to: {body: ground, position: [11, 0, "
    "5]}, free_length: 4, stiffness: 1e3}\n";

// a rope from the body over a point above the beam's tip to a point further on
const std::string kRope =
    "connections:\n  - {name: w, type: rope, path: [face, {body: ground, position: [11, 0, 5]}, "
    "{body: ground, position: [15, 0, 5]}], axial_stiffness: 1e8, free_length: 9}\n";
// a gas cylinder from the box to a point above it
const std::string kCylinder =
    "connections:\n  - {name: c, type: pneumatic_cylinder, from: face, to: {body: ground, "
    "position: [10, 0, 6]}, piston_area: 0.1, gas_pressure: 1e7, gas_volume: 2, friction: "
    "{coulomb: 1e3, static: 2e3}}\n";
// a tensioner from a point above the box to the box
const std::string kTensioner =
    "connections:\n  - {name: t, type: tensioner, from: {body: ground, position: [10, 0, 6]}, "
    "to: face, tension: 1e4, stroke_limits: [-1, 1], stop_stiffness: 1e6}\n";

// planar four-bar of parallel revolute joints (hinge axes along y): 3 bodies, 6 x 3 = 18
// degrees of freedom, 4 x 5 = 20 rows, one degree of freedom left: 3 rows are redundant
const std::string kFourBar = R"(bodies:
  crank1: {type: rigid_body, mass: 10, inertia: [1, 1, 0.1], position: [0, 0, -0.5]}
  crank2: {type: rigid_body, mass: 10, inertia: [1, 1, 0.1], position: [2, 0, -0.5]}
  bar: {type: rigid_body, mass: 20, inertia: [0.1, 7, 7], position: [1, 0, -1]}
joints:
  - {name: a, type: revolute, from: {body: ground, position: [0, 0, 0], axis: [0, 1, 0]}, to: {body: crank1, position: [0, 0, 0.5], axis: [0, 1, 0]}}
  - {name: b, type: revolute, from: {body: crank1, position: [0, 0, -0.5], axis: [0, 1, 0]}, to: {body: bar, position: [-1, 0, 0], axis: [0, 1, 0]}}
  - {name: c, type: revolute, from: {body: bar, position: [1, 0, 0], axis: [0, 1, 0]}, to: {body: crank2, position: [0, 0, -0.5], axis: [0, 1, 0]}}
  - {name: d, type: revolute, from: {body: crank2, position: [0, 0, 0.5], axis: [0, 1, 0]}, to: {body: ground, position: [2, 0, 0], axis: [0, 1, 0]}}
)";

std::string replace(std::string text, const std::string& from, const std::string& to) {
  const auto pos = text.find(from);
  EXPECT_NE(pos, std::string::npos) << from;
  if (pos != std::string::npos) text.replace(pos, from.size(), to);
  return text;
}

// the message of the InputError thrown for text ("" when it loads)
std::string error_of(const std::string& text) {
  try {
    io::load_model_text(text, "m.yaml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(ModelLoader, BuildsTheCantilever) {
  const io::Model m =
      io::load_model_text(kBase + "dynamics: {time_step: 1e-4, duration: 0.5}\n", "m.yaml");
  EXPECT_EQ(m.system->num_coordinates(), 66);
  EXPECT_EQ(m.system->num_constraints(), 6);
  ASSERT_EQ(m.system->forces().size(), 1u);  // gravity
  EXPECT_EQ(m.gravity, Vec3(0, 0, -kStandardGravity));
  const auto& beam = dynamic_cast<const AncfBeam&>(*m.system->find_body("beam"));
  EXPECT_DOUBLE_EQ(beam.length(), 10.0);
  EXPECT_DOUBLE_EQ(beam.section(0).EI(), 210e9 * 8.33e-6);
  ASSERT_TRUE(m.dynamics);
  EXPECT_EQ(m.dynamics->output_interval, 1e-4);  // defaults to the step
  EXPECT_FALSE(m.dynamics->start_from_statics);
}

TEST(ModelLoader, PipeSectionPolylineAndLoads) {
  const std::string text = R"(environment: {gravity: [0, 0, -9.81]}
bodies:
  riser:
    type: ancf_beam
    polyline: [[0, 0, 0], [0, 0, -100], [50, 0, -150]]
    elements: [4, 2]
    outer_diameter: 0.6
    inner_diameter: 0.4
    youngs_modulus: 2.1e11
    density: 7850
supports:
  - {body: riser, node: 0, type: fixed, fix: [x, y, z]}
  - {body: riser, node: end, type: pinned}
loads:
  - {type: point_force, body: riser, arc_length: 50, force: [1000, 0, 0], ramp: {start: 1, duration: 2}}
  - {type: distributed_load, body: riser, elements: [0, 3], load_table: [[0, 0, 0, 0], [10, 100, 0, 0]]}
statics: {load_steps: 5, tolerance: 1e-9}
)";
  const io::Model m = io::load_model_text(text, "m.yaml");
  const auto& riser = dynamic_cast<const AncfBeam&>(*m.system->find_body("riser"));
  EXPECT_EQ(riser.num_elements(), 6);
  EXPECT_NEAR(riser.length(), 100 + std::sqrt(50.0 * 50 + 50 * 50), 1e-12);
  EXPECT_NEAR(riser.section(0).area, 3.14159265358979 / 4 * (0.36 - 0.16), 1e-12);
  EXPECT_NEAR(riser.section(0).second_moment,
              3.14159265358979 / 64 * (0.6 * 0.6 * 0.6 * 0.6 - 0.4 * 0.4 * 0.4 * 0.4), 1e-12);
  EXPECT_EQ(m.system->num_constraints(), 6);
  EXPECT_EQ(m.system->forces().size(), 3u);
  EXPECT_EQ(m.statics.load_steps, 5);
  EXPECT_EQ(m.statics.tolerance, 1e-9);
}

struct BadCase {
  const char* what;
  std::string text;
  std::string message;
};

class ModelLoaderRejects : public ::testing::TestWithParam<BadCase> {};

TEST_P(ModelLoaderRejects, WithExactMessage) {
  EXPECT_EQ(error_of(GetParam().text), GetParam().message);
}

INSTANTIATE_TEST_SUITE_P(
    BadInput, ModelLoaderRejects,
    ::testing::Values(
        BadCase{"misspelled key", replace(kBase, "elements: 10", "elemnts: 10"),
                "m.yaml:3:5: bodies.beam.elements: required key is missing (a whole number)\n"
                "m.yaml:6:5: bodies.beam.elemnts: unknown key; did you mean 'elements'?"},
        BadCase{"wrong type", replace(kBase, "elements: 10", "elements: ten"),
                "m.yaml:6:15: bodies.beam.elements: expected a whole number, got 'ten'"},
        BadCase{"unit mistake", replace(kBase, "density: 7850", "density: 7.85"),
                "m.yaml:10:14: bodies.beam.density: 7.85 kg/m^3 is implausibly low; seaflex uses "
                "kg/m^3 (steel: 7850), not t/m^3"},
        BadCase{"E in GPa", replace(kBase, "youngs_modulus: 210e9", "youngs_modulus: 210"),
                "m.yaml:9:21: bodies.beam.youngs_modulus: 210 Pa is implausibly low; seaflex uses "
                "Pa (steel: 2.1e11), not GPa or MPa"},
        BadCase{"dangling body", replace(kBase, "body: beam", "body: bem"),
                "m.yaml:12:12: supports[0].body: no body named 'bem'; did you mean 'beam'?"},
        BadCase{"node out of range", replace(kBase, "node: start", "node: 12"),
                "m.yaml:12:24: supports[0].node: must be between 0 and 10, got 12"},
        BadCase{"node not a number", replace(kBase, "node: start", "node: top"),
                "m.yaml:12:24: supports[0].node: expected a node number (0..10), start or end; got "
                "'top'"},
        BadCase{"zero length", replace(kBase, "end: [10, 0, 0]", "end: [0, 0, 0]"),
                "m.yaml:5:10: bodies.beam.end: coincides with start: the beam needs a length "
                "greater than 0 m"},
        BadCase{"three errors at once",
                replace(replace(replace(kBase, "youngs_modulus: 210e9", "youngs_modulus: -1"),
                                "elements: 10", "elements: 0"),
                        "type: clamped", "type: clamp"),
                "m.yaml:6:15: bodies.beam.elements: must be between 1 and 100000, got 0\n"
                "m.yaml:9:21: bodies.beam.youngs_modulus: must be greater than 0 Pa, got -1\n"
                "m.yaml:12:37: supports[0].type: unknown value 'clamp'; did you mean 'clamped'?"},
        BadCase{"short vector", replace(kBase, "start: [0, 0, 0]", "start: [0, 0]"),
                "m.yaml:4:12: bodies.beam.start: expected a list of three numbers [x, y, z] in m, "
                "got 2 entries"},
        BadCase{"syntax error", "bodies:\n  beam: {type: ancf_beam\n",
                "m.yaml:3:1: YAML syntax error: end of map flow not found"},
        BadCase{
            "unknown body type", replace(kBase, "type: ancf_beam", "type: ancf_bem"),
            "m.yaml:3:11: bodies.beam.type: unknown value 'ancf_bem'; did you mean 'ancf_beam'?"},
        BadCase{"fractional steps", kBase + "dynamics: {time_step: 0.001, duration: 0.0015}\n",
                "m.yaml:13:40: dynamics.duration: must be a whole number of time steps (0.001 s), "
                "got 0.0015 s"},
        BadCase{
            "missing force", kBase + "loads:\n  - {type: point_force, body: beam, node: end}\n",
            "m.yaml:14:5: loads[0].force: required key is missing (give force as [x, y, z] in N, "
            "or force_table as [[t, x, y, z], ...])"},
        BadCase{"duplicate key",
                replace(kBase, "    density: 7850\n", "    density: 7850\n    density: 7800\n"),
                "m.yaml:11:5: bodies.beam.density: duplicate key"},
        BadCase{"inner above outer",
                replace(kBase, "    area: 0.01\n    second_moment: 8.33e-6\n",
                        "    outer_diameter: 0.4\n    inner_diameter: 0.5\n"),
                "m.yaml:8:21: bodies.beam.inner_diameter: must be smaller than outer_diameter (0.4 "
                "m), got 0.5 m"},
        BadCase{"L1 with exact bending",
                replace(kBase, "    density: 7850\n", "    density: 7850\n    axial_model: L1\n"),
                "m.yaml:11:18: bodies.beam.axial_model: L1 needs bending_model T1 or T2: with the "
                "exact "
                "curvature nothing restrains the length of the nodal slopes r'"},
        BadCase{
            "L1 with the thesis's exact bending",
            replace(kBase, "    density: 7850\n",
                    "    density: 7850\n    axial_model: L1\n    bending_model: exact_deformed\n"),
            "m.yaml:11:18: bodies.beam.axial_model: L1 needs bending_model T1 or T2: with the "
            "exact curvature nothing restrains the length of the nodal slopes r'"},
        BadCase{
            "unknown bending model",
            replace(kBase, "    density: 7850\n", "    density: 7850\n    bending_model: thesis\n"),
            "m.yaml:11:20: bodies.beam.bending_model: unknown value 'thesis'; expected one of: "
            "exact, exact_deformed, T1, T2"},
        BadCase{
            "twice-held coordinate", kBase + "  - {body: beam, node: 0, type: pinned}\n",
            "m.yaml:13:24: supports[1].node: beam.n0 x, y, z already held by an earlier support: "
            "a coordinate can be held only once"},
        BadCase{"fix on a clamped support",
                replace(kBase, "type: clamped}", "type: clamped, fix: [x]}"),
                "m.yaml:12:51: supports[0].fix: only a support of type 'fixed' takes a component "
                "list; 'clamped' holds position and slope"},
        BadCase{"unknown component",
                replace(kBase, "type: clamped}", "type: fixed, fix: [x, slope_q]}"),
                "m.yaml:12:53: supports[0].fix[1]: unknown component 'slope_q'; did you mean "
                "'slope_x'?"},
        BadCase{
            "arc length beyond the end",
            kBase +
                "loads:\n  - {type: point_force, body: beam, arc_length: 11, force: [0, 0, 1]}\n",
            "m.yaml:14:49: loads[0].arc_length: must be between 0 and 10 m, got 11"},
        BadCase{"huge element count", replace(kBase, "elements: 10", "elements: 100000000"),
                "m.yaml:6:15: bodies.beam.elements: must be between 1 and 100000, got 100000000"},
        BadCase{"infinite number", replace(kBase, "area: 0.01", "area: .inf"),
                "m.yaml:7:11: bodies.beam.area: expected a number in m^2, got '.inf'"},
        BadCase{"both section forms",
                replace(kBase, "    area: 0.01\n", "    area: 0.01\n    outer_diameter: 0.3\n"),
                "m.yaml:7:11: bodies.beam.area: give the section either as "
                "outer_diameter/inner_diameter or as area/second_moment, not both"},
        BadCase{
            "gauss points of a closed form",
            replace(kBase, "    density: 7850\n",
                    "    density: 7850\n    axial_model: L2\n    bending_model: T2\n    "
                    "gauss_points: 7\n"),
            "m.yaml:13:19: bodies.beam.gauss_points: applies only to the exact axial or bending "
            "model; L1, L2, T1 and T2 are closed forms"},
        BadCase{"node as a list", replace(kBase, "node: start", "node: [1]"),
                "m.yaml:12:24: supports[0].node: expected a node number (0..10), start or end; got "
                "a list"},
        BadCase{"no bodies", "bodies: {}\n", "m.yaml:1:9: bodies: the model has no bodies"},
        BadCase{"empty file", "", "m.yaml: the model file is empty"},
        BadCase{"not a mapping", "- 1\n- 2\n",
                "m.yaml:1:1: expected a mapping of keys, got a list"},
        BadCase{
            "body name with a dot", replace(kBase, "  beam:", "  my.beam:"),
            "m.yaml:2:3: bodies.my.beam: body names may use letters, digits, '_' and '-' only "
            "(they become output channel names such as <body>.n0.x)\n"
            "m.yaml:12:12: supports[0].body: no body named 'beam': the model has no valid bodies"}),
    [](const ::testing::TestParamInfo<BadCase>& info) {
      std::string name = info.param.what;
      for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
      return name;
    });

namespace {

const Constraint& constraint_named(const System& sys, const std::string& name) {
  for (const auto& c : sys.constraints())
    if (c->name() == name) return *c;
  throw std::logic_error("no constraint named " + name);
}

}  // namespace

// Every joint type, each on its own rigid body held at its centre of gravity by ground, plus
// beam-to-beam and beam-to-body fixed joints: the rows of constraints/joint.hpp, and the
// flex joint's rotational spring with its stiffness converted from kN m/deg.
TEST(ModelLoader, EveryJointTypeWithItsRows) {
  const std::string text = R"(environment: {gravity: 0}
bodies:
  beam: {type: ancf_beam, start: [0, 0, 0], end: [4, 0, 0], elements: 4, area: 0.01, second_moment: 8.33e-6, youngs_modulus: 210e9, density: 7850}
  beam2: {type: ancf_beam, start: [4, 0, 0], end: [8, 0, 0], elements: 2, area: 0.01, second_moment: 8.33e-6, youngs_modulus: 210e9, density: 7850}
  b_ball: {type: rigid_body, mass: 1, inertia: [1, 1, 1], position: [0, 10, 0]}
  b_universal: {type: rigid_body, mass: 1, inertia: [1, 1, 1], position: [0, 20, 0]}
  b_revolute: {type: rigid_body, mass: 1, inertia: [1, 1, 1], position: [0, 30, 0]}
  b_cylindrical: {type: rigid_body, mass: 1, inertia: [1, 1, 1], position: [0, 40, 0]}
  b_prismatic: {type: rigid_body, mass: 1, inertia: [1, 1, 1], position: [0, 50, 0]}
  b_fixed: {type: rigid_body, mass: 1, inertia: [1, 1, 1], position: [0, 60, 0]}
  b_flex: {type: rigid_body, mass: 1, inertia: [1, 1, 1], position: [0, 70, 0]}
  tipbox: {type: rigid_body, mass: 1, inertia: [1, 1, 1], position: [9, 0, 0]}
supports:
  - {body: beam, node: start, type: clamped}
joints:
  - {name: ball, type: ball, from: {body: ground, position: [0, 10, 0]}, to: {body: b_ball}}
  - {name: universal, type: universal, from: {body: ground, position: [0, 20, 0]}, to: {body: b_universal}}
  - {name: revolute, type: revolute, from: {body: ground, position: [0, 30, 0]}, to: {body: b_revolute}}
  - {name: cylindrical, type: cylindrical, from: {body: ground, position: [0, 40, 0]}, to: {body: b_cylindrical}}
  - {name: prismatic, type: prismatic, from: {body: ground, position: [0, 50, 0]}, to: {body: b_prismatic}}
  - {name: fixed, type: fixed, from: {body: ground, position: [0, 60, 0]}, to: {body: b_fixed}}
  - {name: flex, type: flex, stiffness: 2, damping: 0.5, from: {body: ground, position: [0, 70, 0]}, to: {body: b_flex}}
  - {name: beams, type: fixed, from: {body: beam, node: end}, to: {body: beam2, node: start}}
  - {name: tip, type: fixed, from: {body: beam2, node: end}, to: {body: tipbox, position: [-1, 0, 0], axis: [1, 0, 0]}}
)";
  const io::Model m = io::load_model_text(text, "m.yaml");
  const System& sys = *m.system;
  const std::vector<std::pair<std::string, Index>> rows{
      {"ball", 3},  {"universal", 4}, {"revolute", 5}, {"cylindrical", 4}, {"prismatic", 5},
      {"fixed", 6}, {"flex", 3},      {"beams", 6},    {"tip", 5}};
  Index joint_rows = 0;
  for (const auto& [name, n] : rows) {
    const Constraint& c = constraint_named(sys, name);
    EXPECT_EQ(c.num_rows(), n) << name;
    EXPECT_NE(dynamic_cast<const Joint*>(&c), nullptr) << name;
    joint_rows += n;
  }
  EXPECT_EQ(joint_rows, 41);
  // + 6 of the clamped support + 1 Euler-parameter normalization per rigid body
  EXPECT_EQ(sys.num_constraints(), 41 + 6 + 8);
  EXPECT_EQ(sys.num_coordinates(), 6 * (5 + 3) + 7 * 8);
  // the beam named first is behind the body internally, but from/to stay as named
  const auto& tip = dynamic_cast<const Joint&>(constraint_named(sys, "tip"));
  EXPECT_EQ(tip.from().body(), sys.find_body("beam2"));
  EXPECT_EQ(tip.to().body(), sys.find_body("tipbox"));
  EXPECT_EQ(tip.type(), JointType::kFixed);
  EXPECT_EQ(dynamic_cast<const Joint&>(constraint_named(sys, "flex")).type(), JointType::kBall);

  // flex adds one force, its rotational spring "<joint>.spring", beside the ball joint's
  // rows; no other forces (gravity is off)
  ASSERT_EQ(sys.forces().size(), 1u);
  const auto* spring = dynamic_cast<const RotationalSpring*>(sys.forces()[0].get());
  ASSERT_NE(spring, nullptr);
  EXPECT_EQ(spring->name(), "flex.spring");
  // 2 kN m/deg: tilting the body 10 deg about x stores 1/2 k theta^2 with k in N m/rad
  State s = sys.initial_state();
  const auto& flex_body = *sys.find_body("b_flex");
  const double theta = 10.0 * std::numbers::pi / 180.0;
  s.q.segment<4>(flex_body.offset() + 3) =
      math::euler_parameters_from_rotation(math::rotation_from_roll_pitch_yaw(theta, 0, 0));
  const double k = 2.0 * 1000.0 * 180.0 / std::numbers::pi;
  EXPECT_NEAR(spring->angle(s), theta, 1e-12);
  EXPECT_NEAR(spring->potential_energy(s), 0.5 * k * theta * theta, 1e-9 * k);
  // its channel, in degrees, after the bodies' channels and before the reactions
  const ChannelList channels = sys.channels();
  const auto it = std::find_if(channels.begin(), channels.end(),
                               [](const auto& c) { return c.name == "flex.spring.angle"; });
  ASSERT_NE(it, channels.end());
  EXPECT_NEAR(it->value(s), 10.0, 1e-9);
}

INSTANTIATE_TEST_SUITE_P(
    RigidBodiesAndJoints, ModelLoaderRejects,
    ::testing::Values(
        BadCase{"joint naming a missing body",
                replace(kRigid, "to: tip}", "to: {body: bem, node: end}}"),
                "m.yaml:22:54: joints[0].to.body: no body named 'bem'; did you mean 'beam'?"},
        BadCase{"missing marker", replace(kRigid, "to: tip}", "to: tipp}"),
                "m.yaml:22:47: joints[0].to: no marker named 'tipp'; did you mean 'tip'?"},
        BadCase{
            "marker beyond the beam's end",
            replace(kRigid, "tip: {body: beam, node: end}", "tip: {body: beam, arc_length: 12}"),
            "m.yaml:17:33: markers.tip.arc_length: must be between 0 and 10 m, got 12"},
        BadCase{"marker node out of range",
                replace(kRigid, "tip: {body: beam, node: end}", "tip: {body: beam, node: 11}"),
                "m.yaml:17:27: markers.tip.node: must be between 0 and 10, got 11"},
        BadCase{"inertia not positive definite",
                replace(kRigid, "inertia: [100, 200, 250]", "inertia: [100, -200, 250]"),
                "m.yaml:14:14: bodies.box.inertia: the inertia tensor is not positive definite "
                "(principal moments -200, 100, 250 kg m^2)"},
        BadCase{"inertia violating the triangle inequality",
                replace(kRigid, "inertia: [100, 200, 250]", "inertia: [100, 200, 400]"),
                "m.yaml:14:14: bodies.box.inertia: principal moments 100, 200, 400 kg m^2 violate "
                "the triangle inequality I1 + I2 >= I3 that every real body meets"},
        BadCase{"asymmetric inertia tensor",
                replace(kRigid, "inertia: [100, 200, 250]",
                        "inertia: [[100, 1, 0], [2, 200, 0], [0, 0, 250]]"),
                "m.yaml:14:14: bodies.box.inertia: the inertia tensor must be symmetric: entry "
                "[0][1] = 1 but [1][0] = 2"},
        BadCase{"prismatic joint on a beam marker",
                replace(kRigid, "type: fixed,", "type: prismatic,"),
                "m.yaml:22:24: joints[0].type: joint 'weld': a prismatic joint needs the y axis of "
                "both markers, but beam.n10 is a beam marker, which has only the slope axis (the "
                "cable element carries no torsion)"},
        BadCase{
            "revolute joint between beams",
            replace(replace(replace(kRigid,
                                    "  box:\n    type: rigid_body\n    mass: 1000\n    "
                                    "inertia: [100, 200, 250]\n    position: [11, 0, 0]\n",
                                    "  beam2: {type: ancf_beam, start: [10, 0, 0], end: [20, "
                                    "0, 0], elements: 5, area: 0.01, second_moment: 8.33e-6, "
                                    "youngs_modulus: 210e9, density: 7850}\n"),
                            "face: {body: box, position: [-1, 0, 0], axis: [1, 0, 0]}",
                            "face: {body: beam2, node: start}"),
                    "type: fixed,", "type: revolute,"),
            "m.yaml:18:24: joints[0].type: joint 'weld': a revolute joint needs x and y axes "
            "on one side, but beam2.n0 and beam.n10 are beam markers, which have only the slope "
            "axis (the cable element carries no torsion); beam to beam takes ball or fixed"},
        BadCase{"joint connecting a body to itself",
                replace(kRigid, "to: tip}", "to: {body: box}}"),
                "m.yaml:22:47: joints[0].to: joint 'weld' connects body 'box' to itself"},
        BadCase{"ball joint to ground at a clamped node",
                kRigid +
                    "  - {name: extra, type: ball, from: {body: ground, position: [0, 0, 0]}, to: "
                    "{body: beam, node: start}}\n",
                "m.yaml:23:5: joints[1]: 'extra' over-constrains the assembly: its condition 'x' "
                "repeats what 'support beam.n0' already imposes; remove it or use a joint with "
                "fewer conditions (a closed loop of parallel revolute joints, such as a four-bar, "
                "needs a ball and a universal joint in place of two of its revolutes)"},
        BadCase{"four-bar of parallel revolutes", kFourBar,
                "m.yaml:9:5: joints[3]: 'd' over-constrains the assembly: its condition 'y' "
                "repeats what 'a', 'b', 'c' already impose; remove it or use a joint with fewer "
                "conditions (a closed loop of parallel revolute joints, such as a four-bar, needs "
                "a ball and a universal joint in place of two of its revolutes)"},
        BadCase{"markers that do not meet",
                replace(kRigid, "position: [11, 0, 0]", "position: [11.5, 0, 0]"),
                "m.yaml:22:5: joints[0]: 'weld' is not satisfied by the initial positions: "
                "condition 'x' is off by 0.5 (box@(-1, 0, 0) is at (10.5, 0, 0) m, beam.n10 at "
                "(10, 0, 0) m); place the bodies so that the joint closes"},
        BadCase{"velocities that the joint does not allow",
                replace(kRigid, "position: [11, 0, 0]",
                        "position: [11, 0, 0]\n    velocity: [0, 0.25, 0]"),
                "m.yaml:23:5: joints[0]: 'weld' is not satisfied by the initial velocities: "
                "condition 'y' changes at 0.25 per second; give the bodies velocities that the "
                "joint allows"},
        BadCase{"flex joint bent at the start",
                replace(replace(kRigid, "type: fixed,", "type: flex, stiffness: 2,"),
                        "axis: [1, 0, 0]", "axis: [0, 0, 1]"),
                "m.yaml:22:5: joints[0]: flex joint 'weld' starts bent by 90 deg: it is neutral "
                "when the z axes of its markers are parallel (a beam marker's axis is the beam's "
                "slope, from its start towards its end); give the rigid-body or ground marker an "
                "axis along the beam"},
        BadCase{"flex joint without stiffness", replace(kRigid, "type: fixed,", "type: flex,"),
                "m.yaml:22:5: joints[0].stiffness: required key is missing (a number in kN m/deg)"},
        BadCase{
            "stiffness on a ball joint",
            replace(kRigid, "type: fixed,", "type: ball, stiffness: 10,"),
            "m.yaml:22:41: joints[0].stiffness: only a flex joint takes stiffness; a ball joint "
            "is rigid"},
        BadCase{"spring with stiffness and tension table",
                kRigid + replace(kSpring, "stiffness: 1e3}",
                                 "stiffness: 1e3, tension_table: [[0, 0], [1, 1e3]]}"),
                "m.yaml:24:130: connections[0].tension_table: give either stiffness or "
                "tension_table, not both"},
        BadCase{"duplicate joint names",
                kRigid +
                    "  - {name: weld, type: ball, from: {body: ground, position: [12, 0, 0]}, to: "
                    "{body: box, position: [1, 0, 0]}}\n",
                "m.yaml:23:12: joints[1].name: a joint named 'weld' repeats the name of an earlier "
                "joint or connection: names must be unique (they name output channels)"},
        BadCase{"body named ground",
                replace(replace(kRigid, "  box:\n", "  ground:\n"), "face: {body: box",
                        "face: {body: ground"),
                "m.yaml:11:3: bodies.ground: 'ground' is reserved for the fixed world frame; give "
                "the body another name"},
        // one report per problem: a named marker's problem where it is defined, not again at
        // each reference; a missing marker reference once; a duplicate name does not hide
        // the problems of the entry's markers
        BadCase{"problem of a named marker reported once",
                replace(kRigid, "tip: {body: beam, node: end}",
                        "tip: {body: beam, node: end, axis: [1, 0, 0]}"),
                "m.yaml:17:38: markers.tip.axis: a marker on beam 'beam' is placed by node or "
                "arc_length; its only axis is the beam's slope"},
        BadCase{"missing from reported once", replace(kRigid, "from: face, ", ""),
                "m.yaml:22:5: joints[0].from: required key is missing (a marker name or {body: "
                "..., ...})"},
        BadCase{"duplicate name and a dangling body",
                kRigid +
                    "  - {name: weld, type: ball, from: {body: ground, position: [12, 0, 0]}, to: "
                    "{body: bx}}\n",
                "m.yaml:23:12: joints[1].name: a joint named 'weld' repeats the name of an earlier "
                "joint or connection: names must be unique (they name output channels)\n"
                "m.yaml:23:85: joints[1].to.body: no body named 'bx'; did you mean 'box'?"},
        BadCase{"stiffness of a joint of unknown type",
                replace(kRigid, "type: fixed,", "type: flx, stiffness: 3,"),
                "m.yaml:22:24: joints[0].type: unknown value 'flx'; did you mean 'flex'?"},
        BadCase{"slack given as yes",
                kRigid + replace(kSpring, "stiffness: 1e3}", "stiffness: 1e3, slack: yes}"),
                "m.yaml:24:122: connections[0].slack: expected true or false, got 'yes'"},
        BadCase{"tension table with repeated extension",
                kRigid + replace(kSpring, "stiffness: 1e3}", "tension_table: [[0, 0], [0, 1]]}"),
                "m.yaml:24:123: connections[0].tension_table[1]: extensions must increase "
                "strictly: 0 follows 0"},
        BadCase{"spring from a body to itself",
                kRigid + replace(kSpring, "to: {body: ground, position: [11, 0, 5]}",
                                 "to: {body: box, position: [1, 0, 0]}"),
                "m.yaml:24:45: connections[0].to: connection 's' connects body 'box' to itself"},
        BadCase{"spring with coincident ends",
                kRigid + replace(kSpring, "position: [11, 0, 5]}, free_length: 4",
                                 "position: [10, 0, 0]}, free_length: 0"),
                "m.yaml:24:5: connections[0]: the end points of spring 's' coincide at the start, "
                "so the direction of its force is undefined; place its ends apart"},
        BadCase{"rope parts that do not match its path",
                kRigid + replace(kRope, "free_length: 9}", "free_length: 9, parts: [4]}"),
                "m.yaml:24:162: connections[0].parts: expected a list of 2 whole numbers >= "
                "1, one per segment of the path"},
        BadCase{"rope through one point",
                kRigid + replace(kRope,
                                 "path: [face, {body: ground, position: [11, 0, 5]}, "
                                 "{body: ground, position: [15, 0, 5]}]",
                                 "path: [face]"),
                "m.yaml:24:33: connections[0].path: expected a list of two or more markers "
                "(names or {body: ..., ...})"},
        BadCase{
            "rope on ground only",
            kRigid + replace(kRope, "path: [face,", "path: [{body: ground, position: [1, 2, 3]},"),
            "m.yaml:24:33: connections[0].path: every point of rope 'w' is on ground: "
            "its length cannot change"},
        BadCase{"rope with free length and initial tension",
                kRigid + replace(kRope, "free_length: 9}", "free_length: 9, initial_tension: 1e4}"),
                "m.yaml:24:172: connections[0].initial_tension: give either free_length or "
                "initial_tension, not both"},
        BadCase{"rope with zero parts",
                kRigid + replace(kRope, "free_length: 9}", "free_length: 9, parts: [1, 0]}"),
                "m.yaml:24:166: connections[0].parts[1]: must be between 1 and 1000, got 0"},
        BadCase{"cylinder static friction below Coulomb",
                kRigid + replace(kCylinder, "static: 2e3", "static: 500"),
                "m.yaml:24:180: connections[0].friction.static: static friction 500 N is "
                "below the Coulomb friction 1000 N: Stribeck friction falls from static to "
                "Coulomb"},
        BadCase{"cylinder friction key misspelt",
                kRigid + replace(kCylinder, "static: 2e3", "statik: 2e3"),
                "m.yaml:24:172: connections[0].friction.statik: unknown key; did you mean "
                "'static'?"},
        BadCase{
            "cylinder polytropic exponent out of range",
            kRigid + replace(kCylinder, "gas_volume: 2,", "gas_volume: 2, polytropic_exponent: 2,"),
            "m.yaml:24:168: connections[0].polytropic_exponent: must be between 1 and "
            "1.67, got 2"},
        BadCase{"cylinder without gas volume", kRigid + replace(kCylinder, "gas_volume: 2,", ""),
                "m.yaml:24:5: connections[0].gas_volume: required key is missing (a number "
                "in m^3)"},
        BadCase{"tensioner stop stiffness without stroke limits",
                kRigid + replace(kTensioner, "stroke_limits: [-1, 1], ", ""),
                "m.yaml:24:116: connections[0].stop_stiffness: applies only with stroke_limits: "
                "without them the stroke is unlimited"},
        BadCase{"tensioner stroke limits of three numbers",
                kRigid + replace(kTensioner, "[-1, 1]", "[-1, 0, 1]"),
                "m.yaml:24:115: connections[0].stroke_limits: expected a list of two numbers "
                "[s_min, s_max] in m with s_min < 0 < s_max, got 3 entries"},
        BadCase{"tensioner stroke limit at zero", kRigid + replace(kTensioner, "[-1, 1]", "[0, 1]"),
                "m.yaml:24:115: connections[0].stroke_limits: expected [s_min, s_max] with s_min < "
                "0 < s_max (the stroke counts from the reference length), got [0, 1]"},
        BadCase{"tensioner stroke limit not a number",
                kRigid + replace(kTensioner, "[-1, 1]", "[-1, up]"),
                "m.yaml:24:120: connections[0].stroke_limits[1]: expected a number in m, got 'up'"},
        BadCase{"tensioner negative damping",
                kRigid + replace(kTensioner, "tension: 1e4,", "tension: 1e4, damping: -5,"),
                "m.yaml:24:109: connections[0].damping: must be at least 0 N s/m, got -5"},
        BadCase{"tensioner zero reference length",
                kRigid + replace(kTensioner, "tension: 1e4,", "tension: 1e4, reference_length: 0,"),
                "m.yaml:24:118: connections[0].reference_length: must be greater than 0 m, got 0"},
        BadCase{"load at a ground marker",
                kRigid + "loads:\n  - {type: point_force, at: {body: ground, position: [0, 0, 0]}, "
                         "force: [0, 0, 1]}\n",
                "m.yaml:24:29: loads[0].at: a load at a ground marker would act on nothing; give a "
                "marker on a body"}),
    [](const ::testing::TestParamInfo<BadCase>& info) {
      std::string name = info.param.what;
      for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
      return name;
    });
