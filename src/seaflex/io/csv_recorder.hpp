// Writes output rows to a CSV file: a header row "time,<channel>,...", then one row per
// output time. Every row reaches the operating system in one write as it is computed, so
// a run that stops early leaves every computed row on disk; a write that fails (disk
// full) cuts the file back to its last whole row and throws OutputError naming it
// (core/output_file.hpp).
#pragma once

#include <filesystem>

#include "seaflex/core/output_file.hpp"
#include "seaflex/simulation/recorder.hpp"

namespace seaflex::io {

class CsvRecorder : public Recorder {
 public:
  /// Creates (truncates) path, or with resume leaves it to restore(); throws OutputError
  /// when it cannot.
  explicit CsvRecorder(const std::filesystem::path& path, bool resume = false);

  void begin(const std::vector<std::string>& channels) override;
  void record(const State& state, std::span<const double> values) override;
  void flush() override;
  bool save(CheckpointWriter& out, const std::string& prefix) const override;
  void restore(const CheckpointReader& in, const std::string& prefix) override;

 private:
  RowFile file_;
  std::string line_;
  std::filesystem::path path_;
  bool resumed_ = false;  // the header is already in the file
};

}  // namespace seaflex::io
