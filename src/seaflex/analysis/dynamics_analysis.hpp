// A dynamic run as `seaflex run` (and `seaflex resume`) performs it: the model's integrator
// and time loop (simulation/simulation.hpp), fed to the result files of the timeseries
// stem and to the caller's recorders; statics first when the model starts from them. On a
// failure or interruption every recorder is flushed before the error propagates, so the
// results up to it are kept.
#pragma once

#include <functional>
#include <memory>

#include "seaflex/analysis/analysis_options.hpp"
#include "seaflex/analysis/result_files.hpp"
#include "seaflex/io/model_loader.hpp"

namespace seaflex::analysis {

/// The time loop of one run and its recorders. Precondition: model.dynamics.
class DynamicsRun {
 public:
  /// resume: the result files continue those of a checkpointed run (ResultFiles).
  DynamicsRun(const io::Model& model, const AnalysisOutput& output, bool resume = false);
  ~DynamicsRun();
  DynamicsRun(const DynamicsRun&) = delete;
  DynamicsRun& operator=(const DynamicsRun&) = delete;

  Integrator& integrator() { return *integrator_; }
  Simulation& simulation() { return *simulation_; }
  /// The result files; null when the output has no directory.
  ResultFiles* files() { return files_.get(); }

  /// Runs from state (or continues at resume_at, see Simulation::resume). Throws
  /// SolverError, OutputError or Interrupted after flushing every recorder; hooks.note
  /// then says where the results are.
  SimulationReport run(State& state, const AnalysisHooks& hooks,
                       const SimulationPosition* resume_at = nullptr);

 private:
  std::unique_ptr<Integrator> integrator_;
  std::unique_ptr<Simulation> simulation_;
  std::unique_ptr<ResultFiles> files_;
};

struct RunSummary {
  SimulationReport report;
  std::string design_summary;  ///< fatigue and code-check lines of the result files
};

/// `seaflex run` without its printing: statics when the model starts from them (written
/// as by run_statics), then the time loop from that state. prepare is called before the
/// loop starts (restart files). The output directory must exist (make_output_dir); call
/// clear_results first for a fresh one. Throws InputError without a dynamics section.
RunSummary run_dynamics(const io::Model& model, const AnalysisOutput& output,
                        const AnalysisHooks& hooks = {},
                        const std::function<void(DynamicsRun&)>& prepare = {});

}  // namespace seaflex::analysis
