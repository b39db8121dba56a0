#include "seaflex/core/interrupt.hpp"

#include <unistd.h>

#include <fmt/format.h>

#include <cmath>
#include <csignal>
#include <cstring>

namespace seaflex {

namespace {
volatile std::sig_atomic_t g_signal = 0;
volatile std::sig_atomic_t g_polling = 0;  // depth of live ScopedInterruptPolling

const char* signal_name(int signal) {
  if (signal == SIGINT) return "SIGINT";
  if (signal == SIGTERM) return "SIGTERM";
  return "a signal";
}

extern "C" void on_signal(int signal) {
  if (g_polling > 0 && g_signal == 0) {  // a loop polls: it stops after its step
    g_signal = signal;
    return;
  }
  // nothing polls (or a second signal): stop at once; write(2) and _exit(2) are
  // async-signal-safe, stdio is not
  const char* text = signal == SIGINT    ? "seaflex: stopped by SIGINT\n"
                     : signal == SIGTERM ? "seaflex: stopped by SIGTERM\n"
                                         : "seaflex: stopped by a signal\n";
  const ssize_t ignored = ::write(STDERR_FILENO, text, std::strlen(text));
  (void)ignored;
  ::_exit(128 + signal);
}
}  // namespace

void install_interrupt_handlers() {
  struct sigaction action {};
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;  // a read interrupted by a stored signal goes on
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

int interrupt_signal() {
  return g_signal;
}

void set_interrupt_signal(int signal) {
  g_signal = signal;
}

ScopedInterruptPolling::ScopedInterruptPolling() {
  g_polling = g_polling + 1;
}

ScopedInterruptPolling::~ScopedInterruptPolling() {
  g_polling = g_polling - 1;
}

Interrupted::Interrupted(int signal, double time)
    : std::runtime_error(fmt::format("interrupted by {} after the step to t = {:.6g} s",
                                     signal_name(signal), time)),
      signal_(signal),
      time_(time) {}

Interrupted::Interrupted(int signal, const std::string& what)
    : std::runtime_error(fmt::format("interrupted by {} {}", signal_name(signal), what)),
      signal_(signal),
      time_(NAN) {}

}  // namespace seaflex
