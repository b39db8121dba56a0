#include "seaflex/core/interrupt.hpp"

#include <fmt/format.h>

#include <csignal>

namespace seaflex {

namespace {
volatile std::sig_atomic_t g_signal = 0;

extern "C" void on_signal(int signal) {
  g_signal = signal;
}

const char* signal_name(int signal) {
  if (signal == SIGINT) return "SIGINT";
  if (signal == SIGTERM) return "SIGTERM";
  return "a signal";
}
}  // namespace

void install_interrupt_handlers() {
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
}

int interrupt_signal() {
  return g_signal;
}

void set_interrupt_signal(int signal) {
  g_signal = signal;
}

Interrupted::Interrupted(int signal, double time)
    : std::runtime_error(fmt::format("interrupted by {} after the step to t = {:.6g} s",
                                     signal_name(signal), time)),
      signal_(signal),
      time_(time) {}

}  // namespace seaflex
