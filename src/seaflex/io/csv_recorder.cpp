#include "seaflex/io/csv_recorder.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace seaflex::io {

CsvRecorder::CsvRecorder(const std::filesystem::path& path, bool resume)
    : path_(path), resumed_(resume) {
  file_ = std::fopen(path.c_str(), resume ? "ab" : "w");
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
  if (resumed_) return;
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

bool CsvRecorder::save(CheckpointWriter& out, const std::string& prefix) const {
  std::fflush(file_);
  out.put(prefix + ".bytes", static_cast<long>(std::ftell(file_)));
  return true;
}

void CsvRecorder::restore(const CheckpointReader& in, const std::string& prefix) {
  const long bytes = in.integer(prefix + ".bytes");
  std::fclose(file_);
  file_ = nullptr;
  std::error_code ec;
  if (std::filesystem::file_size(path_, ec) < static_cast<std::uintmax_t>(bytes) || ec)
    throw std::runtime_error(fmt::format("{} is shorter than at the checkpoint", path_.string()));
  std::filesystem::resize_file(path_, static_cast<std::uintmax_t>(bytes));
  file_ = std::fopen(path_.c_str(), "ab");
  if (!file_)
    throw std::runtime_error(
        fmt::format("cannot write {}: {}", path_.string(), std::strerror(errno)));
  resumed_ = true;
}

}  // namespace seaflex::io
