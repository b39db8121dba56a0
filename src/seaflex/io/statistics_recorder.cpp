#include "seaflex/io/statistics_recorder.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>
#include <stdexcept>

#include "seaflex/core/errors.hpp"
#include "seaflex/core/output_file.hpp"
#include "seaflex/post/extremes.hpp"

namespace seaflex::io {

namespace {

std::string station_name(const std::string& beam, Index station, int quantity) {
  return fmt::format("{}.station{}.{}", beam, station,
                     post::beam_quantities()[static_cast<std::size_t>(quantity)].name);
}

}  // namespace

std::vector<std::filesystem::path> StatisticsRecorder::files(
    const std::filesystem::path& dir, const std::vector<const AncfBeam*>& beams) {
  std::vector<std::filesystem::path> out = {dir / "statistics.csv", dir / "extremes.csv"};
  for (const AncfBeam* b : beams) out.push_back(dir / fmt::format("{}.range.csv", b->name()));
  return out;
}

StatisticsRecorder::StatisticsRecorder(const std::filesystem::path& dir,
                                       const StatisticsSettings& settings, double end_time,
                                       double output_interval, std::vector<post::BeamResults> beams)
    : dir_(dir), settings_(settings), output_interval_(output_interval) {
  // the first output row at or after the start, and the analysed duration n dt
  first_row_ = std::ceil(settings.start / output_interval - 1e-9) * output_interval;
  const double analysed = end_time - first_row_ + output_interval;
  block_length_ = analysed / settings.blocks;
  for (auto& r : beams) {
    const std::size_t n = static_cast<std::size_t>(r.num_stations()) *
                          static_cast<std::size_t>(post::kBeamQuantityCount);
    beams_.push_back({std::move(r), std::vector<post::StatisticsAccumulator>(n, make())});
  }
}

post::StatisticsAccumulator StatisticsRecorder::make() const {
  return post::StatisticsAccumulator(settings_.blocks, block_length_);
}

void StatisticsRecorder::begin(const std::vector<std::string>& channels) {
  names_ = channels;
  if (restored_ && channels_.size() != channels.size())
    throw InputError({Diagnostic{"", 0, 0, "statistics",
                                 fmt::format("the checkpoint holds the statistics of {} channels, "
                                             "the model has {}",
                                             channels_.size(), channels.size())}});
  if (channels_.size() != channels.size()) channels_.assign(channels.size(), make());
}

void StatisticsRecorder::record(const State& state, std::span<const double> values) {
  if (state.t < first_row_ - 1e-6 * output_interval_) return;  // the build-up
  for (std::size_t i = 0; i < values.size() && i < channels_.size(); ++i)
    channels_[i].add(state.t, values[i]);
  for (auto& b : beams_) {
    b.results.compute(state, table_);
    std::size_t k = 0;
    for (Index i = 0; i < table_.rows(); ++i)
      for (Index j = 0; j < table_.cols(); ++j) b.stats[k++].add(state.t, table_(i, j));
  }
}

void StatisticsRecorder::flush() {
  // each file is attempted (complete or absent); the first failure is thrown after
  std::exception_ptr failure;
  for (void (StatisticsRecorder::*write)() const :
       {&StatisticsRecorder::write_statistics, &StatisticsRecorder::write_extremes,
        &StatisticsRecorder::write_ranges}) {
    try {
      (this->*write)();
    } catch (const OutputError&) {
      if (!failure) failure = std::current_exception();
    }
  }
  if (failure) std::rethrow_exception(failure);
}

void StatisticsRecorder::write_statistics() const {
  std::string text =
      "channel,count,duration,min,max,mean,std,skewness,kurtosis,up_crossings,period,peaks\n";
  const auto line = [&](const std::string& name, const post::StatisticsAccumulator& a) {
    const post::RecordStatistics s = a.result();
    // 17 significant digits: the exact doubles
    fmt::format_to(std::back_inserter(text),
                   "{},{},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{},{:.17g},{}\n",
                   name, s.count, s.duration, s.min, s.max, s.mean, s.std, s.skewness, s.kurtosis,
                   s.up_crossings, s.period, s.peaks);
  };
  for (std::size_t i = 0; i < channels_.size(); ++i) line(names_[i], channels_[i]);
  for (const auto& b : beams_)
    for (std::size_t k = 0; k < b.stats.size(); ++k)
      line(station_name(b.results.beam().name(), static_cast<Index>(k) / post::kBeamQuantityCount,
                        static_cast<int>(k % post::kBeamQuantityCount)),
           b.stats[k]);
  write_file_atomically(dir_ / "statistics.csv", text);
}

Hdf5Recorder::Table StatisticsRecorder::table() const {
  Hdf5Recorder::Table t;
  t.columns = {"count",    "duration", "min",          "max",    "mean", "std",
               "skewness", "kurtosis", "up_crossings", "period", "peaks"};
  std::vector<post::RecordStatistics> rows;
  for (std::size_t i = 0; i < channels_.size(); ++i) {
    t.rows.push_back(names_[i]);
    rows.push_back(channels_[i].result());
  }
  for (const auto& b : beams_)
    for (std::size_t k = 0; k < b.stats.size(); ++k) {
      t.rows.push_back(station_name(b.results.beam().name(),
                                    static_cast<Index>(k) / post::kBeamQuantityCount,
                                    static_cast<int>(k % post::kBeamQuantityCount)));
      rows.push_back(b.stats[k].result());
    }
  t.values.resize(static_cast<Index>(rows.size()), static_cast<Index>(t.columns.size()));
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const auto& s = rows[i];
    t.values.row(static_cast<Index>(i)) << static_cast<double>(s.count), s.duration, s.min, s.max,
        s.mean, s.std, s.skewness, s.kurtosis, static_cast<double>(s.up_crossings), s.period,
        static_cast<double>(s.peaks);
  }
  return t;
}

void StatisticsRecorder::write_extremes() const {
  std::string text =
      "channel,method,input,parameters,storm_duration,storm_count,most_probable_maximum,"
      "exceedance_probability,value_at_exceedance\n";
  const double p = settings_.exceedance_probability;
  const auto lines = [&](const std::string& name, const post::StatisticsAccumulator& a) {
    const post::RecordStatistics s = a.result();
    if (s.count < 2 || !(s.std > 0.0)) return;  // a constant: no extremes to estimate
    const double storm = settings_.storm_duration > 0.0 ? settings_.storm_duration : s.duration;
    const auto put = [&](const post::ExtremeEstimate& e) {
      fmt::format_to(std::back_inserter(text),
                     "{},{},\"{}\",{},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g}\n", name, e.method,
                     e.input, e.parameters, e.storm_duration, e.storm_count,
                     e.most_probable_maximum, e.exceedance_probability, e.value_at_exceedance);
    };
    const auto failed = [&](const char* method, const std::exception& ex) {
      fmt::format_to(std::back_inserter(text),
                     "{},{},\"not estimated: {}\",,{:.17g},nan,nan,{:.17g},nan\n", name, method,
                     ex.what(), storm, p);
    };
    put(post::rayleigh_extreme(s.mean, s.std, s.period, storm, p));
    try {
      put(post::weibull_extreme(s.mean, a.peaks(), s.duration, storm, p));
    } catch (const std::invalid_argument& ex) {
      failed("weibull", ex);
    }
    try {
      put(post::gumbel_extreme(a.block_maxima(), a.block_length(), storm, p));
    } catch (const std::invalid_argument& ex) {
      failed("gumbel", ex);
    }
  };
  for (std::size_t i = 0; i < channels_.size(); ++i) lines(names_[i], channels_[i]);
  for (const auto& b : beams_)
    for (std::size_t k = 0; k < b.stats.size(); ++k)
      lines(station_name(b.results.beam().name(), static_cast<Index>(k) / post::kBeamQuantityCount,
                         static_cast<int>(k % post::kBeamQuantityCount)),
            b.stats[k]);
  write_file_atomically(dir_ / "extremes.csv", text);
}

void StatisticsRecorder::write_ranges() const {
  for (const auto& b : beams_) {
    std::string text = "station,s,k";
    for (const auto& q : post::beam_quantities())
      fmt::format_to(std::back_inserter(text),
                     ",{0}.min,{0}.max,{0}.mean,{0}.std,{0}.lower,{0}.upper", q.name);
    text += '\n';
    const auto& stations = b.results.stations();
    std::size_t k = 0;
    for (std::size_t i = 0; i < stations.size(); ++i) {
      fmt::format_to(std::back_inserter(text), "{},{:.17g},{:.17g}", i, stations[i].s, settings_.k);
      for (int j = 0; j < post::kBeamQuantityCount; ++j) {
        const post::RecordStatistics s = b.stats[k++].result();
        fmt::format_to(std::back_inserter(text), ",{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g}",
                       s.min, s.max, s.mean, s.std, s.mean - settings_.k * s.std,
                       s.mean + settings_.k * s.std);
      }
      text += '\n';
    }
    write_file_atomically(dir_ / fmt::format("{}.range.csv", b.results.beam().name()), text);
  }
}

bool StatisticsRecorder::save(CheckpointWriter& out, const std::string& prefix) const {
  const auto put = [&](const std::string& key, const post::StatisticsAccumulator& a) {
    const std::vector<double> v = a.save();
    out.put(key, VecX(Eigen::Map<const VecX>(v.data(), static_cast<Index>(v.size()))));
  };
  out.put(prefix + ".channels", static_cast<long>(channels_.size()));
  for (std::size_t i = 0; i < channels_.size(); ++i)
    put(fmt::format("{}.channel{}", prefix, i), channels_[i]);
  for (std::size_t b = 0; b < beams_.size(); ++b)
    for (std::size_t k = 0; k < beams_[b].stats.size(); ++k)
      put(fmt::format("{}.beam{}.{}", prefix, b, k), beams_[b].stats[k]);
  return true;
}

void StatisticsRecorder::restore(const CheckpointReader& in, const std::string& prefix) {
  const auto get = [&](const std::string& key, post::StatisticsAccumulator& a) {
    const VecX v = in.vector(key);
    try {
      a.restore(std::vector<double>(v.data(), v.data() + v.size()));
    } catch (const std::invalid_argument& e) {
      in.fail(key, e.what());
    }
  };
  // every channel has its line: a damaged count allocates nothing
  const long channels = in.integer(prefix + ".channels", 0);
  for (long i = 0; i < channels; ++i)
    if (!in.has(fmt::format("{}.channel{}", prefix, i)))
      in.fail(prefix + ".channels",
              fmt::format("{} channels, but {}.channel{} is missing", channels, prefix, i));
  channels_.assign(static_cast<std::size_t>(channels), make());
  restored_ = true;
  for (std::size_t i = 0; i < channels_.size(); ++i)
    get(fmt::format("{}.channel{}", prefix, i), channels_[i]);
  for (std::size_t b = 0; b < beams_.size(); ++b)
    for (std::size_t k = 0; k < beams_[b].stats.size(); ++k)
      get(fmt::format("{}.beam{}.{}", prefix, b, k), beams_[b].stats[k]);
}

}  // namespace seaflex::io
