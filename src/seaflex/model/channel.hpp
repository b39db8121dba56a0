// Output channels: named scalar functions of the state, recorded to CSV.
// Naming scheme (docs/model-format.md, "Output channels"): <item>.<part>.<component>,
// e.g. beam.n3.x for the x position of node 3 of the body "beam".
#pragma once

#include <atomic>
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

/// A row of channels evaluated together for one unchanged state (Simulation::record).
/// Channels that share a costly evaluation (a joint's six reaction components) may keep it
/// for the rest of the row: ChannelRow::current() is nonzero inside a row and different for
/// every row of every thread; outside a row (0) a channel computes its value afresh.
class ChannelRow {
 public:
  ChannelRow() : previous_(current_) { current_ = ++count_; }
  ~ChannelRow() { current_ = previous_; }
  ChannelRow(const ChannelRow&) = delete;
  ChannelRow& operator=(const ChannelRow&) = delete;
  static long current() { return current_; }

 private:
  long previous_;
  static inline thread_local long current_ = 0;
  static inline std::atomic<long> count_ = 0;
};

}  // namespace seaflex
