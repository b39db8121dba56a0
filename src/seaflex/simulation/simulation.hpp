// The time loop: steps an integrator, feeds recorders at the output interval, checks every
// step for NaN/Inf and divergence, and on failure flushes the recorders before throwing,
// so results up to the failure stay on disk. After a SIGINT/SIGTERM (core/interrupt.hpp) it
// stops at the end of the current step and throws Interrupted, after flushing.
// Step control: fixed (every step h, reproducible), or adaptive. Adaptive steps are
// accepted only when they are accurate: the integrator's estimate e of the local error of
// the positions (Integrator::local_error(); generalized-alpha: Zienkiewicz & Xie 1991,
// RK4: an embedded third-order solution) is measured in the norm of Hairer, Norsett &
// Wanner (Solving ODEs I, sec. II.4, eq. (4.10)-(4.11), max norm)
//   err = max_i |e_i| / sc_i,  sc_i = tol (1 + max(|q_i(t_n)|, |q_i(t_n+1)|)),
// with Atol = Rtol = tol = error_tolerance (m for positions; slopes and Euler parameters
// are dimensionless), and the step is accepted when err <= 1. The step-size factor is
// that of the same section, eq. (4.13), f = 0.9 err^(-1/p) with p the order of the estimate
// (e ~ h^p: 3 for generalized-alpha, 4 for RK4), on the grid of powers of two: a rejected
// step is retried from the saved state with h / 2^k, 2^-k the largest power of two at most
// f (k from 1 to 4), and the step doubles once four steps in a row were accepted, the last
// one with f >= 2, and the doubled step stays on its own grid. A failed step (Newton
// failure, NaN/Inf, runaway) is retried with h/2. Down to the smallest step; a step that
// fails there stops the run, and so does one whose error estimate there exceeds the
// fixed-step limit (simulation.cpp, 1 % of 1 + |q|). Steps are whole powers-of-two
// fractions of h counted in integer ticks, so that every output time is hit exactly and
// t carries no round-off.
#pragma once

#include <functional>
#include <vector>

#include "seaflex/integrators/integrator.hpp"
#include "seaflex/model/channel.hpp"
#include "seaflex/simulation/recorder.hpp"

namespace seaflex {

enum class StepControl { kFixed, kAdaptive };

struct SimulationSettings {
  double duration = 0.0;         ///< simulated time (s), > 0
  double time_step = 0.0;        ///< h (s), > 0; the largest step when adaptive
  double output_interval = 0.0;  ///< s; a multiple of h (0: every step)
  StepControl step_control = StepControl::kFixed;
  double min_time_step = 0.0;  ///< adaptive: smallest step (s); 0: h / 1024
  /// adaptive: tolerance of the estimated local error of the positions, relative to
  /// 1 + |q_i| (see the file header)
  double error_tolerance = 1e-6;
};

struct SimulationReport {
  long steps = 0;             ///< accepted steps
  long rejected_steps = 0;    ///< failed or inaccurate steps retried with a smaller step (adaptive)
  long inaccurate_steps = 0;  ///< of these, the steps whose error estimate was too large
  /// steps taken at the smallest time step (adaptive) although their error estimate was
  /// above error_tolerance (below the fixed-step limit), and the largest such estimate in
  /// units of error_tolerance x (1 + |q|)
  long floor_steps_above_tolerance = 0;
  double floor_worst_error = 0.0;
  long iterations = 0;  ///< Newton iterations (or stages) of the accepted steps
  long rows = 0;
  double end_time = 0.0;
  double max_constraint_violation = 0.0;
  double min_step = 0.0;  ///< smallest step taken (s)
};

/// Called every output row: (t, duration).
using SimulationProgress = std::function<void(double, double)>;

/// Where the time loop is (restart files): the start time, the time in ticks of
/// h / 2^levels, the adaptive level and its count of successes, the rows written, the
/// report so far.
struct SimulationPosition {
  double t0 = 0.0;
  long ticks = 0;
  int level = 0;
  int successes = 0;
  long rows = 0;
  double scale = 1.0;  ///< the divergence test's state scale (of the initial state)
  SimulationReport report;
  void save(CheckpointWriter& out) const;
  static SimulationPosition load(const CheckpointReader& in);
};

/// Called after every `every` output rows (not after the last): the state and the
/// position, for a restart file.
using SimulationCheckpoint = std::function<void(const State&, const SimulationPosition&)>;

class Simulation {
 public:
  Simulation(Dae& dae, ChannelList channels, Integrator& integrator, SimulationSettings settings);

  void add_recorder(Recorder& recorder) { recorders_.push_back(&recorder); }
  void set_progress(SimulationProgress progress) { progress_ = std::move(progress); }
  /// Restart files: sink is called after every `every_rows` output rows.
  void set_checkpoint(long every_rows, SimulationCheckpoint sink) {
    checkpoint_every_ = every_rows;
    checkpoint_ = std::move(sink);
  }

  /// Runs from state.t for settings.duration. Throws SolverError on failure, after
  /// flushing every recorder.
  SimulationReport run(State& state);
  /// Continues a saved run from its position: the state, the integrator (restore()), the
  /// forces and the recorders (restore()) are already those of the checkpoint; no start,
  /// no first row.
  SimulationReport resume(State& state, const SimulationPosition& position);

  /// Number of steps per output row.
  long steps_per_output() const { return every_; }
  /// Steps taken by run() or resume() so far, the retried ones included (the work done:
  /// the same count in every run of the model).
  long steps_taken() const { return steps_taken_; }

 private:
  void record(State& state);
  // the integrator's local error estimate of the step from saved_ to state, in units of
  // the tolerance (the file header); the coordinate where it is largest
  double error_norm(const State& state, Index& worst) const;
  SimulationReport loop(State& state, SimulationPosition pos, bool fresh);

  Dae& dae_;
  ChannelList channels_;
  Integrator& integrator_;
  SimulationSettings settings_;
  std::vector<Recorder*> recorders_;
  SimulationProgress progress_;
  SimulationCheckpoint checkpoint_;
  long checkpoint_every_ = 0;
  long every_ = 1;
  int levels_ = 0;  // adaptive: the step may be halved this many times
  State saved_;     // the state before the step, for a retry
  std::vector<double> row_;
  long rows_ = 0;
  long steps_taken_ = 0;
};

}  // namespace seaflex
