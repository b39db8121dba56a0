// seaflex command line: check, statics, run, modes, bench, plot. Exit codes: 0 success, 2
// input or usage error, 3 solver failure or a result file that cannot be written (results up
// to the failure stay on disk, whole rows only), 130/143
// a run stopped by SIGINT/SIGTERM after its current step (results up to it stay on disk).
#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>

#include "batch_command.hpp"
#include "fatigue_command.hpp"
#include "mode_output.hpp"
#include "option_checks.hpp"
#include "plot_command.hpp"
#include "progress_line.hpp"
#include "seaflex/core/checkpoint.hpp"
#include "seaflex/core/errors.hpp"
#include "seaflex/core/interrupt.hpp"
#include "seaflex/core/output_file.hpp"
#include "seaflex/core/parallel.hpp"
#include "seaflex/io/beam_csv_recorder.hpp"
#include "seaflex/io/csv_recorder.hpp"
#include "seaflex/io/design_recorders.hpp"
#include "seaflex/io/hdf5_recorder.hpp"
#include "seaflex/io/model_inputs.hpp"
#include "seaflex/io/model_loader.hpp"
#include "seaflex/io/output_selection.hpp"
#include "seaflex/io/plate_csv_recorder.hpp"
#include "seaflex/io/statistics_recorder.hpp"
#include "seaflex/io/vtk_recorder.hpp"
#include "seaflex/post/mode_shapes.hpp"
#include "seaflex/simulation/simulation.hpp"
#include "seaflex/solvers/modal.hpp"
#include "seaflex/solvers/statics.hpp"
#include "stats_command.hpp"

namespace fs = std::filesystem;
using namespace seaflex;

namespace {

constexpr int kExitInput = 2;
constexpr int kExitSolver = 3;

void make_output_dir(const fs::path& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir))
    throw InputError({Diagnostic{
        dir.string(), 0, 0, "",
        "cannot create the output directory: " + (ec ? ec.message() : "not a directory")}});
}

// The recorders of one output stem ("statics", "timeseries"): CSV and/or HDF5 files of
// the channels, and the beam results along the length (CSV: <prefix><beam>.along.csv and
// .envelope.csv; HDF5: inside <stem>.h5).
class Outputs : public Recorder {
 public:
  /// resume: continue the files of a checkpointed run (CSV only; see restore()).
  Outputs(const io::Model& model, const fs::path& dir, const std::string& stem, bool envelopes,
          bool resume = false) {
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
                                                           envelope, resume);
      if (per_row && !io::output_plates(model).empty())  // plate section results per node
        plates_csv_ =
            std::make_unique<io::PlateCsvRecorder>(dir, prefix, io::output_plates(model), resume);
    }
    if (h5) {
      h5_ = std::make_unique<io::Hdf5Recorder>(dir / fmt::format("{}.h5", stem), beam_results(),
                                               per_row, envelope);
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
  /// The simulation feeds every recorder through this one (flush() below).
  void attach(Simulation& sim) { sim.add_recorder(*this); }
  void begin(const std::vector<std::string>& channels) override {
    for (Recorder* r : recorders()) r->begin(channels);
  }
  void record(const State& state, std::span<const double> values) override {
    for (Recorder* r : recorders()) r->record(state, values);
  }
  /// Flushes every recorder, also when one fails (a full disk fails them all): each file
  /// is then complete or reported. The first failure is thrown, the others printed; when a
  /// failure is already on its way (the simulation flushes before it rethrows), that one is
  /// reported and these are only printed.
  void flush() override {
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
  /// One row (statics): begin, record, flush.
  void write_row(const ChannelList& channels, const State& state) {
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
  /// "DIR/<stem>.csv" (and/or .h5): the files of the channels, for messages.
  static std::string describe(const io::Model& model, const fs::path& dir,
                              const std::string& stem) {
    const auto f = model.output.format;
    if (f == io::OutputFormat::kBoth)
      return fmt::format("{} and {}", (dir / fmt::format("{}.csv", stem)).string(),
                         (dir / fmt::format("{}.h5", stem)).string());
    return (dir / fmt::format("{}.{}", stem, f == io::OutputFormat::kCsv ? "csv" : "h5")).string();
  }
  /// Restart files: the position of every recorder; false when one cannot continue a run.
  bool save_all(CheckpointWriter& out) {
    const auto list = recorders();
    for (std::size_t k = 0; k < list.size(); ++k)
      if (!list[k]->save(out, fmt::format("recorder{}", k))) return false;
    return true;
  }
  void restore_all(const CheckpointReader& in) {
    const auto list = recorders();
    for (std::size_t k = 0; k < list.size(); ++k)
      list[k]->restore(in, fmt::format("recorder{}", k));
  }
  /// Fatigue life and code-check utilisation lines for the end of a run.
  std::string design_summary() const { return design_->summary(); }
  /// The files of the channels, for messages.
  std::string names() const {
    std::string list;
    for (const auto& f : files_)
      list += fmt::format("{}{}", list.empty() ? "" : " and ", f.string());
    return list;
  }

 private:
  std::vector<Recorder*> recorders() {
    std::vector<Recorder*> list;
    for (Recorder* r :
         {static_cast<Recorder*>(csv_.get()), static_cast<Recorder*>(beams_csv_.get()),
          static_cast<Recorder*>(h5_.get()), static_cast<Recorder*>(vtk_.get()),
          static_cast<Recorder*>(stats_.get()), static_cast<Recorder*>(plates_csv_.get())})
      if (r) list.push_back(r);
    for (Recorder* r : design_->recorders()) list.push_back(r);
    return list;
  }
  std::unique_ptr<io::CsvRecorder> csv_;
  std::unique_ptr<io::BeamCsvRecorder> beams_csv_;
  std::unique_ptr<io::Hdf5Recorder> h5_;
  std::unique_ptr<io::VtkRecorder> vtk_;
  std::unique_ptr<io::StatisticsRecorder> stats_;
  std::unique_ptr<io::PlateCsvRecorder> plates_csv_;
  std::unique_ptr<io::DesignRecorders> design_;  // fatigue and code checks
  std::vector<fs::path> files_;
};

// Removes the result files a command may write from the output directory, so that what
// is there afterwards, failed or not, comes from this command only.
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

// command-line options that override the model's output section
struct OutputOptions {
  std::string format;  // csv, hdf5, both; empty: the model's output.format
  bool vtk = false;    // ParaView time series, also without output.vtk
};

// loads the model and prints its warnings (they do not stop the run)
io::Model load_model(const std::string& file, const OutputOptions& options = {}) {
  io::Model model = io::load_model_file(file);
  for (const auto& w : model.warnings) fmt::print(stderr, "warning: {}\n", w);
  if (options.format == "csv") model.output.format = io::OutputFormat::kCsv;
  if (options.format == "hdf5") model.output.format = io::OutputFormat::kHdf5;
  if (options.format == "both") model.output.format = io::OutputFormat::kBoth;
  if (options.vtk) model.output.vtk = true;
  return model;
}

void print_summary(const io::Model& model) {
  const System& sys = *model.system;
  fmt::print("model: {}{}\n", model.file, model.title.empty() ? "" : " (" + model.title + ")");
  fmt::print("bodies: {}\n", sys.bodies().size());
  for (const auto& b : sys.bodies())
    fmt::print("  {} [{}]: {}\n", b->name(), b->kind(), b->summary());
  fmt::print("constraints: {} ({} rows)\n", sys.constraints().size(), sys.num_constraints());
  for (const auto& c : sys.constraints()) {
    std::string rows;
    for (Index r = 0; r < c->num_rows(); ++r) {
      // row names read "<constraint>: <label>"; show the label when they do
      const std::string row = c->row_name(r), prefix = c->name() + ": ";
      rows += (r ? ", " : "") + (row.starts_with(prefix) ? row.substr(prefix.size()) : row);
    }
    fmt::print("  {}: {}\n", c->name(), rows);
  }
  fmt::print("forces: {}\n", sys.forces().size());
  for (const auto& f : sys.forces()) fmt::print("  {}\n", f->name());
  fmt::print("gravity: ({:g}, {:g}, {:g}) m/s^2\n", model.gravity.x(), model.gravity.y(),
             model.gravity.z());
  // the channels written: those the output section selects
  const std::size_t written = io::output_channels(model).size(),
                    all = io::model_channels(model).size();
  fmt::print("coordinates: {}, constraint rows: {}, output channels: {}{}\n", sys.num_coordinates(),
             sys.num_constraints(), written,
             written < all ? fmt::format(" (of {}, as the output section selects)", all) : "");
  fmt::print(
      "statics: {} load step(s), tolerance {:g}, max {} iterations per step, loads at t = {:g} s\n",
      model.statics.load_steps, model.statics.tolerance, model.statics.max_iterations,
      model.statics.time);
  if (model.dynamics) {
    const auto& d = *model.dynamics;
    fmt::print(
        "dynamics: {}, time step {:g} s{}, duration {:g} s ({} steps), output every {:g} s, "
        "start from {}\n",
        d.integrator, d.time_step,
        d.adaptive ? fmt::format(" (adaptive, down to {:g} s)",
                                 d.min_time_step > 0 ? d.min_time_step : d.time_step / 1024)
                   : "",
        d.duration, std::lround(d.duration / d.time_step), d.output_interval,
        d.start_from_statics ? "static equilibrium" : "the model's initial state");
  } else {
    fmt::print("dynamics: none (add a dynamics section to use 'seaflex run')\n");
  }
}

// statics with a report on stdout; on failure the last converged state goes to
// statics_partial.csv (.h5) before the error propagates
State run_statics(const io::Model& model, const fs::path& dir, bool quiet) {
  State state = model.system->initial_state();
  const ScopedInterruptPolling polling;  // a signal stops statics after its increment
  try {
    const StaticsReport rep = solve_statics(
        *model.system, state, model.statics,
        [&](double factor, int iterations, const StaticsReport& so_far) {
          if (!quiet && model.statics.load_steps > 1)
            fmt::print(stderr,
                       "[seaflex] statics: load factor {:.4g} converged in {} iterations: {}\n",
                       factor, iterations, describe_convergence(so_far));
        });
    if (!quiet)
      fmt::print("statics converged: {} load increment(s), {} Newton iterations; {}\n",
                 rep.increments, rep.iterations, describe_convergence(rep));
  } catch (const SolverError&) {
    Outputs partial(model, dir, "statics_partial", false);
    partial.write_row(io::output_channels(model), state);
    std::fprintf(stderr, "seaflex: the last converged statics increment is in %s\n",
                 partial.names().c_str());
    throw;
  } catch (const Interrupted&) {  // SIGINT/SIGTERM: keep the last converged increment
    Outputs partial(model, dir, "statics_partial", false);
    partial.write_row(io::output_channels(model), state);
    std::fprintf(stderr, "seaflex: the last converged statics increment is in %s\n",
                 partial.names().c_str());
    throw;
  }
  Outputs outputs(model, dir, "statics", false);
  outputs.write_row(io::output_channels(model), state);
  if (!quiet) fmt::print("{}", outputs.design_summary());
  // a signal during the last increment: statics are complete and written; stop here
  if (const int sig = interrupt_signal(); sig != 0)
    throw Interrupted(sig, fmt::format("after statics (written to {})", outputs.names()));
  return state;
}

int cmd_check(const std::string& file) {
  const io::Model model = load_model(file);
  print_summary(model);
  fmt::print("model OK\n");
  return 0;
}

int cmd_statics(const std::string& file, const fs::path& dir, bool quiet,
                const OutputOptions& options) {
  const io::Model model = load_model(file, options);
  make_output_dir(dir);
  clear_results(model, dir);
  run_statics(model, dir, quiet);
  if (!quiet) fmt::print("wrote {}\n", Outputs::describe(model, dir, "statics"));
  return 0;
}

// Restart files: paths as hex (a path with blanks stays one word).
std::string to_hex(const std::string& text) {
  std::string out;
  for (unsigned char c : text) out += fmt::format("{:02x}", c);
  return out;
}
// the text of `key`, written by to_hex; a located error for anything else
std::string from_hex(const CheckpointReader& in, const std::string& key) {
  const std::string hex = in.text(key);
  const auto digit = [](char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    return -1;
  };
  std::string out;
  for (std::size_t i = 0; i + 1 < hex.size(); i += 2) {
    const int hi = digit(hex[i]), lo = digit(hex[i + 1]);
    if (hi < 0 || lo < 0 || (hi == 0 && lo == 0)) break;
    out += static_cast<char>(hi * 16 + lo);
  }
  if (out.size() * 2 != hex.size() || out.empty())
    in.fail(key, "not a file name written by seaflex (pairs of lowercase hex digits)");
  return out;
}

// The files a checkpoint holds the hash of: the model, then every file it reads.
std::vector<std::pair<std::string, std::string>> input_hashes(const std::string& model) {
  std::vector<std::pair<std::string, std::string>> list;
  for (const auto& f : io::model_input_files(model))
    list.emplace_back(f, io::input_file_hash(f, "input file"));
  return list;
}

// A model or output that a restart file cannot hold yet is refused before anything runs.
void check_checkpointable(const io::Model& model, const std::string& file) {
  for (const auto& f : model.system->forces())
    if (f->has_memory())
      throw InputError({Diagnostic{file, 0, 0, "--checkpoint-every",
                                   fmt::format("restart files do not hold the memory of '{}' "
                                               "(radiation) yet; run without checkpoints",
                                               f->name())}});
  if (model.fatigue)
    throw InputError({Diagnostic{file, 0, 0, "--checkpoint-every",
                                 "restart files do not hold the rainflow counters of the fatigue "
                                 "section yet; run without checkpoints"}});
  if (model.output.format != io::OutputFormat::kCsv || model.output.vtk)
    throw InputError({Diagnostic{file, 0, 0, "--checkpoint-every",
                                 "restart files continue CSV results only; use --format csv "
                                 "and no VTK output with checkpoints"}});
}

// Checkpoints every `rows` output rows into DIR/checkpoint.txt.
void enable_checkpoints(Simulation& sim, const std::string& file, const fs::path& dir, long rows,
                        Integrator& integrator, Outputs& outputs,
                        const cli::ProgressLine& progress) {
  const std::string model_path = fs::absolute(file).string();
  const std::string hash = io::input_file_hash(file, "model");
  const auto inputs = input_hashes(file);  // WAMIT files, tables: a resume needs the same
  sim.set_checkpoint(rows, [=, &integrator, &outputs, &progress](const State& state,
                                                                 const SimulationPosition& pos) {
    CheckpointWriter w;
    w.put("format", std::string("seaflex-checkpoint-1"));
    w.put("model", to_hex(model_path));
    w.put("model_hash", hash);
    w.put("inputs", static_cast<long>(inputs.size()));
    for (std::size_t k = 0; k < inputs.size(); ++k) {
      w.put(fmt::format("input{}.file", k), to_hex(inputs[k].first));
      w.put(fmt::format("input{}.hash", k), inputs[k].second);
    }
    w.put("checkpoint_rows", rows);
    w.put("wall_s", progress.elapsed());  // the whole run's, so far
    pos.save(w);
    w.put("state.t", state.t);
    w.put("state.q", state.q);
    w.put("state.v", state.v);
    w.put("state.lambda", state.lambda);
    w.put("state.z", state.z);
    if (!integrator.save(w) || !outputs.save_all(w))
      throw std::runtime_error("this run cannot be checkpointed");
    w.write((dir / "checkpoint.txt").string());
  });
}

// Runs the simulation (fresh, or from a checkpoint) and prints its summary.
int simulate(Simulation& sim, State& state, const io::Model& model, const fs::path& dir,
             Outputs& outputs, bool quiet, const SimulationPosition* resume_at,
             cli::ProgressLine& progress) {
  const auto& d = *model.dynamics;
  sim.set_progress([&](double t, double T) { progress.update(t, T); });
  const ScopedInterruptPolling polling;  // a signal stops the run after its current step
  try {
    const double resume_at_t = state.t;
    const SimulationReport rep = resume_at ? sim.resume(state, *resume_at) : sim.run(state);
    progress.done();
    if (quiet) return 0;  // -q: errors only
    // a resumed run counts from its start: steps, rows and wall time of the whole run
    const std::string thread_note =
        fmt::format("{} thread{}", threads(), threads() == 1 ? "" : "s") +
        (resume_at ? fmt::format("; resumed at t = {:g} s, {:.2f} s of it since", resume_at_t,
                                 progress.this_process())
                   : "");
    if (rep.rejected_steps > 0 || rep.min_step < d.time_step)
      fmt::print(
          "dynamics: {} steps ({} rejected and retried, smallest {:g} s) to t = {:g} s in "
          "{:.2f} s wall time ({}); {} Newton iterations; {} rows; max constraint violation "
          "{:.2e}\n",
          rep.steps, rep.rejected_steps, rep.min_step, rep.end_time, progress.elapsed(),
          thread_note, rep.iterations, rep.rows, rep.max_constraint_violation);
    else
      fmt::print(
          "dynamics: {} steps of {:g} s to t = {:g} s in {:.2f} s wall time ({}); {} rows; max "
          "constraint violation {:.2e}\n",
          rep.steps, d.time_step, rep.end_time, progress.elapsed(), thread_note, rep.rows,
          rep.max_constraint_violation);
    fmt::print("wrote {}\n", Outputs::describe(model, dir, "timeseries"));
    fmt::print("{}", outputs.design_summary());
  } catch (const SolverError&) {
    progress.done();
    std::fprintf(stderr, "seaflex: results up to the failure are in %s\n", outputs.names().c_str());
    throw;
  } catch (const OutputError&) {
    progress.done();
    std::fprintf(stderr, "seaflex: results up to the failure are in %s\n", outputs.names().c_str());
    throw;
  } catch (const Interrupted&) {
    progress.done();
    std::fprintf(stderr, "seaflex: results up to the interruption are in %s\n",
                 outputs.names().c_str());
    throw;
  }
  return 0;
}

// the number of output rows between checkpoints every `seconds` (a whole number of rows)
long checkpoint_rows(const io::DynamicsSettings& d, double seconds, const std::string& file) {
  const double interval =
      d.simulation().output_interval > 0.0 ? d.simulation().output_interval : d.time_step;
  const double rows = seconds / interval;
  if (!(rows >= 1.0 - 1e-9) || std::abs(rows - std::round(rows)) > 1e-6 * rows)
    throw InputError(
        {Diagnostic{file, 0, 0, "--checkpoint-every",
                    fmt::format("must be a whole number of output intervals ({:g} s), got {:g} s",
                                interval, seconds)}});
  if (seconds > d.duration)
    throw InputError(
        {Diagnostic{file, 0, 0, "--checkpoint-every",
                    fmt::format("must not exceed the run's duration ({:g} s), got {:g} s",
                                d.duration, seconds)}});
  return std::lround(rows);
}

int cmd_run(const std::string& file, const fs::path& dir, bool quiet, const OutputOptions& options,
            double checkpoint_every) {
  const io::Model model = load_model(file, options);
  if (!model.dynamics)
    throw InputError({Diagnostic{file, 0, 0, "dynamics",
                                 "'seaflex run' needs a dynamics section (time_step, duration); "
                                 "see docs/model-format.md"}});
  const auto& d = *model.dynamics;
  const long rows = checkpoint_every > 0.0 ? checkpoint_rows(d, checkpoint_every, file) : 0;
  if (rows > 0) check_checkpointable(model, file);
  make_output_dir(dir);
  clear_results(model, dir);
  State state =
      d.start_from_statics ? run_statics(model, dir, quiet) : model.system->initial_state();
  auto integrator = d.make_integrator();
  Simulation sim(*model.system, io::output_channels(model), *integrator, d.simulation());
  Outputs outputs(model, dir, "timeseries", true);
  outputs.attach(sim);
  cli::ProgressLine progress(quiet);
  if (rows > 0) enable_checkpoints(sim, file, dir, rows, *integrator, outputs, progress);
  return simulate(sim, state, model, dir, outputs, quiet, nullptr, progress);
}

// Continues the run whose last checkpoint is DIR/checkpoint.txt: the joined files are
// those an uninterrupted run writes, byte for byte.
int cmd_resume(const fs::path& dir, bool quiet) {
  const std::string path = (dir / "checkpoint.txt").string();
  const CheckpointReader in(path);
  const std::string file = from_hex(in, "model");
  {
    // a regular file of bounded size (not /dev/zero, a FIFO or a directory), unchanged
    std::error_code ec;
    const auto st = fs::status(file, ec);
    if (!fs::exists(st))
      in.fail("model",
              fmt::format("the model file {} is gone: a restart needs the same model", file));
    if (!fs::is_regular_file(st))
      in.fail("model", fmt::format("{} is not a regular file (a directory, device or pipe is not "
                                   "a model)",
                                   file));
    if (fs::file_size(file, ec) > io::kMaxInputFileBytes || ec)
      in.fail("model", fmt::format("{} has more than {} bytes", file, io::kMaxInputFileBytes));
    if (io::input_file_hash(file, "model") != in.text("model_hash"))
      in.fail("model", fmt::format("the model file {} changed since the checkpoint (or is gone): "
                                   "a restart needs the same model",
                                   file));
  }
  // every file the model reads, as at the checkpoint (a checkpoint of an older seaflex
  // without the list is refused: it could not tell)
  const long inputs = in.integer("inputs", 0, 100000);
  std::vector<std::string> recorded;
  for (long k = 0; k < inputs; ++k) {
    const std::string key = fmt::format("input{}.file", k);
    const std::string f = from_hex(in, key);
    const std::string hash = io::input_file_hash(f, key);
    if (hash != in.text(fmt::format("input{}.hash", k)))
      in.fail(key, fmt::format("the input file {} {} since the checkpoint: a restart needs the "
                               "same inputs",
                               f, hash == "absent" ? "is gone" : "changed"));
    recorded.push_back(f);
  }
  if (const auto now = io::model_input_files(file); now != recorded)
    for (const auto& f : now)
      if (std::find(recorded.begin(), recorded.end(), f) == recorded.end())
        in.fail("inputs", fmt::format("the model reads {}, which was not there at the checkpoint: "
                                      "a restart needs the same inputs",
                                      f));
  OutputOptions options;
  options.format = "csv";
  const io::Model model = load_model(file, options);
  if (!model.dynamics)
    throw InputError({Diagnostic{file, 0, 0, "dynamics", "the model has no dynamics section"}});
  check_checkpointable(model, file);
  const auto& d = *model.dynamics;
  // the time loop's position: bounded, so that a damaged file cannot run for ever
  const long nominal = std::lround(d.duration / d.time_step);
  in.integer("sim.ticks", 0, nominal << 20);  // at most 2^20 ticks per step (adaptive)
  in.integer("sim.level", 0, 20);
  in.integer("sim.successes", 0);
  in.integer("sim.rows", 1, nominal + 1);
  for (const char* key : {"sim.t0", "sim.scale", "state.t", "sim.min_step"}) in.finite(key);
  for (const char* key : {"sim.steps", "sim.rejected_steps", "sim.iterations"}) in.integer(key, 0);
  const long checkpoint_rows = in.integer("checkpoint_rows", 1, nominal);
  auto integrator = d.make_integrator();
  Simulation sim(*model.system, io::output_channels(model), *integrator, d.simulation());
  Outputs outputs(model, dir, "timeseries", true, /*resume=*/true);
  outputs.restore_all(in);
  outputs.attach(sim);
  // the state: every vector the size this model needs
  const State initial = model.system->initial_state();
  State state = initial;
  state.t = in.finite("state.t");
  state.q = in.vector("state.q", initial.q.size());
  state.v = in.vector("state.v", initial.v.size());
  state.lambda = in.vector("state.lambda", initial.lambda.size());
  state.z = in.vector("state.z", initial.z.size());
  try {
    integrator->restore(*model.system, in);
  } catch (const std::invalid_argument& e) {
    in.fail("", e.what());
  }
  const SimulationPosition pos = SimulationPosition::load(in);
  // the progress line and the summary count the whole run: the wall time before the
  // checkpoint, and the fraction of the run done then
  cli::ProgressLine progress(quiet, in.has("wall_s") ? in.finite("wall_s") : 0.0,
                             (state.t - pos.t0) / d.duration);
  enable_checkpoints(sim, file, dir, checkpoint_rows, *integrator, outputs, progress);
  if (!quiet) fmt::print("resuming {} at t = {:g} s\n", file, state.t);
  return simulate(sim, state, model, dir, outputs, quiet, &pos, progress);
}

int cmd_modes(const std::string& file, const fs::path& dir, int count, bool about_initial,
              bool quiet, bool vtk) {
  const io::Model model = load_model(file);
  make_output_dir(dir);
  clear_results(model, dir);
  const State state =
      about_initial ? model.system->initial_state() : run_statics(model, dir, quiet);
  cli::clear_mode_shapes(dir);
  const ModalResult modes = solve_modes(*model.system, state, count);
  std::string text = "mode,frequency_hz,period_s,omega_rad_s,dominant_coordinate,energy_share\n";
  if (!quiet)
    fmt::print("{:>5} {:>14} {:>14}  {}\n", "mode", "frequency (Hz)", "period (s)",
               "dominant coordinate (share of kinetic energy)");
  for (Index k = 0; k < modes.omega.size(); ++k) {
    const double f = modes.frequency_hz[k];
    const double T = f > 0 ? 1.0 / f : INFINITY;
    const auto dom = post::dominant_coordinate(modes.shapes.col(k), modes.mass_shapes.col(k));
    const std::string name = model.system->coordinate_name(dom.index);
    char line[512];
    std::snprintf(line, sizeof line, "%ld,%.17g,%.17g,%.17g,", static_cast<long>(k + 1), f, T,
                  modes.omega[k]);
    text += line;
    text += name;
    std::snprintf(line, sizeof line, ",%.6g\n", dom.share);
    text += line;
    if (!quiet)
      fmt::print("{:>5} {:>14.6g} {:>14.6g}  {} ({:.0f} %)\n", k + 1, f, T, name, 100 * dom.share);
  }
  write_file_atomically(dir / "modes.csv", text);  // complete or absent
  cli::write_mode_shapes(model, state, modes, dir, vtk);
  if (!quiet)
    fmt::print("wrote {} and {}{}\n", (dir / "modes.csv").string(),
               (dir / "mode_shapes.csv").string(),
               vtk ? fmt::format(" and {}", (dir / "mode<k>.pvd").string()) : "");
  return 0;
}

// Times a model's dynamics without writing results: statics (when the model starts from
// it), then the simulation; prints the speed against real time and where the time goes.
int cmd_bench(const std::string& file, double duration) {
  using Clock = std::chrono::steady_clock;
  const auto seconds_since = [](Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
  };
  const io::Model model = load_model(file);
  if (!model.dynamics)
    throw InputError({Diagnostic{
        file, 0, 0, "dynamics", "'seaflex bench' needs a dynamics section (time_step, duration)"}});
  io::DynamicsSettings d = *model.dynamics;
  if (duration / d.time_step > 2e9)  // the loader's limit on dynamics.duration
    throw InputError({Diagnostic{
        file, 0, 0, "--duration",
        fmt::format("{:g} s at a time step of {:g} s is {:.3g} steps, more than the limit of 2e9",
                    duration, d.time_step, duration / d.time_step)}});
  if (duration > 0.0)
    d.duration = std::max(d.time_step, std::round(duration / d.time_step) * d.time_step);
  fmt::print("model: {} ({} coordinates, {} constraint rows)\n", file,
             model.system->num_coordinates(), model.system->num_constraints());
  State state = model.system->initial_state();
  if (d.start_from_statics) {
    const auto t0 = Clock::now();
    const StaticsReport rep = solve_statics(*model.system, state, model.statics);
    fmt::print("statics: {} Newton iterations in {} increment(s), {:.3f} s wall\n", rep.iterations,
               rep.increments, seconds_since(t0));
  }
  auto integrator = d.make_integrator();
  Simulation sim(*model.system, io::model_channels(model), *integrator, d.simulation());
  const auto t0 = Clock::now();
  const SimulationReport rep = sim.run(state);
  const double wall = seconds_since(t0);
  const IntegratorStats& st = integrator->stats();
  const double other = wall - st.assembly_s - st.factorize_s - st.solve_s;
  fmt::print(
      "dynamics: {}, {:g} s simulated in {:.3f} s wall: {:.4g} s wall per simulated s, "
      "{:.4g} x real time\n",
      integrator->name(), d.duration, wall, wall / d.duration, d.duration / wall);
  fmt::print(
      "steps: {} accepted, {} rejected, smallest {:g} s; {:.3g} iterations per step (Newton; "
      "stages for rk4)\n",
      rep.steps, rep.rejected_steps, rep.min_step,
      static_cast<double>(rep.iterations) / std::max(1L, rep.steps));
  fmt::print("work: {} evaluations, {} factorizations, {} solves\n", st.evaluations,
             st.factorizations, st.solves);
  fmt::print(
      "wall time: assembly {:.3f} s ({:.0f} %), factorization {:.3f} s ({:.0f} %), solve "
      "{:.3f} s ({:.0f} %), other {:.3f} s ({:.0f} %)\n",
      st.assembly_s, 100 * st.assembly_s / wall, st.factorize_s, 100 * st.factorize_s / wall,
      st.solve_s, 100 * st.solve_s / wall, other, 100 * other / wall);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"seaflex: flexible multibody dynamics of offshore structures (ANCF beams)"};
  app.require_subcommand(1);
  app.set_version_flag("--version", fmt::format("seaflex {}", SEAFLEX_VERSION));
  std::string file;
  std::string dir = "results";
  bool quiet = false;
  int count = 10;
  bool about_initial = false;
  int threads = 0;  // 0: not given, keep seaflex::threads()'s default
  const auto add_threads = [&](CLI::App* cmd) {
    cmd->add_option("--threads", threads,
                    "threads of the element loops (default: OMP_NUM_THREADS if set, else 1); "
                    "results are identical for any count; at most the machine's hardware threads")
        ->check(cli::thread_count());
  };

  auto* check = app.add_subcommand("check", "validate a model and print a summary");
  check->add_option("MODEL", file, "model file (YAML)")->required();
  auto* statics = app.add_subcommand("statics", "static equilibrium; writes DIR/statics.csv");
  statics->add_option("MODEL", file, "model file (YAML)")->required();
  statics->add_option("-o,--output", dir, "output directory")->capture_default_str();
  statics->add_flag("-q,--quiet", quiet, "print only errors and warnings");
  add_threads(statics);
  OutputOptions output_options;
  const auto add_format = [&](CLI::App* cmd) {
    cmd->add_option("--format", output_options.format,
                    "result files: csv, hdf5 or both (default: the model's output.format, else "
                    "csv)")
        ->check(CLI::IsMember({"csv", "hdf5", "both"}));
    cmd->add_flag("--vtk", output_options.vtk,
                  "also write a ParaView time series (DIR/<stem>.pvd, DIR/vtk/)");
  };
  add_format(statics);
  auto* run = app.add_subcommand("run", "dynamic simulation; writes DIR/timeseries.csv");
  run->add_option("MODEL", file, "model file (YAML)")->required();
  run->add_option("-o,--output", dir, "output directory")->capture_default_str();
  run->add_flag("-q,--quiet", quiet, "print only errors and warnings");
  double checkpoint_every = 0.0;
  run->add_option("--checkpoint-every", checkpoint_every,
                  "write DIR/checkpoint.txt every T seconds of simulated time (a whole number "
                  "of output intervals), to continue with seaflex resume DIR")
      ->check(cli::finite_positive(1e9, "s"));
  add_threads(run);
  add_format(run);
  auto* modes = app.add_subcommand(
      "modes", "natural frequencies about static equilibrium; writes DIR/modes.csv");
  modes->add_option("MODEL", file, "model file (YAML)")->required();
  modes->add_option("-o,--output", dir, "output directory")->capture_default_str();
  modes->add_option("-n,--count", count, "number of modes")
      ->check(cli::whole_number(1000000))
      ->capture_default_str();
  modes->add_flag("--about-initial", about_initial,
                  "linearize about the initial state instead of statics");
  modes->add_flag("-q,--quiet", quiet, "print only errors and warnings");
  modes->add_flag("--vtk", output_options.vtk,
                  "also write a ParaView animation of each mode (DIR/mode<k>.pvd, DIR/vtk/)");
  add_threads(modes);

  double bench_duration = 0.0;
  auto* bench = app.add_subcommand(
      "bench", "time a model's dynamics (no output files): speed and the split of the work");
  bench->add_option("MODEL", file, "model file (YAML)")->required();
  bench
      ->add_option("--duration", bench_duration,
                   "simulated time (s) instead of the model's duration")
      ->check(cli::finite_positive(1e9, "s"));
  add_threads(bench);

  std::string resume_dir;
  auto* resume =
      app.add_subcommand("resume", "continue a run from its last checkpoint (DIR/checkpoint.txt)");
  resume->add_option("DIR", resume_dir, "output directory of the checkpointed run")->required();
  resume->add_flag("-q,--quiet", quiet, "print only errors and warnings");
  add_threads(resume);

  std::string plot_dir, plot_out;
  std::vector<std::string> plot_channels;
  auto* plot = app.add_subcommand(
      "plot", "PNG figures of a run (DIR/timeseries.csv) into DIR/plots, with python3-matplotlib");
  plot->add_option("DIR", plot_dir, "output directory of seaflex run")->required();
  plot->add_option("CHANNEL", plot_channels,
                   "channels to plot (names or shell patterns); none: the standard report");
  plot->add_option("--out", plot_out, "directory for the PNG files (default DIR/plots)");

  std::vector<std::string> stats_channels;
  auto* stats =
      app.add_subcommand("stats", "statistics and extremes of a run (DIR/statistics.csv)");
  stats->add_option("DIR", plot_dir, "output directory of seaflex run")->required();
  stats->add_option("CHANNEL", stats_channels,
                    "channels (names or shell patterns); none: all but beam stations");
  std::string scatter_file;
  auto* fatigue = app.add_subcommand(
      "fatigue",
      "combine the fatigue damage of load cases (a scatter diagram) into damage per "
      "year and life; writes DIR/<beam>.fatigue_total.csv");
  fatigue->add_option("SCATTER", scatter_file, "scatter diagram (YAML)")->required();
  fatigue->add_option("-o,--output", dir, "output directory")->capture_default_str();
  cli::add_batch_command(app);  // runs in its callback (python3 -m seaflex.batch)

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : kExitInput;
  }
  try {
    if (threads > 0) set_threads(threads);
    if (threads == 0 && seaflex::threads() > cli::hardware_threads())  // from OMP_NUM_THREADS
      throw InputError({Diagnostic{
          "OMP_NUM_THREADS", 0, 0, "",
          fmt::format("{} threads are more than the {} hardware threads of this machine; set at "
                      "most {} (or use --threads)",
                      seaflex::threads(), cli::hardware_threads(), cli::hardware_threads())}});
    install_interrupt_handlers();  // SIGINT/SIGTERM end a run after its current step
    if (*check) return cmd_check(file);
    if (*statics) return cmd_statics(file, dir, quiet, output_options);
    if (*run) return cmd_run(file, dir, quiet, output_options, checkpoint_every);
    if (*resume) return cmd_resume(resume_dir, quiet);
    if (*modes) return cmd_modes(file, dir, count, about_initial, quiet, output_options.vtk);
    if (*bench) return cmd_bench(file, bench_duration);
    if (*plot) return cli::cmd_plot(plot_dir, plot_channels, plot_out);
    if (*stats) return cli::cmd_stats(plot_dir, stats_channels);
    if (*fatigue)
      return cli::cmd_fatigue(scatter_file, dir, [](const std::string& m, const std::string& o) {
        return cmd_run(m, o, true, {}, 0.0);
      });
  } catch (const InputError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return kExitInput;
  } catch (const ModelError& e) {
    std::fprintf(stderr, "seaflex: model error: %s\n", e.what());
    return kExitInput;
  } catch (const SolverError& e) {
    std::fprintf(stderr, "seaflex: solver failure: %s\n", e.what());
    return kExitSolver;
  } catch (const OutputError& e) {
    // disk full, a file size limit: every file is complete up to its last whole row
    std::fprintf(stderr, "seaflex: %s\n", e.what());
    return kExitSolver;
  } catch (const Interrupted& e) {
    std::fprintf(stderr, "seaflex: %s\n", e.what());
    return 128 + e.signal();  // the shell's convention for a death by that signal
  } catch (const std::exception& e) {
    std::fprintf(stderr, "seaflex: error: %s\n", e.what());
    return kExitInput;
  }
  return 0;
}
