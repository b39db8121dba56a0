// The model loader for ANCF plates: a valid plate model builds the expected system
// (coordinates, supports, channels, loads, markers); every malformed plate input is
// rejected with the exact message (file:line:column: key: what).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "seaflex/core/errors.hpp"
#include "seaflex/elements/ancf_plate.hpp"
#include "seaflex/io/model_loader.hpp"
#include "seaflex/solvers/statics.hpp"

using namespace seaflex;

namespace {

const std::string kPlate = R"(bodies:
  plate:
    type: ancf_plate
    corner: [0, 0, 0]
    edge1: [4, 0, 0]
    edge2: [0, 2, 0]
    elements: [4, 2]
    thickness: 0.02
    youngs_modulus: 210e9
    poisson_ratio: 0.3
    density: 7850
supports:
  - {body: plate, type: simply_supported, edges: [i0, i_max]}
loads:
  - {type: plate_pressure, body: plate, pressure: -1000}
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

}  // namespace

TEST(PlateLoader, BuildsPlateSupportsLoadsAndChannels) {
  io::Model m = io::load_model_text(kPlate, "m.yaml");
  const auto* plate = dynamic_cast<const AncfPlate*>(m.system->find_body("plate"));
  ASSERT_NE(plate, nullptr);
  EXPECT_EQ(plate->num_nodes(), 15);
  EXPECT_EQ(plate->num_coordinates(), 180);
  EXPECT_DOUBLE_EQ(plate->a(), 1.0);
  EXPECT_DOUBLE_EQ(plate->b(), 1.0);
  EXPECT_NEAR(plate->mass(), 7850 * 0.02 * 8.0, 1e-9);
  // two simply supported edges of 3 nodes each: r and r_p2 held (6 per node)
  EXPECT_EQ(m.system->num_constraints(), 36);
  // channels n<i>_<j>.x|y|z, i along edge1
  const auto channels = m.system->channels();
  ASSERT_EQ(channels.size(), 45u);
  EXPECT_EQ(channels[0].name, "plate.n0_0.x");
  EXPECT_EQ(channels[5].name, "plate.n0_1.z");
  EXPECT_EQ(channels.back().name, "plate.n4_2.z");
  const State s = m.system->initial_state();
  EXPECT_DOUBLE_EQ(channels.back().value(s), 0.0);
  EXPECT_DOUBLE_EQ(channels[channels.size() - 3].value(s), 4.0);
  EXPECT_DOUBLE_EQ(channels[channels.size() - 2].value(s), 2.0);
  EXPECT_EQ(m.system->coordinate_name(plate->offset() + 12 * 4 + 9 + 2), "plate.n1_1.r_p1p2.z");
}

// a pressure pushes the plate along its normal (+z): a strip on two opposite simply
// supported edges bends up, the follower and the fixed-direction forms alike; a point
// force at a node marker and a spring to ground at another
TEST(PlateLoader, PressurePointForceAndMarkers) {
  const std::string text =
      "environment: {gravity: 0}\n" +
      replace(
          replace(kPlate, "pressure: -1000}",
                  "pressure: 1000}\n  - {type: point_force, at: {body: "
                  "plate, node: n2_1}, force: [0, 0, 10]}"),
          "supports:",
          "connections:\n  - {name: tie, type: spring, from: {body: ground, position: [2, 1, 5]}, "
          "to: {body: plate, node: n2_1}, free_length: 5, stiffness: 1e3}\nsupports:");
  io::Model m = io::load_model_text(text, "m.yaml");
  State s = m.system->initial_state();
  solve_statics(*m.system, s, m.statics);
  const auto* plate = dynamic_cast<const AncfPlate*>(m.system->find_body("plate"));
  const double up = s.q[plate->node_index(2, 1) + 2];
  EXPECT_GT(up, 0.0);
  io::Model f = io::load_model_text(
      replace(text, "pressure: 1000}", "pressure: 1000, direction: [0, 0, 2]}"), "m.yaml");
  State sf = f.system->initial_state();
  solve_statics(*f.system, sf, f.statics);
  // the follower turns with the plate and acts on the stretched area: the two differ at
  // second order in the rotation (~5e-3 rad here) and by the membrane strain (~1e-5), so
  // the deflections agree to 1e-4 relative, but not exactly (measured 7e-6)
  const double ratio = sf.q[plate->node_index(2, 1) + 2] / up;
  EXPECT_NEAR(ratio, 1.0, 1e-4);
  EXPECT_GT(std::abs(ratio - 1.0), 1e-7);
}

// a plate joined to a rigid body: a 100 kg box on a fixed joint at node n4_1 of a plate
// clamped along i0 (the box's marker axes along the plate's r_p1, r_p2 and normal); the
// joint carries the box's weight: reaction on the box (0, 0, m g) to 1e-9 relative
// (equilibrium of the box alone), and the plate's free edge sags
TEST(PlateLoader, PlateJoinedToRigidBody) {
  const std::string text =
      replace(kPlate, "supports:",
              "  box:\n    type: rigid_body\n    mass: 100\n    inertia: [10, 10, 10]\n"
              "    position: [4, 1, 0]\n"
              "joints:\n  - {name: weld, type: fixed, from: {body: plate, node: n4_1}, to: "
              "{body: box}}\nsupports:");
  const std::string clamped = replace(
      replace(text, "type: simply_supported, edges: [i0, i_max]", "type: clamped, edges: [i0]"),
      "  - {type: plate_pressure, body: plate, pressure: -1000}\n", "");
  io::Model m = io::load_model_text(clamped.substr(0, clamped.find("loads:")), "m.yaml");
  State s = m.system->initial_state();
  solve_statics(*m.system, s, m.statics);
  const auto* plate = dynamic_cast<const AncfPlate*>(m.system->find_body("plate"));
  EXPECT_LT(s.q[plate->node_index(4, 1) + 2], -1e-4);
  const auto channels = m.system->channels();
  auto value = [&](const std::string& name) {
    const auto it = std::find_if(channels.begin(), channels.end(),
                                 [&](const Channel& c) { return c.name == name; });
    EXPECT_NE(it, channels.end()) << name;
    return it == channels.end() ? 0.0 : it->value(s);
  };
  const double W = 100 * kStandardGravity;
  EXPECT_NEAR(value("weld.fz"), W, 1e-9 * W);
  EXPECT_NEAR(value("weld.fx"), 0.0, 1e-9 * W);
  // the box hangs at the node: it moves with it
  EXPECT_NEAR(value("box.z"), s.q[plate->node_index(4, 1) + 2], 1e-9);
}

struct PlateBadCase {
  const char* what;
  std::string text;
  std::string message;
};

class PlateLoaderRejects : public ::testing::TestWithParam<PlateBadCase> {};

TEST_P(PlateLoaderRejects, WithExactMessage) {
  EXPECT_EQ(error_of(GetParam().text), GetParam().message);
}

INSTANTIATE_TEST_SUITE_P(
    BadInput, PlateLoaderRejects,
    ::testing::Values(
        PlateBadCase{"negative thickness", replace(kPlate, "thickness: 0.02", "thickness: -0.1"),
                     "m.yaml:8:16: bodies.plate.thickness: must be greater than 0 m, got -0.1"},
        PlateBadCase{"Poisson ratio 0.5",
                     replace(kPlate, "poisson_ratio: 0.3", "poisson_ratio: 0.5"),
                     "m.yaml:10:20: bodies.plate.poisson_ratio: must be greater than -1 and less "
                     "than 0.5 (an isotropic material), got 0.5"},
        PlateBadCase{"Poisson ratio -1", replace(kPlate, "poisson_ratio: 0.3", "poisson_ratio: -1"),
                     "m.yaml:10:20: bodies.plate.poisson_ratio: must be greater than -1 and less "
                     "than 0.5 (an isotropic material), got -1"},
        PlateBadCase{"zero edge", replace(kPlate, "edge1: [4, 0, 0]", "edge1: [0, 0, 0]"),
                     "m.yaml:5:12: bodies.plate.edge1: must not be zero: the plate needs a length "
                     "along its first edge"},
        PlateBadCase{
            "parallel edges", replace(kPlate, "edge2: [0, 2, 0]", "edge2: [2, 0, 0]"),
            "m.yaml:6:12: bodies.plate.edge2: is parallel to edge1: the rectangle is degenerate"},
        PlateBadCase{"skew edges", replace(kPlate, "edge2: [0, 2, 0]", "edge2: [1, 2, 0]"),
                     "m.yaml:6:12: bodies.plate.edge2: must be perpendicular to edge1 (the plate "
                     "is a rectangle); the angle between them is 63.4349 deg"},
        PlateBadCase{"one element count", replace(kPlate, "elements: [4, 2]", "elements: [4]"),
                     "m.yaml:7:15: bodies.plate.elements: expected [n1, n2], the numbers of "
                     "elements along edge1 and edge2, got 1 entry"},
        PlateBadCase{"no such edge", replace(kPlate, "edges: [i0, i_max]", "edges: [i0, k0]"),
                     "m.yaml:13:55: supports[0].edges[1]: plate 'plate' has no edge 'k0'; did you "
                     "mean 'i0'? (i0: the nodes n0_<j> at the corner, along edge2; i_max: n4_<j>; "
                     "j0: the nodes n<i>_0, along edge1; j_max: n<i>_2)"},
        PlateBadCase{"misspelled edge", replace(kPlate, "edges: [i0, i_max]", "edges: [i_mx]"),
                     "m.yaml:13:51: supports[0].edges[0]: plate 'plate' has no edge 'i_mx'; did "
                     "you mean 'i_max'? (i0: the nodes n0_<j> at the corner, along edge2; i_max: "
                     "n4_<j>; j0: the nodes n<i>_0, along edge1; j_max: n<i>_2)"},
        PlateBadCase{"edge twice", replace(kPlate, "edges: [i0, i_max]", "edges: [i0, i0]"),
                     "m.yaml:13:55: supports[0].edges[1]: edge 'i0' is listed twice"},
        PlateBadCase{"node outside",
                     replace(kPlate, "type: simply_supported, edges: [i0, i_max]",
                             "type: pinned, node: n5_1"),
                     "m.yaml:13:39: supports[0].node: node n5_1 does not exist: plate 'plate' has "
                     "nodes n0_0 to n4_2"},
        PlateBadCase{"node malformed",
                     replace(kPlate, "type: simply_supported, edges: [i0, i_max]",
                             "type: clamped, node: centre"),
                     "m.yaml:13:40: supports[0].node: expected a node n<i>_<j> with 0 <= i <= 4 "
                     "and 0 <= j <= 2, got 'centre'"},
        PlateBadCase{"pinned edge", replace(kPlate, "type: simply_supported", "type: pinned"),
                     "m.yaml:13:25: supports[0].type: 'pinned' holds one node; an edge is "
                     "simply_supported or clamped"},
        PlateBadCase{"simply supported node", replace(kPlate, "edges: [i0, i_max]", "node: n1_1"),
                     "m.yaml:13:25: supports[0].type: 'simply_supported' applies to edges; a node "
                     "is pinned or clamped"},
        PlateBadCase{"edges and node",
                     replace(kPlate, "edges: [i0, i_max]", "edges: [i0], node: n1_1"),
                     "m.yaml:13:62: supports[0].node: give either edges or node, not both"},
        PlateBadCase{"in_plane on clamped",
                     replace(kPlate, "type: simply_supported, edges: [i0, i_max]",
                             "type: clamped, edges: [i0], in_plane: free"),
                     "m.yaml:13:57: supports[0].in_plane: applies to simply_supported edges only; "
                     "a clamped edge holds all its position components"},
        PlateBadCase{
            "in_plane free on a skew plate",
            replace(replace(replace(kPlate, "edge1: [4, 0, 0]", "edge1: [4, 4, 0]"),
                            "edge2: [0, 2, 0]", "edge2: [-1, 1, 0]"),
                    "edges: [i0, i_max]", "edges: [i0, i_max], in_plane: free"),
            "m.yaml:13:73: supports[0].in_plane: 'free' needs a plate whose edges are along the x, "
            "y or z axes (the held components are coordinates); plate 'plate' has edge1 along "
            "(0.707107, 0.707107, 0) and edge2 along (-0.707107, 0.707107, 0)"},
        PlateBadCase{"gauss points with closed forms",
                     replace(kPlate, "density: 7850",
                             "density: 7850\n    midplane_model: L3\n    transverse_model: T2\n"
                             "    gauss_points: 4"),
                     "m.yaml:14:19: bodies.plate.gauss_points: applies only to the exact midplane "
                     "or transverse model; L1, L3, T2 and T3 are integrated exactly"},
        PlateBadCase{"zero pressure direction",
                     replace(kPlate, "pressure: -1000}", "pressure: -1000, direction: [0, 0, 0]}"),
                     "m.yaml:15:69: loads[0].direction: the direction must be a non-zero vector"},
        PlateBadCase{
            "marker on a plate by position",
            replace(kPlate, "pressure: -1000}",
                    "pressure: -1000}\n  - {type: point_force, at: {body: plate, "
                    "position: [1, 1, 0]}, force: [0, 0, 1]}"),
            "m.yaml:16:29: loads[1].at.node: required key is missing (a node n<i>_<j>)\n"
            "m.yaml:16:53: loads[1].at.position: a marker on plate 'plate' is placed by node "
            "(n<i>_<j>); its axes are the plate's slopes r_p1, r_p2 and the normal r_p1 x r_p2"}));
