// Detects a time integration that grows without bound while its state is still finite and
// small, as an explicit integrator does above its stability limit: RK4 multiplies a mode of
// circular frequency omega by |R(i omega h)| per step, R(z) = 1 + z + z^2/2 + z^3/6 + z^4/24
// (Hairer & Wanner, Solving ODEs II, sec. IV.2), with
//   |R(iy)|^2 = 1 - y^6/72 + y^8/576,
// above 1 for y = omega h > 2 sqrt(2) = 2.83: at omega h = 3 a spring's amplitude grows by
// 1.505 and its energy by 2.26 per step. The divergence test of the time loop (|q| above
// 1e6 times its initial size) catches this only after tens of steps, when the energy has
// grown by 1e10 or more.
//
// The test here: the largest velocity norm |v| in each window of kWindow steps. The run
// grows without bound when that maximum rose by at least kFactor from each window to the
// next for kWindows windows in a row (|v| times 4^4 = 256, the energy times 65536, within
// 30 steps: at least 1.26 per step), and the last of these window ratios is at least a
// quarter of the first (a geometric growth keeps its ratio; the window maximum samples an
// oscillation within a factor 1.5 at omega h = 3). A motion that the step resolves cannot
// grow that fast: an exponential growth e^(lambda t) with lambda h >= 0.23 is not resolved
// by h. A motion starting from rest, |v| ~ t^p, gives window ratios ((j + 1)/j)^p that fall
// from window to window: it never fires for p < 12 (tests/unit/test_growth_monitor.cpp);
// a higher power is locally an exponential and cannot be told apart. RK4 above its limit
// fires after 30 steps (42 at omega h = 2.95). Not caught: runs of fewer than 30 steps,
// and growth slower than about 1.26 per step (RK4 at 2.83 < omega h < 2.95), which the
// divergence test stops later.
// Cost: one norm of v per step.
#pragma once

#include <optional>

namespace seaflex {

class GrowthMonitor {
 public:
  static constexpr int kWindow = 6;       ///< steps per window
  static constexpr double kFactor = 4.0;  ///< growth of the window maximum that counts
  static constexpr int kWindows = 4;      ///< consecutive growing windows that stop a run

  /// Forgets the history (a new run, a resumed run, a retried step).
  void reset() { *this = GrowthMonitor(); }

  /// Call after each accepted step with |v|. Returns the mean growth factor of |v| per
  /// step over the growing windows when the run grows without bound.
  std::optional<double> observe(double velocity_norm);

  /// RK4: the omega h > 2 sqrt(2) at which |R(i omega h)| equals growth (> 1).
  static double rk4_omega_h(double growth);

 private:
  int steps_ = 0;             // steps in the current window
  double current_ = 0.0;      // largest |v| in the current window
  double last_ = 0.0;         // largest |v| of the last completed window (0: none yet)
  double first_ = 0.0;        // largest |v| of the window before the growing windows
  double first_ratio_ = 0.0;  // the ratio of the first growing window
  int growing_ = 0;           // consecutive windows that grew by kFactor
};

}  // namespace seaflex
