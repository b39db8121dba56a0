#include "seaflex/io/output_selection.hpp"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>

#include "seaflex/forces/morison_beam.hpp"

namespace seaflex::io {

bool glob_match(std::string_view pattern, std::string_view name) {
  // iterative wildcard match with one backtrack point: linear in practice
  std::size_t p = 0, n = 0, star = std::string_view::npos, mark = 0;
  while (n < name.size()) {
    if (p < pattern.size() && (pattern[p] == '?' || pattern[p] == name[n])) {
      ++p;
      ++n;
    } else if (p < pattern.size() && pattern[p] == '*') {
      star = p++;
      mark = n;
    } else if (star != std::string_view::npos) {
      p = star + 1;
      n = ++mark;
    } else {
      return false;
    }
  }
  while (p < pattern.size() && pattern[p] == '*') ++p;
  return p == pattern.size();
}

bool channel_of_body(std::string_view channel, std::string_view body) {
  return channel.size() > body.size() && channel.starts_with(body) && channel[body.size()] == '.';
}

ChannelList output_channels(const Model& model) {
  const OutputSettings& out = model.output;
  ChannelList all = model_channels(model);
  if (out.bodies.empty() && out.channels.empty()) return all;
  std::vector<std::string> left_out;  // bodies not listed
  for (const auto& b : model.system->bodies())
    if (!out.bodies.empty() &&
        std::find(out.bodies.begin(), out.bodies.end(), b->name()) == out.bodies.end())
      left_out.push_back(b->name());
  ChannelList kept;
  for (auto& c : all) {
    const bool dropped = std::any_of(left_out.begin(), left_out.end(), [&](const std::string& b) {
      return channel_of_body(c.name, b);
    });
    const bool matched = out.channels.empty() ||
                         std::any_of(out.channels.begin(), out.channels.end(),
                                     [&](const std::string& p) { return glob_match(p, c.name); });
    if (!dropped && matched) kept.push_back(std::move(c));
  }
  return kept;
}

std::vector<const AncfBeam*> output_beams(const Model& model) {
  std::vector<const AncfBeam*> beams;
  for (const auto& b : model.system->bodies()) {
    const auto* beam = dynamic_cast<const AncfBeam*>(b.get());
    if (!beam) continue;
    const auto& listed = model.output.bodies;
    if (listed.empty() || std::find(listed.begin(), listed.end(), beam->name()) != listed.end())
      beams.push_back(beam);
  }
  return beams;
}

namespace {
template <class T>
std::vector<const T*> output_bodies_of(const Model& model) {
  std::vector<const T*> list;
  const auto& listed = model.output.bodies;
  for (const auto& b : model.system->bodies())
    if (const auto* body = dynamic_cast<const T*>(b.get()))
      if (listed.empty() || std::find(listed.begin(), listed.end(), body->name()) != listed.end())
        list.push_back(body);
  return list;
}
}  // namespace

std::vector<const AncfPlate*> output_plates(const Model& model) {
  return output_bodies_of<AncfPlate>(model);
}

std::vector<const RigidBody*> output_rigid_bodies(const Model& model) {
  return output_bodies_of<RigidBody>(model);
}

std::optional<VtkSea> sea_surface(const Model& model) {
  if (!model.ocean) return std::nullopt;
  // horizontal extent of the initial positions (all coordinates that are positions)
  Eigen::AlignedBox<double, 2> box;
  const State s0 = model.system->initial_state();
  for (const auto& b : model.system->bodies()) {
    if (const auto* beam = dynamic_cast<const AncfBeam*>(b.get())) {
      for (int k = 0; k < beam->num_nodes(); ++k) box.extend(s0.q.segment<2>(beam->node_index(k)));
    } else if (const auto* plate = dynamic_cast<const AncfPlate*>(b.get())) {
      for (int i = 0; i <= plate->nx(); ++i)
        for (int j = 0; j <= plate->ny(); ++j) box.extend(s0.q.segment<2>(plate->node_index(i, j)));
    } else if (const auto* body = dynamic_cast<const RigidBody*>(b.get())) {
      box.extend(body->position(s0).head<2>());
    }
  }
  if (box.isEmpty()) box.extend(Eigen::Vector2d::Zero());
  const double margin = std::max(10.0, 0.2 * box.sizes().maxCoeff());
  VtkSea sea;
  sea.ocean = model.ocean;
  sea.x0 = box.min().x() - margin;
  sea.x1 = box.max().x() + margin;
  sea.y0 = box.min().y() - margin;
  sea.y1 = box.max().y() + margin;
  return sea;
}

std::vector<post::PipePressure> pipe_pressure(const Model& model, const AncfBeam& beam) {
  post::PipePressure none;
  none.gravity = model.gravity.norm();
  std::vector<post::PipePressure> out(beam.sections().size(), none);
  // the loader names a beam's Morison loads "<beam>.morison" (load_ocean.cpp)
  const std::string name = fmt::format("{}.morison", beam.name());
  for (const auto& f : model.system->forces()) {
    const auto* morison = dynamic_cast<const MorisonBeam*>(f.get());
    if (!morison || morison->name() != name) continue;
    for (std::size_t i = 0; i < out.size(); ++i) {
      const MorisonBeamCoefficients& c = morison->coefficients(static_cast<int>(i));
      post::PipePressure& p = out[i];
      if (model.ocean) p.gravity = model.ocean->g();  // as the contents' weight
      if (c.buoyancy && model.ocean) {
        p.water_density = model.ocean->rho();
        p.external_diameter = c.diameter;
      }
      p.contents_density = c.internal_density;
      p.contents_diameter = c.internal_diameter;
    }
  }
  return out;
}

}  // namespace seaflex::io
