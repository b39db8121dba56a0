#include "seaflex/analysis/memory_recorder.hpp"

#include <algorithm>

namespace seaflex::analysis {

MemoryRecorder::MemoryRecorder(std::vector<post::BeamResults> beams, long expected_rows)
    : expected_rows_(std::max(0L, expected_rows)) {
  for (auto& b : beams) beams_.push_back(Beam{b.beam().name(), std::move(b), {}});
}

void MemoryRecorder::begin(const std::vector<std::string>& channels) {
  channels_ = channels;
  const auto rows = static_cast<std::size_t>(expected_rows_);
  time_.clear();
  time_.reserve(rows);
  columns_.assign(channels.size(), {});
  for (auto& c : columns_) c.reserve(rows);
  for (auto& b : beams_) {
    b.values.clear();
    b.values.reserve(rows * post::kBeamQuantityCount * b.results.num_stations());
  }
}

void MemoryRecorder::record(const State& state, std::span<const double> values) {
  time_.push_back(state.t);
  for (std::size_t k = 0; k < values.size() && k < columns_.size(); ++k)
    columns_[k].push_back(values[k]);
  for (auto& b : beams_) {
    b.results.compute(state, scratch_);  // stations x quantities, column-major
    b.values.insert(b.values.end(), scratch_.data(), scratch_.data() + scratch_.size());
  }
}

}  // namespace seaflex::analysis
