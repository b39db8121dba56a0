// The interface every time integrator implements. Integrators see only the Dae.
#pragma once

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

class Integrator {
 public:
  virtual ~Integrator() = default;
  virtual std::string_view name() const = 0;
  /// Advances state (t, q, v) by h. Must not allocate after the first call.
  virtual StepReport step(const Dae& dae, State& state, double h) = 0;
  /// Sets state.lambda to the multipliers consistent with (t, q, v) (thesis eq. 132), for
  /// reaction outputs; called by the Simulation before it records a row.
  virtual void update_multipliers(const Dae& dae, State& state) = 0;
};

}  // namespace seaflex
