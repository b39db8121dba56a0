// Where an analysis (statics, a run) writes its results and what it tells its caller as it
// goes. The command line writes result files and prints; the Python module records in
// memory and calls Python back. Both run the same analysis code (statics_analysis.hpp,
// dynamics_analysis.hpp), so their numbers are the same bit for bit.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "seaflex/simulation/recorder.hpp"
#include "seaflex/simulation/simulation.hpp"
#include "seaflex/solvers/statics.hpp"

namespace seaflex::analysis {

struct AnalysisOutput {
  /// Result files in this directory (analysis/result_files.hpp); none: no files.
  std::optional<std::filesystem::path> dir;
  /// Recorders of the caller (not owned): the statics row (or, when statics fail or are
  /// interrupted, the last converged increment), and every output row of a run.
  std::vector<Recorder*> statics;
  std::vector<Recorder*> timeseries;
};

struct AnalysisHooks {
  /// Each converged statics load increment: (load factor, its iterations, report so far).
  std::function<void(double, int, const StaticsReport&)> statics_increment;
  /// Statics converged (and written): the report and the design summary of the files.
  std::function<void(const StaticsReport&, const std::string&)> statics_done;
  /// Every output row of the time loop: (time since the start, duration).
  SimulationProgress progress;
  /// Where the results of a failed or interrupted analysis are (a line for stderr).
  std::function<void(const std::string&)> note;
};

}  // namespace seaflex::analysis
