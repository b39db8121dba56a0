// A recorder that keeps every output row of a run in memory, for tests.
#pragma once

#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "seaflex/simulation/recorder.hpp"

namespace seaflex::testing {

class MemoryRecorder : public Recorder {
 public:
  void begin(const std::vector<std::string>& names) override { names_ = names; }
  void record(const State& state, std::span<const double> row) override {
    times.push_back(state.t);
    rows.emplace_back(row.begin(), row.end());
  }
  void flush() override {}
  std::size_t column(const std::string& name) const {
    for (std::size_t i = 0; i < names_.size(); ++i)
      if (names_[i] == name) return i;
    throw std::out_of_range(name);
  }
  std::vector<double> times;
  std::vector<std::vector<double>> rows;

 private:
  std::vector<std::string> names_;
};

}  // namespace seaflex::testing
