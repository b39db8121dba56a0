#include "seaflex/io/plate_csv_recorder.hpp"

#include <fmt/format.h>

#include "seaflex/post/plate_results.hpp"

namespace seaflex::io {

std::vector<std::filesystem::path> PlateCsvRecorder::files(
    const std::filesystem::path& dir, const std::string& prefix,
    const std::vector<const AncfPlate*>& plates) {
  std::vector<std::filesystem::path> out;
  for (const AncfPlate* p : plates)
    out.push_back(dir / fmt::format("{}{}.nodes.csv", prefix, p->name()));
  return out;
}

PlateCsvRecorder::PlateCsvRecorder(const std::filesystem::path& dir, const std::string& prefix,
                                   std::vector<const AncfPlate*> plates, bool resume)
    : resumed_(resume) {
  for (const AncfPlate* p : plates) {
    const auto path = dir / fmt::format("{}{}.nodes.csv", prefix, p->name());
    plates_.push_back({p, resume ? RowFile() : RowFile(path), path});
  }
}

void PlateCsvRecorder::begin(const std::vector<std::string>&) {
  if (resumed_) return;
  line_ = "time,node,i,j,x,y,z";
  for (const auto& q : post::plate_quantities())
    fmt::format_to(std::back_inserter(line_), ",{}", q.name);
  line_ += '\n';
  for (auto& p : plates_) p.file.append(line_);
}

void PlateCsvRecorder::record(const State& state, std::span<const double>) {
  for (auto& p : plates_) {
    post::compute_plate_results(*p.plate, state, table_);
    line_.clear();
    for (int i = 0; i <= p.plate->nx(); ++i)
      for (int j = 0; j <= p.plate->ny(); ++j) {
        const int node = p.plate->node_number(i, j);
        const Vec3 r = state.q.segment<3>(p.plate->node_index(i, j));
        // 17 significant digits: the exact doubles, as in timeseries.csv
        fmt::format_to(std::back_inserter(line_), "{:.17g},{},{},{},{:.17g},{:.17g},{:.17g}",
                       state.t, node, i, j, r.x(), r.y(), r.z());
        for (Index q = 0; q < table_.cols(); ++q)
          fmt::format_to(std::back_inserter(line_), ",{:.17g}", table_(node, q));
        line_ += '\n';
      }
    p.file.append(line_);  // one write: the file never ends in a partial row
  }
}

void PlateCsvRecorder::flush() {}  // every row is written as it comes

bool PlateCsvRecorder::save(CheckpointWriter& out, const std::string& prefix) const {
  for (std::size_t k = 0; k < plates_.size(); ++k)
    out.put(fmt::format("{}.plate{}.bytes", prefix, k), static_cast<long>(plates_[k].file.size()));
  return true;
}

void PlateCsvRecorder::restore(const CheckpointReader& in, const std::string& prefix) {
  for (std::size_t k = 0; k < plates_.size(); ++k) {
    Plate& p = plates_[k];
    const std::string key = fmt::format("{}.plate{}.bytes", prefix, k);
    const long bytes = in.integer(key, 0);
    in.require_file(key, p.path, static_cast<std::uintmax_t>(bytes));
    try {
      p.file = RowFile(p.path, static_cast<std::uintmax_t>(bytes));
    } catch (const OutputError& e) {
      in.fail(key, e.what());
    }
  }
  resumed_ = true;
}

}  // namespace seaflex::io
