// seaflex command line: check, statics, run, modes, bench, plot. Exit codes: 0 success, 2
// input or usage error, 3 solver failure or a result file that cannot be written (results up
// to the failure stay on disk, whole rows only), 130/143
// a run stopped by SIGINT/SIGTERM after its current step (results up to it stay on disk).
#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <optional>

#include "batch_command.hpp"
#include "fatigue_command.hpp"
#include "mode_output.hpp"
#include "option_checks.hpp"
#include "plot_command.hpp"
#include "progress_line.hpp"
#include "seaflex/analysis/bench_run.hpp"
#include "seaflex/analysis/dynamics_analysis.hpp"
#include "seaflex/analysis/model_summary.hpp"
#include "seaflex/analysis/restart_files.hpp"
#include "seaflex/analysis/result_files.hpp"
#include "seaflex/analysis/statics_analysis.hpp"
#include "seaflex/core/errors.hpp"
#include "seaflex/core/interrupt.hpp"
#include "seaflex/core/output_file.hpp"
#include "seaflex/core/parallel.hpp"
#include "seaflex/hydro/ocean.hpp"
#include "seaflex/hydro/wave_grid.hpp"
#include "seaflex/io/model_loader.hpp"
#include "seaflex/post/mode_shapes.hpp"
#include "seaflex/solvers/modal.hpp"
#include "seaflex/solvers/statics.hpp"
#include "stats_command.hpp"

namespace fs = std::filesystem;
using namespace seaflex;

namespace {

constexpr int kExitInput = 2;
constexpr int kExitSolver = 3;

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

// the report of statics: increments on stderr, the convergence and design summary on
// stdout, where a failed statics kept its last increment
analysis::AnalysisHooks statics_hooks(const io::Model& model, bool quiet) {
  analysis::AnalysisHooks hooks;
  hooks.statics_increment = [&model, quiet](double factor, int iterations,
                                            const StaticsReport& so_far) {
    if (!quiet && model.statics.load_steps > 1)
      fmt::print(stderr, "[seaflex] statics: load factor {:.4g} converged in {} iterations: {}\n",
                 factor, iterations, describe_convergence(so_far));
  };
  hooks.statics_done = [&model, quiet](const StaticsReport& rep,
                                       const std::string& design_summary) {
    if (const std::string w = describe_instability(*model.system, rep.stability); !w.empty())
      fmt::print(stderr, "warning: statics: {}\n", w);
    if (quiet) return;
    fmt::print("statics converged: {} load increment(s), {} Newton iterations; {}\n",
               rep.increments, rep.iterations, describe_convergence(rep));
    fmt::print("{}", design_summary);
  };
  hooks.note = [](const std::string& note) { std::fprintf(stderr, "seaflex: %s\n", note.c_str()); };
  return hooks;
}

// statics with a report on stdout; on failure the last converged state goes to
// statics_partial.csv (.h5) before the error propagates
State run_statics(const io::Model& model, const fs::path& dir, bool quiet) {
  analysis::AnalysisOutput output;
  output.dir = dir;
  return analysis::run_statics(model, output, statics_hooks(model, quiet));
}

int cmd_check(const std::string& file) {
  const io::Model model = load_model(file);
  fmt::print("{}model OK\n", analysis::model_summary(model));
  return 0;
}

int cmd_statics(const std::string& file, const fs::path& dir, bool quiet,
                const OutputOptions& options) {
  const io::Model model = load_model(file, options);
  analysis::make_output_dir(dir);
  analysis::clear_results(model, dir);
  run_statics(model, dir, quiet);
  if (!quiet) fmt::print("wrote {}\n", analysis::ResultFiles::describe(model, dir, "statics"));
  return 0;
}

// The summary of a run (fresh, or continued from a checkpoint) on stdout.
void print_run(const SimulationReport& rep, const io::Model& model, const fs::path& dir,
               const cli::ProgressLine& progress, const SimulationPosition* resume_at,
               double resume_at_t, const std::string& design_summary) {
  const auto& d = *model.dynamics;
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
        rep.steps, rep.rejected_steps, rep.min_step, rep.end_time, progress.elapsed(), thread_note,
        rep.iterations, rep.rows, rep.max_constraint_violation);
  else
    fmt::print(
        "dynamics: {} steps of {:g} s to t = {:g} s in {:.2f} s wall time ({}); {} rows; max "
        "constraint violation {:.2e}\n",
        rep.steps, d.time_step, rep.end_time, progress.elapsed(), thread_note, rep.rows,
        rep.max_constraint_violation);
  if (rep.floor_steps_above_tolerance > 0)
    fmt::print(
        "warning: {} step{} at the smallest time step ({:g} s) kept an estimated local error "
        "above error_tolerance (up to {:.3g} times it, below the 0.01 x (1 + |q|) at which a "
        "step fails): lower min_time_step for these instants to meet the tolerance\n",
        rep.floor_steps_above_tolerance, rep.floor_steps_above_tolerance == 1 ? "" : "s",
        rep.min_step, rep.floor_worst_error);
  fmt::print("wrote {}\n", analysis::ResultFiles::describe(model, dir, "timeseries"));
  fmt::print("{}", design_summary);
}

// the progress line on stderr and the notes of a failed run after it
analysis::AnalysisHooks run_hooks(cli::ProgressLine*& progress) {
  analysis::AnalysisHooks hooks;
  hooks.progress = [&progress](double t, double T) {
    if (progress) progress->update(t, T);
  };
  hooks.note = [&progress](const std::string& note) {
    if (progress) progress->done();
    std::fprintf(stderr, "seaflex: %s\n", note.c_str());
  };
  return hooks;
}

int cmd_run(const std::string& file, const fs::path& dir, bool quiet, const OutputOptions& options,
            double checkpoint_every) {
  const io::Model model = load_model(file, options);
  if (!model.dynamics)
    throw InputError({Diagnostic{file, 0, 0, "dynamics",
                                 "'seaflex run' needs a dynamics section (time_step, duration); "
                                 "see docs/model-format.md"}});
  const auto& d = *model.dynamics;
  const long rows =
      checkpoint_every > 0.0 ? analysis::checkpoint_rows(d, checkpoint_every, file) : 0;
  if (rows > 0) analysis::check_checkpointable(model, file);
  analysis::make_output_dir(dir);
  analysis::clear_results(model, dir);
  analysis::AnalysisOutput output;
  output.dir = dir;
  // the statics of the run print as `seaflex statics` does; the progress line starts with
  // the time loop
  std::optional<cli::ProgressLine> progress;
  cli::ProgressLine* line = nullptr;
  analysis::AnalysisHooks hooks = statics_hooks(model, quiet);
  const analysis::AnalysisHooks loop = run_hooks(line);
  hooks.progress = loop.progress;
  hooks.note = loop.note;
  const analysis::RunSummary summary =
      analysis::run_dynamics(model, output, hooks, [&](analysis::DynamicsRun& run) {
        line = &progress.emplace(quiet);
        if (rows > 0)
          analysis::enable_checkpoints(run, file, dir, rows, [line] { return line->elapsed(); });
      });
  line->done();
  if (!quiet) print_run(summary.report, model, dir, *line, nullptr, 0.0, summary.design_summary);
  return 0;
}

// Continues the run whose last checkpoint is DIR/checkpoint.txt: the joined files are
// those an uninterrupted run writes, byte for byte.
int cmd_resume(const fs::path& dir, bool quiet) {
  OutputOptions options;
  options.format = "csv";
  const auto resumed = analysis::read_checkpoint(
      dir, [&](const std::string& file) { return load_model(file, options); });
  const io::Model& model = resumed->model;
  State& state = resumed->state;
  const SimulationPosition& pos = resumed->position;
  analysis::DynamicsRun& run = *resumed->run;
  // the progress line and the summary count the whole run: the wall time before the
  // checkpoint, and the fraction of the run done then
  cli::ProgressLine progress(quiet, resumed->wall_s, (state.t - pos.t0) / model.dynamics->duration);
  analysis::enable_checkpoints(run, resumed->file, dir, resumed->checkpoint_rows,
                               [&progress] { return progress.elapsed(); });
  if (!quiet) fmt::print("resuming {} at t = {:g} s\n", resumed->file, state.t);
  cli::ProgressLine* line = &progress;
  const double resume_at_t = state.t;
  const SimulationReport rep = run.run(state, run_hooks(line), &pos);
  progress.done();
  if (!quiet)
    print_run(rep, model, dir, progress, &pos, resume_at_t, run.files()->design_summary());
  return 0;
}

int cmd_modes(const std::string& file, const fs::path& dir, int count, bool about_initial,
              bool quiet, bool vtk) {
  const io::Model model = load_model(file);
  analysis::make_output_dir(dir);
  analysis::clear_results(model, dir);
  const State state =
      about_initial ? model.system->initial_state() : run_statics(model, dir, quiet);
  cli::clear_mode_shapes(dir);
  const ModalResult modes = solve_modes(*model.system, state, count);
  if (const std::string w = describe_unstable_modes(modes.unstable, modes.lowest_omega2);
      !w.empty())
    fmt::print(stderr, "warning: modes: {}\n", w);
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
  const io::Model model = load_model(file);
  const analysis::BenchReport b = analysis::bench_dynamics(model, duration, file);
  fmt::print("model: {} ({} coordinates, {} constraint rows)\n", file,
             model.system->num_coordinates(), model.system->num_constraints());
  if (b.statics)
    fmt::print("statics: {} Newton iterations in {} increment(s), {:.3f} s wall\n",
               b.statics->iterations, b.statics->increments, b.statics_wall_s);
  const double wall = b.wall_s;
  const IntegratorStats& st = b.stats;
  const SimulationReport& rep = b.run;
  const double other = wall - st.assembly_s - st.factorize_s - st.solve_s;
  fmt::print(
      "dynamics: {}, {:g} s simulated in {:.3f} s wall: {:.4g} s wall per simulated s, "
      "{:.4g} x real time\n",
      b.integrator, b.duration, wall, wall / b.duration, b.duration / wall);
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
  fmt::print(
      "assembly split: wave kinematics {:.3f} s ({:.0f} %), other forces and tangents {:.3f} s "
      "({:.0f} %)\n",
      b.wave_kinematics_s, 100 * b.wave_kinematics_s / wall, st.assembly_s - b.wave_kinematics_s,
      100 * (st.assembly_s - b.wave_kinematics_s) / wall);
  if (const hydro::WaveGrid* grid = model.ocean ? model.ocean->waves().grid() : nullptr)
    fmt::print(
        "wave grid: {} columns started, {} blocks of {} levels filled ({:.3g} and {:.3g} per "
        "step)\n",
        grid->columns_started(), grid->blocks_filled(), hydro::WaveGrid::kBlock,
        static_cast<double>(grid->columns_started()) / std::max(1L, rep.steps),
        static_cast<double>(grid->blocks_filled()) / std::max(1L, rep.steps));
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
