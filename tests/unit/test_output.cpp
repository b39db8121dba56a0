// Output control: the model's `output` section (format, channel patterns, bodies, beam
// results), its error messages, the channel selection, name patterns and envelopes.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "seaflex/core/errors.hpp"
#include "seaflex/io/output_selection.hpp"
#include "seaflex/post/envelope.hpp"

using namespace seaflex;

namespace {

// two beams and a rigid body on a ball joint; channels: a.n0.x ... a.n2.z, b.n0.x ...,
// box.x ... box.wz, hook.fx ... hook.mz
const std::string kBase = R"(environment: {gravity: 9.81}
bodies:
  a: {type: ancf_beam, start: [0, 0, 0], end: [2, 0, 0], elements: 2, area: 0.01,
      second_moment: 1e-6, youngs_modulus: 2e11, density: 7850}
  b: {type: ancf_beam, start: [0, 1, 0], end: [2, 1, 0], elements: 2, area: 0.01,
      second_moment: 1e-6, youngs_modulus: 2e11, density: 7850}
  box: {type: rigid_body, mass: 10, inertia: [1, 1, 1], position: [0, 0, -1]}
joints:
  - {name: hook, type: ball, from: {body: ground, position: [0, 0, 0]},
     to: {body: box, position: [0, 0, 1]}}
)";

std::string error_of(const std::string& text) {
  try {
    io::load_model_text(text, "m.yaml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::vector<std::string> names(const ChannelList& list) {
  std::vector<std::string> out;
  for (const auto& c : list) out.push_back(c.name);
  return out;
}

}  // namespace

TEST(Output, GlobPatterns) {
  EXPECT_TRUE(io::glob_match("riser.n*.x", "riser.n12.x"));
  EXPECT_FALSE(io::glob_match("riser.n*.x", "riser.n12.y"));
  EXPECT_TRUE(io::glob_match("*", ""));
  EXPECT_TRUE(io::glob_match("a?c", "abc"));
  EXPECT_FALSE(io::glob_match("a?c", "ac"));
  EXPECT_TRUE(io::glob_match("*.f*", "hook.fx"));
  EXPECT_TRUE(io::glob_match("a*b*c", "axxbyybzzc"));
  EXPECT_FALSE(io::glob_match("a*b*c", "axxbyybzz"));
  EXPECT_TRUE(io::glob_match("hook.fx", "hook.fx"));
  EXPECT_FALSE(io::glob_match("hook.f", "hook.fx"));  // whole names only
  EXPECT_TRUE(io::channel_of_body("box.x", "box"));
  EXPECT_FALSE(io::channel_of_body("boxer.x", "box"));
}

TEST(Output, DefaultsWriteEverything) {
  const io::Model m = io::load_model_text(kBase, "m.yaml");
  EXPECT_EQ(m.output.format, io::OutputFormat::kCsv);
  EXPECT_EQ(m.output.beam_results, io::OutputSettings::BeamResults::kAll);
  EXPECT_EQ(m.output.beam_gauss_points, 2);
  EXPECT_FALSE(m.output.vtk);
  EXPECT_EQ(names(io::output_channels(m)), names(io::model_channels(m)));
  EXPECT_EQ(io::output_beams(m).size(), 2u);
}

TEST(Output, SelectsChannelsByBodyAndPattern) {
  const io::Model m = io::load_model_text(kBase + R"(output:
  format: both
  bodies: [b, box]
  channels: ["*.x", "hook.f?"]
  beam_results: envelope
  beam_gauss_points: 3
)",
                                          "m.yaml");
  EXPECT_EQ(m.output.format, io::OutputFormat::kBoth);
  EXPECT_EQ(m.output.beam_results, io::OutputSettings::BeamResults::kEnvelope);
  EXPECT_EQ(m.output.beam_gauss_points, 3);
  // beam a is not listed: none of its channels; the joint is no body: kept by pattern
  const std::vector<std::string> expected = {"b.n0.x",  "b.n1.x",  "b.n2.x", "box.x",
                                             "hook.fx", "hook.fy", "hook.fz"};
  EXPECT_EQ(names(io::output_channels(m)), expected);
  ASSERT_EQ(io::output_beams(m).size(), 1u);
  EXPECT_EQ(io::output_beams(m)[0]->name(), "b");
}

TEST(Output, ErrorsAreLocatedWithSuggestions) {
  const std::string text = kBase + R"(output:
  format: hdf
  bodies: [bb, box, box]
  channels: ["box.*"]
  beam_results: some
  vtk: yes
  interval: 1
)";
  const std::string e = error_of(text);
  EXPECT_NE(e.find("m.yaml:12:11: output.format: unknown value 'hdf'; did you mean 'hdf5'?"),
            std::string::npos)
      << e;
  EXPECT_NE(e.find("m.yaml:13:12: output.bodies[0]: no body named 'bb'; did you mean 'b'?"),
            std::string::npos)
      << e;
  EXPECT_NE(e.find("m.yaml:13:21: output.bodies[2]: body 'box' is listed twice"), std::string::npos)
      << e;
  EXPECT_NE(e.find("m.yaml:15:17: output.beam_results: unknown value 'some'; expected one of: "
                   "all, envelope, none"),
            std::string::npos)
      << e;
  EXPECT_NE(e.find("m.yaml:16:8: output.vtk: unknown value 'yes'; expected one of: true, false"),
            std::string::npos)
      << e;
  EXPECT_NE(e.find("m.yaml:17:3: output.interval: unknown key; expected one of: "
                   "beam_gauss_points, beam_results, bodies, body_angular_velocity, "
                   "channels, energies, envelope_sampling, format, node_slopes, support_reactions, "
                   "vtk"),
            std::string::npos)
      << e;
}

// patterns are checked against the channels once the rest of the file is free of errors
// (like the model check): the channels exist only then
TEST(Output, PatternsThatMatchNoChannel) {
  const std::string e = error_of(kBase + R"(output:
  channels: ["box.xx", "nothing*", "hook.*"]
)");
  EXPECT_NE(e.find("m.yaml:12:14: output.channels[0]: 'box.xx' matches no channel of the "
                   "model; did you mean 'box.x'?"),
            std::string::npos)
      << e;
  EXPECT_NE(e.find("m.yaml:12:24: output.channels[1]: 'nothing*' matches no channel of the "
                   "model; channels are named like a.n0.x (see 'seaflex check' and "
                   "docs/model-format.md)"),
            std::string::npos)
      << e;
  EXPECT_EQ(e.find("channels[2]"), std::string::npos) << e;
}

TEST(Output, EnvelopeMinMaxMean) {
  post::Envelope env;
  MatX a(2, 2), b(2, 2), c(2, 2);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  a << 1, -2, 5, nan;
  b << 3, -6, 5, nan;
  c << 2, 2, 5, nan;
  env.add(a);
  env.add(b);
  env.add(c);
  EXPECT_EQ(env.count(), 3);
  // exact: small integers and their sums
  EXPECT_EQ(env.min()(0, 0), 1.0);
  EXPECT_EQ(env.max()(0, 0), 3.0);
  EXPECT_EQ(env.mean()(0, 0), 2.0);
  EXPECT_EQ(env.min()(0, 1), -6.0);
  EXPECT_EQ(env.max()(0, 1), 2.0);
  EXPECT_EQ(env.mean()(0, 1), -2.0);
  EXPECT_EQ(env.mean()(1, 0), 5.0);
  EXPECT_TRUE(std::isnan(env.min()(1, 1)) && std::isnan(env.max()(1, 1)) &&
              std::isnan(env.mean()(1, 1)));
  EXPECT_THROW(env.add(MatX::Zero(3, 2)), std::invalid_argument);
}

// extend: a step between two rows moves the minimum and maximum, not the mean or the count;
// before the first row it is ignored (the envelope starts with a row)
TEST(Output, EnvelopeExtendedBetweenRows) {
  post::Envelope env;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  MatX a(1, 3), step(1, 3), b(1, 3);
  a << 1, 4, nan;
  step << 9, -3, 7;
  b << 3, 2, nan;
  env.extend(step);  // no row yet: nothing
  EXPECT_EQ(env.count(), 0);
  env.add(a);
  env.extend(step);
  env.add(b);
  EXPECT_EQ(env.count(), 2);
  EXPECT_EQ(env.max()(0, 0), 9.0);
  EXPECT_EQ(env.min()(0, 0), 1.0);
  EXPECT_EQ(env.min()(0, 1), -3.0);
  EXPECT_EQ(env.max()(0, 1), 4.0);
  EXPECT_EQ(env.mean()(0, 0), 2.0);  // the rows' (1 + 3) / 2
  EXPECT_EQ(env.mean()(0, 1), 3.0);
  // a quantity that does not apply (NaN in the rows) stays NaN
  EXPECT_TRUE(std::isnan(env.min()(0, 2)) && std::isnan(env.max()(0, 2)));
  EXPECT_THROW(env.extend(MatX::Zero(2, 3)), std::invalid_argument);
}

// a NaN that comes after numbers (a value that could not be computed at one row or step)
// makes the extremes NaN, as it does the mean: the envelope does not report the extremes of
// the other rows as if they were all (std::min/max and a plain comparison would keep them)
TEST(Output, EnvelopeKeepsALaterNaN) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  MatX a(1, 3), bad(1, 3), b(1, 3);
  a << 1, 4, -2;
  bad << nan, 5, nan;
  b << 3, 2, 0;
  post::Envelope rows, steps;
  rows.add(a);
  rows.add(bad);  // a NaN in a row
  rows.add(b);
  steps.add(a);
  steps.extend(bad);  // a NaN in a step between the rows
  steps.add(b);
  for (const post::Envelope* env : {&rows, &steps}) {
    EXPECT_TRUE(std::isnan(env->min()(0, 0)) && std::isnan(env->max()(0, 0)));
    EXPECT_TRUE(std::isnan(env->min()(0, 2)) && std::isnan(env->max()(0, 2)));
    EXPECT_EQ(env->min()(0, 1), 2.0);  // the finite column as before
    EXPECT_EQ(env->max()(0, 1), 5.0);
  }
  EXPECT_TRUE(std::isnan(rows.mean()(0, 0)));
  EXPECT_EQ(steps.mean()(0, 0), 2.0);  // the mean is over the rows only
}
