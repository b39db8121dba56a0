// Interrupted runs (issues 9 and 22). SIGINT and SIGTERM stop every command promptly:
// * inside a loop that polls (the time loop, the statics increments: a ScopedInterruptPolling
//   is alive), the handler only stores the signal; the loop stops after its current step or
//   increment, keeps what it computed (flushes its recorders, writes the last converged
//   statics) and throws Interrupted, so that the command line exits 128 + signal;
// * anywhere else (loading and checking a model, reading files, the constraint audit, the
//   modes, a second signal while a loop finishes its step), nothing is half-written that a
//   polling loop would keep, so the handler prints "seaflex: stopped by SIGINT" and ends the
//   process at once with _exit(128 + signal).
#pragma once

#include <stdexcept>
#include <string>

namespace seaflex {

/// Installs the SIGINT and SIGTERM handlers (async-signal-safe: they store the signal or
/// write a fixed message and _exit).
void install_interrupt_handlers();
/// The signal received since the last clear (0: none).
int interrupt_signal();
/// Behaves as if signal had been received (tests), or clears it with 0.
void set_interrupt_signal(int signal);

/// While alive, a first SIGINT/SIGTERM is left to the polling loop (interrupt_signal());
/// a second one ends the process at once. Nests.
class ScopedInterruptPolling {
 public:
  ScopedInterruptPolling();
  ~ScopedInterruptPolling();
  ScopedInterruptPolling(const ScopedInterruptPolling&) = delete;
  ScopedInterruptPolling& operator=(const ScopedInterruptPolling&) = delete;
};

/// A run stopped by a signal after a completed step, or a computation stopped at a point
/// where its results are consistent (what: "in statics at load factor 0.5").
class Interrupted : public std::runtime_error {
 public:
  /// "interrupted by SIGINT after the step to t = 1.5 s"
  Interrupted(int signal, double time);
  /// "interrupted by SIGINT <what>"
  Interrupted(int signal, const std::string& what);
  int signal() const { return signal_; }
  /// The simulated time reached (NaN when stopped outside the time loop).
  double time() const { return time_; }

 private:
  int signal_;
  double time_;
};

}  // namespace seaflex
