#include "seaflex/analysis/dynamics_analysis.hpp"

#include <fmt/format.h>

#include "seaflex/analysis/statics_analysis.hpp"
#include "seaflex/core/errors.hpp"
#include "seaflex/core/interrupt.hpp"
#include "seaflex/core/output_file.hpp"
#include "seaflex/io/output_selection.hpp"

namespace seaflex::analysis {

DynamicsRun::DynamicsRun(const io::Model& model, const AnalysisOutput& output, bool resume) {
  const auto& d = *model.dynamics;
  integrator_ = d.make_integrator();
  simulation_ = std::make_unique<Simulation>(*model.system, io::output_channels(model),
                                             *integrator_, d.simulation());
  if (output.dir) {
    files_ = std::make_unique<ResultFiles>(model, *output.dir, "timeseries", true, resume);
    // the HDF5 rows in blocks of a fixed amount of work: coordinates x steps taken
    files_->set_work_counter(
        [sim = simulation_.get(), n = static_cast<double>(model.system->num_coordinates())] {
          return n * static_cast<double>(sim->steps_taken());
        });
    simulation_->add_recorder(*files_);
  }
  for (Recorder* r : output.timeseries) simulation_->add_recorder(*r);
}

DynamicsRun::~DynamicsRun() = default;

SimulationReport DynamicsRun::run(State& state, const AnalysisHooks& hooks,
                                  const SimulationPosition* resume_at) {
  simulation_->set_progress(hooks.progress);
  const ScopedInterruptPolling polling;  // a signal stops the run after its current step
  const auto note = [&](const char* what) {
    if (hooks.note && files_)
      hooks.note(fmt::format("results up to the {} are in {}", what, files_->names()));
  };
  try {
    return resume_at ? simulation_->resume(state, *resume_at) : simulation_->run(state);
  } catch (const SolverError&) {
    note("failure");
    throw;
  } catch (const OutputError&) {
    note("failure");
    throw;
  } catch (const Interrupted&) {
    note("interruption");
    throw;
  }
}

RunSummary run_dynamics(const io::Model& model, const AnalysisOutput& output,
                        const AnalysisHooks& hooks,
                        const std::function<void(DynamicsRun&)>& prepare) {
  if (!model.dynamics)
    throw InputError({Diagnostic{model.file, 0, 0, "dynamics",
                                 "'seaflex run' needs a dynamics section (time_step, duration); "
                                 "see docs/model-format.md"}});
  State state = model.dynamics->start_from_statics ? run_statics(model, output, hooks)
                                                   : model.system->initial_state();
  DynamicsRun run(model, output);
  if (prepare) prepare(run);
  RunSummary summary;
  summary.report = run.run(state, hooks);
  if (run.files()) summary.design_summary = run.files()->design_summary();
  return summary;
}

}  // namespace seaflex::analysis
