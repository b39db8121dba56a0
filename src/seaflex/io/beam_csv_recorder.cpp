#include "seaflex/io/beam_csv_recorder.hpp"

#include <fmt/format.h>

#include <exception>

namespace seaflex::io {

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
                                 bool resume, bool envelope_steps)
    : per_row_(per_row),
      envelope_(envelope),
      envelope_steps_(envelope && envelope_steps),
      resumed_(resume) {
  for (auto& r : beams) {
    const std::string name = r.beam().name();
    beams_.push_back({std::move(r),
                      {},
                      {},
                      dir / fmt::format("{}{}.along.csv", prefix, name),
                      dir / fmt::format("{}{}.envelope.csv", prefix, name)});
    if (per_row_ && !resume) beams_.back().along = RowFile(beams_.back().along_path);
  }
}

void BeamCsvRecorder::begin(const std::vector<std::string>&) {
  if (!per_row_ || resumed_) return;
  line_ = "time,station,s";
  for (const auto& q : post::beam_quantities())
    fmt::format_to(std::back_inserter(line_), ",{}", q.name);
  line_ += '\n';
  for (auto& b : beams_) b.along.append(line_);
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
    b.along.append(line_);  // one write: the file never ends in a partial row
  }
}

void BeamCsvRecorder::observe_step(const State& state) {
  if (!envelope_steps_) return;
  for (auto& b : beams_) {
    b.results.compute(state, table_);
    b.envelope.extend(table_);
  }
}

void BeamCsvRecorder::flush() {
  if (!envelope_) return;
  // every envelope is attempted; the first failure is thrown after the others
  std::exception_ptr failure;
  for (auto& b : beams_) {
    if (b.envelope.count() == 0) continue;
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
    try {
      write_file_atomically(b.envelope_path, line_);
    } catch (const OutputError&) {
      if (!failure) failure = std::current_exception();
    }
  }
  if (failure) std::rethrow_exception(failure);
}

bool BeamCsvRecorder::save(CheckpointWriter& out, const std::string& prefix) const {
  for (std::size_t k = 0; k < beams_.size(); ++k) {
    const Beam& b = beams_[k];
    const std::string p = fmt::format("{}.beam{}", prefix, k);
    if (per_row_) out.put(p + ".bytes", static_cast<long>(b.along.size()));
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
    if (per_row_) {
      const std::string key = p + ".bytes";
      const long bytes = in.integer(key, 0);
      in.require_file(key, b.along_path, static_cast<std::uintmax_t>(bytes));
      try {
        b.along = RowFile(b.along_path, static_cast<std::uintmax_t>(bytes));
      } catch (const OutputError& e) {
        in.fail(key, e.what());
      }
    }
    if (envelope_) {
      const long count = in.integer(p + ".envelope.count", 0);
      if (count > 0) {
        // the sizes of this model's table: stations x quantities
        const Index rows = static_cast<Index>(b.results.stations().size());
        const Index cols = post::kBeamQuantityCount;
        b.envelope.restore(count, in.matrix(p + ".envelope.min", rows, cols),
                           in.matrix(p + ".envelope.max", rows, cols),
                           in.matrix(p + ".envelope.sum", rows, cols));
      }
    }
  }
  resumed_ = true;
}

}  // namespace seaflex::io
