#include "seaflex/io/beam_csv_recorder.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace seaflex::io {

namespace {

std::FILE* open_or_throw(const std::filesystem::path& path, const char* mode = "w") {
  std::FILE* f = std::fopen(path.c_str(), mode);
  if (!f)
    throw std::runtime_error(
        fmt::format("cannot write {}: {}", path.string(), std::strerror(errno)));
  return f;
}

void put_or_throw(const std::string& text, std::FILE* f, const std::filesystem::path& path) {
  if (std::fputs(text.c_str(), f) < 0 || std::fflush(f) != 0)
    throw std::runtime_error(
        fmt::format("cannot write {}: {}", path.string(), std::strerror(errno)));
}

}  // namespace

std::vector<std::filesystem::path> BeamCsvRecorder::files(
    const std::filesystem::path& dir, const std::string& prefix,
    const std::vector<const AncfBeam*>& beams) {
  std::vector<std::filesystem::path> out;
  for (const AncfBeam* b : beams) {
    out.push_back(dir / fmt::format("{}{}.along.csv", prefix, b->name()));
    out.push_back(dir / fmt::format("{}{}.envelope.csv", prefix, b->name()));
  }
  return out;
}

BeamCsvRecorder::BeamCsvRecorder(const std::filesystem::path& dir, const std::string& prefix,
                                 std::vector<post::BeamResults> beams, bool per_row, bool envelope,
                                 bool resume)
    : per_row_(per_row), envelope_(envelope), resumed_(resume) {
  for (auto& r : beams) {
    const std::string name = r.beam().name();
    beams_.push_back({std::move(r),
                      {},
                      nullptr,
                      dir / fmt::format("{}{}.along.csv", prefix, name),
                      dir / fmt::format("{}{}.envelope.csv", prefix, name)});
    if (per_row_)
      beams_.back().along = open_or_throw(beams_.back().along_path, resume ? "ab" : "w");
  }
}

BeamCsvRecorder::~BeamCsvRecorder() {
  for (auto& b : beams_)
    if (b.along) std::fclose(b.along);
}

void BeamCsvRecorder::begin(const std::vector<std::string>&) {
  if (!per_row_ || resumed_) return;
  line_ = "time,station,s";
  for (const auto& q : post::beam_quantities())
    fmt::format_to(std::back_inserter(line_), ",{}", q.name);
  line_ += '\n';
  for (auto& b : beams_) put_or_throw(line_, b.along, b.along_path);
}

void BeamCsvRecorder::record(const State& state, std::span<const double>) {
  for (auto& b : beams_) {
    b.results.compute(state, table_);
    if (envelope_) b.envelope.add(table_);
    if (!per_row_) continue;
    line_.clear();
    const auto& stations = b.results.stations();
    for (Index i = 0; i < table_.rows(); ++i) {
      // 17 significant digits: the exact doubles, as in timeseries.csv
      fmt::format_to(std::back_inserter(line_), "{:.17g},{},{:.17g}", state.t, i,
                     stations[static_cast<std::size_t>(i)].s);
      for (Index j = 0; j < table_.cols(); ++j)
        fmt::format_to(std::back_inserter(line_), ",{:.17g}", table_(i, j));
      line_ += '\n';
    }
    put_or_throw(line_, b.along, b.along_path);
  }
}

void BeamCsvRecorder::flush() {
  if (!envelope_) return;
  for (auto& b : beams_) {
    if (b.envelope.count() == 0) continue;
    std::FILE* f = open_or_throw(b.envelope_path);
    line_ = "station,s";
    for (const auto& q : post::beam_quantities())
      fmt::format_to(std::back_inserter(line_), ",{0}.min,{0}.max,{0}.mean", q.name);
    line_ += '\n';
    const MatX mean = b.envelope.mean();
    const auto& stations = b.results.stations();
    for (Index i = 0; i < mean.rows(); ++i) {
      fmt::format_to(std::back_inserter(line_), "{},{:.17g}", i,
                     stations[static_cast<std::size_t>(i)].s);
      for (Index j = 0; j < mean.cols(); ++j)
        fmt::format_to(std::back_inserter(line_), ",{:.17g},{:.17g},{:.17g}",
                       b.envelope.min()(i, j), b.envelope.max()(i, j), mean(i, j));
      line_ += '\n';
    }
    const bool ok = std::fputs(line_.c_str(), f) >= 0;
    if (std::fclose(f) != 0 || !ok)
      throw std::runtime_error(
          fmt::format("cannot write {}: {}", b.envelope_path.string(), std::strerror(errno)));
  }
  for (auto& b : beams_)
    if (b.along) std::fflush(b.along);
}

bool BeamCsvRecorder::save(CheckpointWriter& out, const std::string& prefix) const {
  for (std::size_t k = 0; k < beams_.size(); ++k) {
    const Beam& b = beams_[k];
    const std::string p = fmt::format("{}.beam{}", prefix, k);
    if (b.along) {
      std::fflush(b.along);
      out.put(p + ".bytes", static_cast<long>(std::ftell(b.along)));
    }
    if (envelope_) {
      out.put(p + ".envelope.count", b.envelope.count());
      if (b.envelope.count() > 0) {
        out.put(p + ".envelope.min", b.envelope.min());
        out.put(p + ".envelope.max", b.envelope.max());
        out.put(p + ".envelope.sum", b.envelope.sum());
      }
    }
  }
  return true;
}

void BeamCsvRecorder::restore(const CheckpointReader& in, const std::string& prefix) {
  for (std::size_t k = 0; k < beams_.size(); ++k) {
    Beam& b = beams_[k];
    const std::string p = fmt::format("{}.beam{}", prefix, k);
    if (b.along) {
      std::fclose(b.along);
      b.along = nullptr;
      std::filesystem::resize_file(b.along_path,
                                   static_cast<std::uintmax_t>(in.integer(p + ".bytes")));
      b.along = open_or_throw(b.along_path, "ab");
    }
    if (envelope_) {
      const long count = in.integer(p + ".envelope.count");
      if (count > 0)
        b.envelope.restore(count, in.matrix(p + ".envelope.min"), in.matrix(p + ".envelope.max"),
                           in.matrix(p + ".envelope.sum"));
    }
  }
  resumed_ = true;
}

}  // namespace seaflex::io
