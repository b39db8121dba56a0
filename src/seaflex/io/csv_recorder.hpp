// Writes output rows to a CSV file: a header row "time,<channel>,...", then one row per
// output time. Every row is flushed to the operating system as it is written, so a run
// that stops early leaves every computed row on disk.
#pragma once

#include <cstdio>
#include <filesystem>

#include "seaflex/simulation/recorder.hpp"

namespace seaflex::io {

class CsvRecorder : public Recorder {
 public:
  /// Opens (truncates) path, or with resume opens it to append after restore();
  /// throws std::runtime_error when it cannot.
  explicit CsvRecorder(const std::filesystem::path& path, bool resume = false);
  ~CsvRecorder() override;
  CsvRecorder(const CsvRecorder&) = delete;
  CsvRecorder& operator=(const CsvRecorder&) = delete;

  void begin(const std::vector<std::string>& channels) override;
  void record(const State& state, std::span<const double> values) override;
  void flush() override;
  bool save(CheckpointWriter& out, const std::string& prefix) const override;
  void restore(const CheckpointReader& in, const std::string& prefix) override;

 private:
  std::FILE* file_ = nullptr;
  std::string line_;
  std::filesystem::path path_;
  bool resumed_ = false;  // the header is already in the file
};

}  // namespace seaflex::io
