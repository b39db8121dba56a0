// The interface every time integrator implements. Integrators see only the Dae.
#pragma once

#include "seaflex/core/checkpoint.hpp"

#include <string>
#include <string_view>

#include "seaflex/system/dae.hpp"

namespace seaflex {

struct StepReport {
  bool ok = true;
  int iterations = 0;     ///< Newton iterations (implicit) or linear solves (explicit)
  double residual = 0.0;  ///< largest constraint violation after the step
  std::string message;    ///< why the step failed, when !ok
};

/// Work counters and wall time by phase, summed over all steps (for `seaflex bench`).
struct IntegratorStats {
  long steps = 0;            ///< step() calls, failed ones included
  long iterations = 0;       ///< Newton iterations (implicit) or stages (explicit)
  long evaluations = 0;      ///< Dae::evaluate calls
  long factorizations = 0;   ///< numeric factorizations of a sparse matrix
  long solves = 0;           ///< triangular solves
  double assembly_s = 0.0;   ///< wall time in Dae::evaluate
  double factorize_s = 0.0;  ///< wall time in numeric factorizations
  double solve_s = 0.0;      ///< wall time in triangular solves
};

class Integrator {
 public:
  virtual ~Integrator() = default;
  virtual std::string_view name() const = 0;
  /// Called once by the Simulation before the first step (and before the first output
  /// row): integrators with memory (accelerations) initialize it from the state, and may
  /// set state.lambda. Nothing by default.
  virtual void start(const Dae& /*dae*/, State& /*state*/) {}
  /// A step that fails (StepReport::ok false) must leave the integrator's memory as it was
  /// before the step: the Simulation restores the state and may retry with a smaller h.
  virtual const IntegratorStats& stats() const { return stats_; }
  /// Advances state (t, q, v) by h. Must not allocate after the first call.
  virtual StepReport step(const Dae& dae, State& state, double h) = 0;
  /// Sets state.lambda to the multipliers consistent with (t, q, v) (thesis eq. 132), for
  /// reaction outputs; called by the Simulation before it records a row.
  virtual void update_multipliers(const Dae& dae, State& state) = 0;

  /// Adaptive step control: an estimate of the local error of the positions of the last
  /// successful step, per coordinate (m, or the coordinate's own unit for slopes and Euler
  /// parameters); empty when the integrator has none. It shrinks as h^local_error_order().
  const VecX& local_error() const { return local_error_; }
  virtual int local_error_order() const { return 0; }
  /// The Simulation rejected the last successful step (its error estimate was too large, or
  /// the state diverged): the integrator takes back the memory that step changed, so that
  /// the next step() continues from the state before it. Nothing by default.
  virtual void reject_step() {}

  /// Restart files (core/checkpoint.hpp): writes what the integrator carries from one step
  /// to the next; false when it cannot be checkpointed.
  virtual bool save(CheckpointWriter& /*out*/) const { return false; }
  /// Takes that back for dae, in place of start(): the next step() continues exactly as
  /// the saved run would have.
  virtual void restore(const Dae& /*dae*/, const CheckpointReader& /*in*/) {}

 protected:
  IntegratorStats stats_;
  VecX local_error_;
};

}  // namespace seaflex
