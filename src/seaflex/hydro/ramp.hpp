// Start-up ramp of the wave field: a half-cosine from 0 to 1 that lets a simulation
// start from calm water without an impulsive load (common practice, e.g. OrcaFlex's
// "build-up" stage and MoorDyn's ramp).
#pragma once

namespace seaflex::hydro {

/// factor(t) = 0 for t < start; 0.5 (1 - cos(pi (t - start) / duration)) for
/// start <= t < start + duration; 1 afterwards. duration <= 0 means a step at start;
/// with start = 0 and duration = 0 the factor is 1 at every time (no ramp).
struct Ramp {
  double start = 0.0;     ///< (s)
  double duration = 0.0;  ///< (s)
  /// The ramp factor (-) in [0, 1] at time t (s).
  double factor(double t) const;
};

}  // namespace seaflex::hydro
