// Output channels: named scalar functions of the state, recorded to CSV.
// Naming scheme (docs/model-format.md, "Output channels"): <item>.<part>.<component>,
// e.g. beam.n3.x for the x position of node 3 of the body "beam".
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "seaflex/model/state.hpp"

namespace seaflex {

struct Channel {
  std::string name;
  std::function<double(const State&)> value;
};

using ChannelList = std::vector<Channel>;

}  // namespace seaflex
