// Beam results along the arc length (post/beam_results.hpp) as CSV files: per beam,
// `<prefix><beam>.along.csv` with one line per station and output row, and
// `<prefix><beam>.envelope.csv` with the minimum, maximum and mean of every quantity at
// every station over the output rows, rewritten whenever the recorder is flushed (at the
// end of a run and on a failure) through a temporary file renamed over it, so it is
// complete or absent. Each along row block is one write; a failed write cuts the file back
// to its last whole row and throws OutputError (core/output_file.hpp). Layout:
// docs/results-format.md.
#pragma once

#include <filesystem>
#include <memory>
#include <vector>

#include "seaflex/core/output_file.hpp"
#include "seaflex/post/beam_results.hpp"
#include "seaflex/post/envelope.hpp"
#include "seaflex/simulation/recorder.hpp"

namespace seaflex::io {

class BeamCsvRecorder : public Recorder {
 public:
  /// Creates (truncates) the along files when per_row (with resume: leaves them to
  /// restore()); throws OutputError when a file cannot be written.
  BeamCsvRecorder(const std::filesystem::path& dir, const std::string& prefix,
                  std::vector<post::BeamResults> beams, bool per_row, bool envelope,
                  bool resume = false, bool envelope_steps = false);

  void begin(const std::vector<std::string>& channels) override;
  void record(const State& state, std::span<const double> values) override;
  /// With envelope_steps: the step's results into the envelopes' minimum and maximum.
  void observe_step(const State& state) override;
  void flush() override;
  bool save(CheckpointWriter& out, const std::string& prefix) const override;
  void restore(const CheckpointReader& in, const std::string& prefix) override;

  /// The files this recorder writes for these beams (for clearing an output directory).
  static std::vector<std::filesystem::path> files(const std::filesystem::path& dir,
                                                  const std::string& prefix,
                                                  const std::vector<const AncfBeam*>& beams);

 private:
  struct Beam {
    post::BeamResults results;
    post::Envelope envelope;
    RowFile along;
    std::filesystem::path along_path, envelope_path;
  };
  std::vector<Beam> beams_;
  bool per_row_, envelope_;
  bool envelope_steps_ = false;  // the envelopes' extremes over every step
  bool resumed_ = false;
  MatX table_;
  std::string line_;
};

}  // namespace seaflex::io
