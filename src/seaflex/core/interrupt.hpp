// Interrupted runs (issue 9): SIGINT and SIGTERM set a flag that the time loop reads after
// every step; it then records nothing more, flushes its recorders and throws Interrupted,
// so that the command line exits non-zero with every row computed so far on disk.
#pragma once

#include <stdexcept>
#include <string>

namespace seaflex {

/// Installs the SIGINT and SIGTERM handlers (async-signal-safe: they store the signal).
void install_interrupt_handlers();
/// The signal received since the last clear (0: none).
int interrupt_signal();
/// Behaves as if signal had been received (tests), or clears it with 0.
void set_interrupt_signal(int signal);

/// A run stopped by a signal after a completed step.
class Interrupted : public std::runtime_error {
 public:
  Interrupted(int signal, double time);
  int signal() const { return signal_; }
  double time() const { return time_; }

 private:
  int signal_;
  double time_;
};

}  // namespace seaflex
