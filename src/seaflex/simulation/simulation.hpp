// The time loop: steps an integrator at a fixed step, feeds recorders at the output
// interval, checks every step for NaN/Inf and divergence, and on failure flushes the
// recorders before throwing, so results up to the failure stay on disk.
#pragma once

#include <functional>
#include <vector>

#include "seaflex/integrators/integrator.hpp"
#include "seaflex/model/channel.hpp"
#include "seaflex/simulation/recorder.hpp"

namespace seaflex {

struct SimulationSettings {
  double duration = 0.0;         ///< simulated time (s), > 0
  double time_step = 0.0;        ///< h (s), > 0
  double output_interval = 0.0;  ///< s; a multiple of h (0: every step)
};

struct SimulationReport {
  long steps = 0;
  long rows = 0;
  double end_time = 0.0;
  double max_constraint_violation = 0.0;
};

/// Called every output row: (t, duration).
using SimulationProgress = std::function<void(double, double)>;

class Simulation {
 public:
  Simulation(Dae& dae, ChannelList channels, Integrator& integrator, SimulationSettings settings);

  void add_recorder(Recorder& recorder) { recorders_.push_back(&recorder); }
  void set_progress(SimulationProgress progress) { progress_ = std::move(progress); }

  /// Runs from state.t for settings.duration. Throws SolverError on failure, after
  /// flushing every recorder.
  SimulationReport run(State& state);

  /// Number of steps per output row.
  long steps_per_output() const { return every_; }

 private:
  void record(State& state);

  Dae& dae_;
  ChannelList channels_;
  Integrator& integrator_;
  SimulationSettings settings_;
  std::vector<Recorder*> recorders_;
  SimulationProgress progress_;
  long every_ = 1;
  std::vector<double> row_;
  long rows_ = 0;
};

}  // namespace seaflex
