// `seaflex bench` without its printing: a model's dynamics timed without writing results
// (statics first when the model starts from them), with the integrator's split of the
// work and wall time (assembly, of it the wave kinematics; factorization, solve).
#pragma once

#include <optional>
#include <string>

#include "seaflex/io/model_loader.hpp"

namespace seaflex::analysis {

struct BenchReport {
  double duration = 0.0;                 ///< simulated time (s)
  std::optional<StaticsReport> statics;  ///< when the model starts from statics
  double statics_wall_s = 0.0;
  std::string integrator;
  SimulationReport run;
  double wall_s = 0.0;  ///< of the time loop
  IntegratorStats stats;
  /// time in the wave kinematics (Ocean::fluid, Ocean::elevation) during the time loop,
  /// summed over threads (s); part of stats.assembly_s
  double wave_kinematics_s = 0.0;
};

/// Runs the model's dynamics for `duration` seconds (rounded to whole steps; 0: the
/// model's duration) with every channel evaluated at each output row and nothing written.
/// Throws InputError (file in messages) without a dynamics section or beyond 2e9 steps.
BenchReport bench_dynamics(const io::Model& model, double duration, const std::string& file);

}  // namespace seaflex::analysis
