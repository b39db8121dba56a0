// Results kept in memory (the Python module's results): the channels as one contiguous
// array each, the output times, and the beam results along the length of chosen beams at
// every row (post/beam_results.hpp). The values are those the CSV and HDF5 recorders
// write, unrounded, so they equal the files bit for bit.
#pragma once

#include <string>
#include <vector>

#include "seaflex/post/beam_results.hpp"
#include "seaflex/simulation/recorder.hpp"

namespace seaflex::analysis {

class MemoryRecorder : public Recorder {
 public:
  /// One beam's results along the length: values holds rows x kBeamQuantityCount x
  /// stations (row-major), the quantities in post::BeamQuantity order; the stations are
  /// results.stations() (owned by results).
  struct Beam {
    std::string name;
    post::BeamResults results;  ///< refers to the model's beam: use only during the run
    std::vector<double> values;
  };
  /// beams: the beams whose results along the length are kept at every row;
  /// expected_rows: capacity reserved up front (the run's row count), 0: none.
  explicit MemoryRecorder(std::vector<post::BeamResults> beams = {}, long expected_rows = 0);

  void begin(const std::vector<std::string>& channels) override;
  void record(const State& state, std::span<const double> values) override;
  void flush() override {}

  const std::vector<std::string>& channels() const { return channels_; }
  const std::vector<double>& time() const { return time_; }
  /// The values of channel k, one per row.
  const std::vector<double>& column(std::size_t k) const { return columns_.at(k); }
  const std::vector<Beam>& beams() const { return beams_; }
  long rows() const { return static_cast<long>(time_.size()); }

 private:
  std::vector<std::string> channels_;
  std::vector<double> time_;
  std::vector<std::vector<double>> columns_;
  std::vector<Beam> beams_;
  long expected_rows_;
  MatX scratch_;  // one beam's stations x quantities
};

}  // namespace seaflex::analysis
