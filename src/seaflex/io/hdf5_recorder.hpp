// Results in one HDF5 file (HDF5 C API): the channels of the CSV time series, the node
// positions of every output beam (time x node x 3), its results along the length (time x
// station per quantity, post/beam_results.hpp) and their envelopes. Every dataset that
// grows in time is chunked (rows of 16 KiB or more deflate-compressed, one per chunk);
// rows are kept in memory and written in blocks (set_work_counter(); and at every flush()),
// each block ending with H5Fflush, and file space is never reused, so a run that is killed
// leaves a readable file holding every block written before.
// Layout: docs/results-format.md.
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "seaflex/post/beam_results.hpp"
#include "seaflex/simulation/recorder.hpp"

namespace seaflex::io {

class Hdf5Recorder : public Recorder {
 public:
  /// Creates (truncates) the file; throws std::runtime_error when it cannot.
  /// beams: the beams whose positions are written; their results along the length per
  /// output row when per_row, their envelopes (written at every flush) when envelope, with
  /// their extremes also over the steps between the rows when envelope_steps.
  Hdf5Recorder(const std::filesystem::path& path, std::vector<post::BeamResults> beams,
               bool per_row, bool envelope, bool envelope_steps = false);
  ~Hdf5Recorder() override;
  Hdf5Recorder(const Hdf5Recorder&) = delete;
  Hdf5Recorder& operator=(const Hdf5Recorder&) = delete;

  void begin(const std::vector<std::string>& channels) override;
  void record(const State& state, std::span<const double> values) override;
  void observe_step(const State& state) override;
  void flush() override;
  /// Rows in blocks: a block is written (and the file flushed) once work() has grown by
  /// kWorkPerBlock since the last write (work: the coordinate-steps computed so far, a count
  /// that is the same in every run of the model, so the file's bytes are too), or once it
  /// holds 1024 rows. Without a counter (statics) every row is written at once.
  void set_work_counter(std::function<double()> work);
  /// About 0.2 s of the storm benchmark's run (docs/performance.md, "HDF5 rows in blocks"):
  /// the most a run killed by SIGKILL loses; a failure or SIGINT/SIGTERM writes every row.
  static constexpr double kWorkPerBlock = 524288.0;

  /// A table of named rows and columns (statistics of a run).
  struct Table {
    std::vector<std::string> rows, columns;
    MatX values;  ///< rows x columns
  };
  /// At every flush, writes source() into the group /statistics: the string dataset
  /// `channel` (the rows) and one dataset per column.
  void set_statistics(std::function<Table()> source);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace seaflex::io
