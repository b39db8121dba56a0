// The progress line of `seaflex run` and `seaflex resume` on stderr (shown only when a run
// lasts more than two seconds, never with -q), and the wall time of the whole run: a run
// continued from a checkpoint counts the wall time before the checkpoint (kept in the
// restart file) and estimates the time left from the part it ran itself.
#pragma once

#include <chrono>

namespace seaflex::cli {

class ProgressLine {
 public:
  /// earlier_wall_s: wall time of the run before this process (a resumed run; else 0);
  /// start_fraction: the fraction of the run done before this process.
  explicit ProgressLine(bool quiet, double earlier_wall_s = 0.0, double start_fraction = 0.0);
  ~ProgressLine() { done(); }
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  /// t: simulated time since the start of the run; duration: the run's simulated time.
  void update(double t, double duration);
  /// Ends the line (before other output).
  void done();
  /// Wall time of the whole run so far (s), the earlier processes included.
  double elapsed() const { return earlier_ + this_process(); }
  /// Wall time of this process's part (s).
  double this_process() const;

 private:
  using Clock = std::chrono::steady_clock;
  bool quiet_;
  double earlier_, fraction0_;
  Clock::time_point start_, last_;
  bool shown_ = false;
};

}  // namespace seaflex::cli
