// The model loader: a valid model builds the expected system; every malformed input is
// rejected before solving with the exact message (file:line:column: key: what), all
// problems of a file at once.
#include "seaflex/io/model_loader.hpp"

#include <gtest/gtest.h>

#include <regex>

#include "seaflex/core/errors.hpp"
#include "seaflex/elements/ancf_beam.hpp"

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
  EXPECT_DOUBLE_EQ(beam.section().EI(), 210e9 * 8.33e-6);
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
  EXPECT_NEAR(riser.section().area, 3.14159265358979 / 4 * (0.36 - 0.16), 1e-12);
  EXPECT_NEAR(riser.section().second_moment,
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
