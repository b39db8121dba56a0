#include "seaflex/io/csv_recorder.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace seaflex::io {

CsvRecorder::CsvRecorder(const std::filesystem::path& path) : path_(path) {
  file_ = std::fopen(path.c_str(), "w");
  if (!file_)
    throw std::runtime_error(
        fmt::format("cannot write {}: {}", path.string(), std::strerror(errno)));
}

CsvRecorder::~CsvRecorder() {
  if (file_) std::fclose(file_);
}

void CsvRecorder::begin(const std::vector<std::string>& channels) {
  line_ = "time";
  for (const auto& c : channels) {
    line_ += ',';
    line_ += c;
  }
  line_ += '\n';
  std::fputs(line_.c_str(), file_);
  std::fflush(file_);
}

void CsvRecorder::record(const State& state, std::span<const double> values) {
  line_.clear();
  // 17 significant digits round-trip doubles exactly: results compare bit for bit
  fmt::format_to(std::back_inserter(line_), "{:.17g}", state.t);
  for (double v : values) fmt::format_to(std::back_inserter(line_), ",{:.17g}", v);
  line_ += '\n';
  if (std::fputs(line_.c_str(), file_) < 0 || std::fflush(file_) != 0)
    throw std::runtime_error(
        fmt::format("cannot write {}: {}", path_.string(), std::strerror(errno)));
}

void CsvRecorder::flush() {
  std::fflush(file_);
}

}  // namespace seaflex::io
