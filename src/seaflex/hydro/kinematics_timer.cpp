#include "seaflex/hydro/kinematics_timer.hpp"

namespace seaflex::hydro::kinematics_timer {

namespace detail {
std::atomic<bool> g_on{false};
std::atomic<std::int64_t> g_ns{0};
}  // namespace detail

void enable(bool on) {
  detail::g_on.store(on, std::memory_order_relaxed);
}
void reset() {
  detail::g_ns.store(0, std::memory_order_relaxed);
}
double seconds() {
  return 1e-9 * static_cast<double>(detail::g_ns.load(std::memory_order_relaxed));
}

}  // namespace seaflex::hydro::kinematics_timer
