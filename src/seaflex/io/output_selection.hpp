// What a run writes (the model's `output` section, docs/model-format.md section 14): the
// channels selected by body and by name pattern, the beams whose results along the length
// are written, and the pressures those results need from the model's hydrodynamics.
#pragma once

#include <string_view>
#include <vector>

#include "seaflex/io/model_loader.hpp"
#include "seaflex/io/vtk_recorder.hpp"
#include "seaflex/post/beam_results.hpp"

namespace seaflex::io {

/// Shell-style match of a whole name: `*` matches any characters (also none), `?` one.
bool glob_match(std::string_view pattern, std::string_view name);

/// True when the channel belongs to the body: its name starts with "<body>.".
bool channel_of_body(std::string_view channel, std::string_view body);

/// The model's channels (model_channels) that output.bodies and output.channels select:
/// a channel of a body not listed in output.bodies is left out; when patterns are given,
/// a channel is kept only when one of them matches its name.
ChannelList output_channels(const Model& model);

/// The ANCF beams whose results are written (output.bodies, or every beam), file order.
std::vector<const AncfBeam*> output_beams(const Model& model);

/// The plates and rigid bodies whose shapes are drawn (output.bodies, or all), file order.
std::vector<const AncfPlate*> output_plates(const Model& model);
std::vector<const RigidBody*> output_rigid_bodies(const Model& model);

/// The sea surface of the ParaView animation: a 41 x 41 grid over the horizontal extent
/// of the bodies' initial positions, with a margin of 20 % of that extent (at least
/// 10 m); none when the model has no water.
std::optional<VtkSea> sea_surface(const Model& model);

/// The pressures on each of a beam's sections (one per beam.sections()) from its Morison
/// entry (hydrodynamics.<beam>):
/// water density and buoyancy diameter (when buoyancy is on), contents density and
/// diameter; zero for a beam the water does not act on.
std::vector<post::PipePressure> pipe_pressure(const Model& model, const AncfBeam& beam);

}  // namespace seaflex::io
