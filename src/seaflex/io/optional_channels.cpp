#include "seaflex/io/optional_channels.hpp"

#include <fmt/format.h>

#include <numbers>
#include <stdexcept>

#include "seaflex/constraints/coordinate_lock.hpp"
#include "seaflex/elements/ancf_beam.hpp"
#include "seaflex/elements/ancf_plate.hpp"
#include "seaflex/elements/rigid_body.hpp"
#include "seaflex/math/rotation.hpp"

namespace seaflex::io {

namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;
const char* const kXyz[] = {"x", "y", "z"};

// the multiplier of a constraint row; a state without multipliers is a programming error
double multiplier(const State& s, Index row) {
  if (row >= s.lambda.size()) throw std::logic_error("support reaction: state without multipliers");
  return s.lambda[row];
}

void add_slopes(const System& system, ChannelList& channels) {
  for (const auto& b : system.bodies()) {
    const auto* beam = dynamic_cast<const AncfBeam*>(b.get());
    if (!beam) continue;
    for (int k = 0; k < beam->num_nodes(); ++k)
      for (int c = 0; c < 3; ++c)
        channels.push_back(
            {fmt::format("{}.n{}.slope_{}", beam->name(), k, kXyz[c]),
             [beam, k, c](const State& s) { return s.q[beam->node_index(k) + 3 + c]; }});
  }
}

// a beam support: per node, the held position components as forces, the slopes as a
// moment (all three held) or as generalized forces
void add_beam_reactions(const AncfBeam& beam, const CoordinateLock& lock, Index row0,
                        ChannelList& channels) {
  const auto& locals = lock.locals();
  std::vector<int> nodes;
  for (Index local : locals)
    if (nodes.empty() || nodes.back() != local / 6) nodes.push_back(static_cast<int>(local / 6));
  for (int k : nodes) {
    std::array<Index, 6> row;  // row of each of the node's six coordinates, -1 when free
    row.fill(-1);
    for (std::size_t r = 0; r < locals.size(); ++r)
      if (locals[r] / 6 == k) row[locals[r] % 6] = row0 + static_cast<Index>(r);
    const std::string prefix = fmt::format("{}.n{}.reaction", beam.name(), k);
    for (int c = 0; c < 3; ++c)
      if (row[c] >= 0)
        channels.push_back({fmt::format("{}.f{}", prefix, kXyz[c]),
                            [r = row[c]](const State& s) { return -multiplier(s, r); }});
    if (row[3] >= 0 && row[4] >= 0 && row[5] >= 0) {
      for (int c = 0; c < 3; ++c)
        channels.push_back(
            {fmt::format("{}.m{}", prefix, kXyz[c]), [&beam, k, c, row](const State& s) {
               const Vec3 Qs(-multiplier(s, row[3]), -multiplier(s, row[4]),
                             -multiplier(s, row[5]));
               const Vec3 slope = s.q.segment<3>(beam.node_index(k) + 3);
               return slope.cross(Qs)[c];
             }});
    } else {
      for (int c = 0; c < 3; ++c)
        if (row[3 + c] >= 0)
          channels.push_back({fmt::format("{}.slope_{}", prefix, kXyz[c]),
                              [r = row[3 + c]](const State& s) { return -multiplier(s, r); }});
    }
  }
}

// a plate support: rows labelled "n<i>_<j>.<kind>.<axis>" (io/load_plate.cpp)
void add_plate_reactions(const AncfPlate& plate, const CoordinateLock& lock, Index row0,
                         ChannelList& channels) {
  const auto& labels = lock.labels();
  for (std::size_t r = 0; r < labels.size(); ++r) {
    const std::string& label = labels[r];
    const auto dot1 = label.find('.');
    const auto dot2 = label.rfind('.');
    if (dot1 == std::string::npos || dot2 == dot1) continue;
    const std::string node = label.substr(0, dot1);
    const std::string kind = label.substr(dot1 + 1, dot2 - dot1 - 1);
    const std::string axis = label.substr(dot2 + 1);
    const std::string name =
        kind == "r" ? fmt::format("{}.{}.reaction.f{}", plate.name(), node, axis)
                    : fmt::format("{}.{}.reaction.{}.{}", plate.name(), node, kind, axis);
    channels.push_back({name, [row = row0 + static_cast<Index>(r)](const State& s) {
                          return -multiplier(s, row);
                        }});
  }
}

void add_reactions(const System& system, ChannelList& channels) {
  Index row0 = 0;
  for (const auto& c : system.constraints()) {
    if (const auto* lock = dynamic_cast<const CoordinateLock*>(c.get())) {
      if (const auto* beam = dynamic_cast<const AncfBeam*>(&lock->body()))
        add_beam_reactions(*beam, *lock, row0, channels);
      else if (const auto* plate = dynamic_cast<const AncfPlate*>(&lock->body()))
        add_plate_reactions(*plate, *lock, row0, channels);
    }
    row0 += c->num_rows();
  }
}

void add_energies(const System& system, const Vec3& g, ChannelList& channels) {
  for (const auto& b : system.bodies()) {
    const Body* body = b.get();
    channels.push_back({fmt::format("{}.energy.kinetic", body->name()),
                        [body](const State& s) { return body->kinetic_energy(s); }});
    channels.push_back({fmt::format("{}.energy.gravity", body->name()),
                        [body, g](const State& s) { return body->gravity_potential(g, s); }});
    channels.push_back({fmt::format("{}.energy.strain", body->name()),
                        [body](const State& s) { return body->strain_energy(s); }});
  }
}

void add_body_rates(const System& system, ChannelList& channels) {
  for (const auto& b : system.bodies()) {
    const auto* body = dynamic_cast<const RigidBody*>(b.get());
    if (!body) continue;
    for (int c = 0; c < 3; ++c)
      channels.push_back(
          {fmt::format("{}.body.w{}", body->name(), kXyz[c]), [body, c](const State& s) {
             // Nikravesh (1988), ch. 6: w' = 2 Gbar(p) p'
             const Vec3 wb = 2.0 * math::euler_gbar(body->euler_parameters(s)) *
                             s.v.segment<4>(body->offset() + 3);
             return kDeg * wb[c];
           }});
  }
}

}  // namespace

void add_optional_channels(const Model& model, ChannelList& channels) {
  const OutputSettings& out = model.output;
  const System& system = *model.system;
  if (out.node_slopes) add_slopes(system, channels);
  if (out.support_reactions) add_reactions(system, channels);
  if (out.energies) add_energies(system, model.gravity, channels);
  if (out.body_angular_velocity) add_body_rates(system, channels);
}

}  // namespace seaflex::io
