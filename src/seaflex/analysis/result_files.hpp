// The result files of one output stem ("statics", "statics_partial", "timeseries") in an
// output directory, as one Recorder: the channels in CSV and/or HDF5, the beam results
// along the length (CSV: <prefix><beam>.along.csv and .envelope.csv; HDF5: inside
// <stem>.h5), plate section results, statistics of a run, fatigue and code checks, and the
// ParaView series. Which files is chosen by the model's output section
// (docs/results-format.md). Used by the command line and the Python module alike.
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "seaflex/io/model_loader.hpp"
#include "seaflex/simulation/recorder.hpp"

namespace seaflex::io {
class CsvRecorder;
class BeamCsvRecorder;
class Hdf5Recorder;
class VtkRecorder;
class StatisticsRecorder;
class PlateCsvRecorder;
class DesignRecorders;
}  // namespace seaflex::io

namespace seaflex::analysis {

class ResultFiles : public Recorder {
 public:
  /// envelopes: beam envelopes and a run's statistics and design results (timeseries);
  /// resume: continue the files of a checkpointed run (CSV only; see restore_all()).
  ResultFiles(const io::Model& model, const std::filesystem::path& dir, const std::string& stem,
              bool envelopes, bool resume = false);
  ~ResultFiles() override;
  ResultFiles(const ResultFiles&) = delete;
  ResultFiles& operator=(const ResultFiles&) = delete;

  void begin(const std::vector<std::string>& channels) override;
  void record(const State& state, std::span<const double> values) override;
  void observe_step(const State& state) override;
  /// Flushes every recorder, also when one fails (a full disk fails them all): each file
  /// is then complete or reported. The first failure is thrown, the others printed on
  /// stderr; when a failure is already on its way (the simulation flushes before it
  /// rethrows), that one is reported and these are only printed.
  void flush() override;
  /// The HDF5 file takes its rows in blocks of about Hdf5Recorder::kWorkPerBlock of work
  /// (io/hdf5_recorder.hpp); without a counter, row by row.
  void set_work_counter(std::function<double()> work);
  /// One row (statics): begin, record, flush.
  void write_row(const ChannelList& channels, const State& state);

  /// "DIR/<stem>.csv" (and/or .h5): the files of the channels, for messages.
  static std::string describe(const io::Model& model, const std::filesystem::path& dir,
                              const std::string& stem);
  /// Restart files: the position of every recorder; false when one cannot continue a run.
  bool save_all(CheckpointWriter& out);
  void restore_all(const CheckpointReader& in);
  /// Fatigue life and code-check utilisation lines for the end of a run.
  std::string design_summary() const;
  /// The files of the channels, for messages.
  std::string names() const;

 private:
  std::vector<Recorder*> recorders();
  std::unique_ptr<io::CsvRecorder> csv_;
  std::unique_ptr<io::BeamCsvRecorder> beams_csv_;
  std::unique_ptr<io::Hdf5Recorder> h5_;
  std::unique_ptr<io::VtkRecorder> vtk_;
  std::unique_ptr<io::StatisticsRecorder> stats_;
  std::unique_ptr<io::PlateCsvRecorder> plates_csv_;
  std::unique_ptr<io::DesignRecorders> design_;  // fatigue and code checks
  std::vector<std::filesystem::path> files_;
};

/// Creates the output directory (and its parents); InputError when it cannot.
void make_output_dir(const std::filesystem::path& dir);
/// Removes the result files a command may write from the output directory, so that what
/// is there afterwards, failed or not, comes from this command only.
void clear_results(const io::Model& model, const std::filesystem::path& dir);

}  // namespace seaflex::analysis
