// Restart files of a run (`seaflex run --checkpoint-every T`, `seaflex resume DIR`):
// DIR/checkpoint.txt holds the model's path and hash, the hashes of every file it reads,
// the time loop's position, the state, the integrator's memory and every recorder's
// position (core/checkpoint.hpp), so that a resumed run writes the files an uninterrupted
// one writes, byte for byte. Every value read back is checked (type, range, size) and a
// changed model or input file is refused.
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <string>

#include "seaflex/analysis/dynamics_analysis.hpp"
#include "seaflex/io/model_loader.hpp"

namespace seaflex::analysis {

/// Refuses (InputError, key --checkpoint-every) a model or output that a restart file
/// cannot hold yet: radiation memory, fatigue counters, HDF5 or VTK output.
void check_checkpointable(const io::Model& model, const std::string& file);
/// The number of output rows between checkpoints every `seconds`: a whole number of
/// output intervals, at most the run's duration (InputError otherwise).
long checkpoint_rows(const io::DynamicsSettings& d, double seconds, const std::string& file);
/// Writes DIR/checkpoint.txt every `rows` output rows of run (which has result files);
/// wall_s gives the whole run's wall time so far (kept for the resumed run's summary).
void enable_checkpoints(DynamicsRun& run, const std::string& file, const std::filesystem::path& dir,
                        long rows, std::function<double()> wall_s);

/// A run restored from its last checkpoint, ready to continue with
/// run->run(state, hooks, &position).
struct ResumedRun {
  std::string file;  ///< the model file
  io::Model model;
  std::unique_ptr<DynamicsRun> run;  ///< its result files continue those in the directory
  State state;
  SimulationPosition position;
  double wall_s = 0.0;       ///< wall time of the run before the checkpoint (s)
  long checkpoint_rows = 0;  ///< output rows between checkpoints
};

/// Reads DIR/checkpoint.txt and restores the run; load reads the model file (the command
/// line prints its warnings and keeps CSV output). Throws InputError naming the file and
/// key for a damaged checkpoint, a changed or missing model or input file.
std::unique_ptr<ResumedRun> read_checkpoint(
    const std::filesystem::path& dir, const std::function<io::Model(const std::string&)>& load);

}  // namespace seaflex::analysis
