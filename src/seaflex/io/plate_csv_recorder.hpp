// Plate section results (post/plate_results.hpp) as CSV files: per plate,
// `<prefix><plate>.nodes.csv` with one line per node and output row: time, node, i, j, the
// position and every quantity (moments, membrane forces, surface stresses). Layout:
// docs/results-format.md.
#pragma once

#include <filesystem>
#include <vector>

#include "seaflex/core/output_file.hpp"
#include "seaflex/elements/ancf_plate.hpp"
#include "seaflex/simulation/recorder.hpp"

namespace seaflex::io {

class PlateCsvRecorder : public Recorder {
 public:
  /// Opens (truncates, or with resume appends to) the files; throws std::runtime_error.
  PlateCsvRecorder(const std::filesystem::path& dir, const std::string& prefix,
                   std::vector<const AncfPlate*> plates, bool resume = false);

  void begin(const std::vector<std::string>& channels) override;
  void record(const State& state, std::span<const double> values) override;
  void flush() override;
  bool save(CheckpointWriter& out, const std::string& prefix) const override;
  void restore(const CheckpointReader& in, const std::string& prefix) override;

  /// The files this recorder writes for these plates (for clearing an output directory).
  static std::vector<std::filesystem::path> files(const std::filesystem::path& dir,
                                                  const std::string& prefix,
                                                  const std::vector<const AncfPlate*>& plates);

 private:
  struct Plate {
    const AncfPlate* plate;
    RowFile file;
    std::filesystem::path path;
  };
  std::vector<Plate> plates_;
  bool resumed_ = false;
  MatX table_;
  std::string line_;
};

}  // namespace seaflex::io
