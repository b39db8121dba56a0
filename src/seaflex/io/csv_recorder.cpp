#include "seaflex/io/csv_recorder.hpp"

#include <fmt/format.h>

namespace seaflex::io {

CsvRecorder::CsvRecorder(const std::filesystem::path& path, bool resume)
    : path_(path), resumed_(resume) {
  if (!resume) file_ = RowFile(path);
}

void CsvRecorder::begin(const std::vector<std::string>& channels) {
  line_ = "time";
  for (const auto& c : channels) {
    line_ += ',';
    line_ += c;
  }
  line_ += '\n';
  if (resumed_) return;
  file_.append(line_);
}

void CsvRecorder::record(const State& state, std::span<const double> values) {
  line_.clear();
  // 17 significant digits round-trip doubles exactly: results compare bit for bit
  fmt::format_to(std::back_inserter(line_), "{:.17g}", state.t);
  for (double v : values) fmt::format_to(std::back_inserter(line_), ",{:.17g}", v);
  line_ += '\n';
  file_.append(line_);  // one write: the file never ends in a partial row
}

void CsvRecorder::flush() {}  // every row is written as it comes

bool CsvRecorder::save(CheckpointWriter& out, const std::string& prefix) const {
  out.put(prefix + ".bytes", static_cast<long>(file_.size()));
  return true;
}

void CsvRecorder::restore(const CheckpointReader& in, const std::string& prefix) {
  const std::string key = prefix + ".bytes";
  const long bytes = in.integer(key, 0);
  in.require_file(key, path_, static_cast<std::uintmax_t>(bytes));
  try {
    file_ = RowFile(path_, static_cast<std::uintmax_t>(bytes));
  } catch (const OutputError& e) {
    in.fail(key, e.what());
  }
  resumed_ = true;
}

}  // namespace seaflex::io
