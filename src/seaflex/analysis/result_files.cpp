#include "seaflex/analysis/result_files.hpp"

#include <fmt/format.h>

#include <cstdio>
#include <exception>

#include "seaflex/core/errors.hpp"
#include "seaflex/io/beam_csv_recorder.hpp"
#include "seaflex/io/csv_recorder.hpp"
#include "seaflex/io/design_recorders.hpp"
#include "seaflex/io/hdf5_recorder.hpp"
#include "seaflex/io/output_selection.hpp"
#include "seaflex/io/plate_csv_recorder.hpp"
#include "seaflex/io/statistics_recorder.hpp"
#include "seaflex/io/vtk_recorder.hpp"

namespace fs = std::filesystem;

namespace seaflex::analysis {

ResultFiles::ResultFiles(const io::Model& model, const fs::path& dir, const std::string& stem,
                         bool envelopes, bool resume) {
  const io::OutputSettings& out = model.output;
  const bool csv = out.format != io::OutputFormat::kHdf5;
  const bool h5 = out.format != io::OutputFormat::kCsv;
  const bool per_row = out.beam_results == io::OutputSettings::BeamResults::kAll;
  const bool envelope = envelopes && out.beam_results != io::OutputSettings::BeamResults::kNone;
  const std::string prefix = stem == "timeseries" ? "" : fmt::format("{}.", stem);
  const auto beam_results = [&] {
    std::vector<post::BeamResults> list;
    for (const AncfBeam* b : io::output_beams(model))
      list.emplace_back(*b, io::pipe_pressure(model, *b), out.beam_gauss_points);
    return list;
  };
  if (csv) {
    csv_ = std::make_unique<io::CsvRecorder>(dir / fmt::format("{}.csv", stem), resume);
    files_.push_back(dir / fmt::format("{}.csv", stem));
    if (per_row || envelope)
      beams_csv_ = std::make_unique<io::BeamCsvRecorder>(dir, prefix, beam_results(), per_row,
                                                         envelope, resume, out.envelope_steps);
    if (per_row && !io::output_plates(model).empty())  // plate section results per node
      plates_csv_ =
          std::make_unique<io::PlateCsvRecorder>(dir, prefix, io::output_plates(model), resume);
  }
  if (h5) {
    h5_ = std::make_unique<io::Hdf5Recorder>(dir / fmt::format("{}.h5", stem), beam_results(),
                                             per_row, envelope, out.envelope_steps);
    files_.push_back(dir / fmt::format("{}.h5", stem));
  }
  if (model.statistics && envelopes && model.dynamics)  // a run's statistics (timeseries)
    stats_ =
        std::make_unique<io::StatisticsRecorder>(dir, *model.statistics, model.dynamics->duration,
                                                 model.dynamics->output_interval, beam_results());
  if (stats_ && h5_) h5_->set_statistics([s = stats_.get()] { return s->table(); });
  design_ = std::make_unique<io::DesignRecorders>(model, dir, prefix, stem == "timeseries");
  if (out.vtk)
    vtk_ =
        std::make_unique<io::VtkRecorder>(dir, stem, beam_results(), io::output_plates(model),
                                          io::output_rigid_bodies(model), io::sea_surface(model));
}

ResultFiles::~ResultFiles() = default;

void ResultFiles::begin(const std::vector<std::string>& channels) {
  for (Recorder* r : recorders()) r->begin(channels);
}

void ResultFiles::record(const State& state, std::span<const double> values) {
  for (Recorder* r : recorders()) r->record(state, values);
}

void ResultFiles::observe_step(const State& state) {
  for (Recorder* r : recorders()) r->observe_step(state);
}

void ResultFiles::flush() {
  const bool failing = std::current_exception() != nullptr;  // inside a handler
  std::exception_ptr first;
  for (Recorder* r : recorders()) {
    try {
      r->flush();
    } catch (const std::exception& e) {
      if (first || failing) std::fprintf(stderr, "seaflex: %s\n", e.what());
      if (!first) first = std::current_exception();
    }
  }
  if (first && !failing) std::rethrow_exception(first);
}

void ResultFiles::set_work_counter(std::function<double()> work) {
  if (h5_) h5_->set_work_counter(std::move(work));
}

void ResultFiles::write_row(const ChannelList& channels, const State& state) {
  std::vector<std::string> names;
  std::vector<double> values;
  for (const auto& c : channels) {
    names.push_back(c.name);
    values.push_back(c.value(state));
  }
  try {
    begin(names);
    record(state, values);
  } catch (...) {
    flush();
    throw;
  }
  flush();
}

std::string ResultFiles::describe(const io::Model& model, const fs::path& dir,
                                  const std::string& stem) {
  const auto f = model.output.format;
  if (f == io::OutputFormat::kBoth)
    return fmt::format("{} and {}", (dir / fmt::format("{}.csv", stem)).string(),
                       (dir / fmt::format("{}.h5", stem)).string());
  return (dir / fmt::format("{}.{}", stem, f == io::OutputFormat::kCsv ? "csv" : "h5")).string();
}

bool ResultFiles::save_all(CheckpointWriter& out) {
  const auto list = recorders();
  for (std::size_t k = 0; k < list.size(); ++k)
    if (!list[k]->save(out, fmt::format("recorder{}", k))) return false;
  return true;
}

void ResultFiles::restore_all(const CheckpointReader& in) {
  const auto list = recorders();
  for (std::size_t k = 0; k < list.size(); ++k) list[k]->restore(in, fmt::format("recorder{}", k));
}

std::string ResultFiles::design_summary() const {
  return design_->summary();
}

std::string ResultFiles::names() const {
  std::string list;
  for (const auto& f : files_) list += fmt::format("{}{}", list.empty() ? "" : " and ", f.string());
  return list;
}

std::vector<Recorder*> ResultFiles::recorders() {
  std::vector<Recorder*> list;
  for (Recorder* r :
       {static_cast<Recorder*>(csv_.get()), static_cast<Recorder*>(beams_csv_.get()),
        static_cast<Recorder*>(h5_.get()), static_cast<Recorder*>(vtk_.get()),
        static_cast<Recorder*>(stats_.get()), static_cast<Recorder*>(plates_csv_.get())})
    if (r) list.push_back(r);
  for (Recorder* r : design_->recorders()) list.push_back(r);
  return list;
}

void make_output_dir(const fs::path& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir))
    throw InputError({Diagnostic{
        dir.string(), 0, 0, "",
        "cannot create the output directory: " + (ec ? ec.message() : "not a directory")}});
}

void clear_results(const io::Model& model, const fs::path& dir) {
  std::vector<fs::path> files;
  for (const char* f :
       {"statics.csv", "statics_partial.csv", "timeseries.csv", "modes.csv", "mode_shapes.csv",
        "statics.h5", "statics_partial.h5", "timeseries.h5", "checkpoint.txt"})
    files.push_back(dir / f);
  std::vector<const AncfBeam*> beams;
  for (const auto& b : model.system->bodies())
    if (const auto* beam = dynamic_cast<const AncfBeam*>(b.get())) beams.push_back(beam);
  for (const char* prefix : {"", "statics.", "statics_partial."})
    for (const auto& f : io::BeamCsvRecorder::files(dir, prefix, beams)) files.push_back(f);
  for (const char* prefix : {"", "statics.", "statics_partial."})
    for (const auto& f : io::PlateCsvRecorder::files(dir, prefix, io::output_plates(model)))
      files.push_back(f);
  for (const auto& f : io::StatisticsRecorder::files(dir, beams)) files.push_back(f);
  std::error_code ec;
  for (const auto& f : io::DesignRecorders::files(model, dir)) files.push_back(f);
  for (const auto& f : files) fs::remove(f, ec);
  for (const char* stem : {"statics", "statics_partial", "timeseries"}) {
    fs::remove(dir / fmt::format("{}.pvd", stem), ec);
    fs::remove_all(dir / "vtk" / stem, ec);
  }
}

}  // namespace seaflex::analysis
