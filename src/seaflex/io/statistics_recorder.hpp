// The statistics of a run (the model's `statistics` section): for every output channel and
// every quantity at every beam station, the statistics of post/statistics.hpp over the rows
// from statistics.start on, accumulated row by row, and the extremes of post/extremes.hpp.
// Files, rewritten whenever the recorder is flushed (at the end of a run and on a failure;
// layout in docs/results-format.md):
//   statistics.csv    one line per channel and per beam station quantity
//                     (<beam>.station<i>.<quantity>)
//   extremes.csv      three lines (rayleigh, weibull, gumbel) per line of statistics.csv
//   <beam>.range.csv  per station: min, max, mean, std and mean -+ k std of every quantity
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "seaflex/io/hdf5_recorder.hpp"
#include "seaflex/io/model_loader.hpp"
#include "seaflex/post/beam_results.hpp"
#include "seaflex/post/statistics.hpp"
#include "seaflex/simulation/recorder.hpp"

namespace seaflex::io {

class StatisticsRecorder : public Recorder {
 public:
  /// end_time and output_interval: the run's (s), to place the blocks of the Gumbel fit.
  StatisticsRecorder(const std::filesystem::path& dir, const StatisticsSettings& settings,
                     double end_time, double output_interval, std::vector<post::BeamResults> beams);

  void begin(const std::vector<std::string>& channels) override;
  void record(const State& state, std::span<const double> values) override;
  /// Writes the files; throws std::runtime_error when one cannot be written.
  void flush() override;
  bool save(CheckpointWriter& out, const std::string& prefix) const override;
  void restore(const CheckpointReader& in, const std::string& prefix) override;

  /// The lines of statistics.csv as a table (columns count ... peaks), for the HDF5 file.
  Hdf5Recorder::Table table() const;

  /// The files this recorder writes for these beams (for clearing an output directory).
  static std::vector<std::filesystem::path> files(const std::filesystem::path& dir,
                                                  const std::vector<const AncfBeam*>& beams);

 private:
  struct Beam {
    post::BeamResults results;
    std::vector<post::StatisticsAccumulator> stats;  // station-major: i * quantities + j
  };
  void write_statistics() const;
  void write_extremes() const;
  void write_ranges() const;
  post::StatisticsAccumulator make() const;

  std::filesystem::path dir_;
  StatisticsSettings settings_;
  double first_row_ = 0.0, block_length_ = 0.0, output_interval_ = 0.0;
  std::vector<std::string> names_;
  std::vector<post::StatisticsAccumulator> channels_;
  std::vector<Beam> beams_;
  MatX table_;
  bool restored_ = false;  // from a checkpoint: begin() checks the channel count
};

}  // namespace seaflex::io
