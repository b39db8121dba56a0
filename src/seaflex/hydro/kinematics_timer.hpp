// A wall-time accumulator around the wave kinematics (Ocean::fluid and Ocean::elevation),
// for `seaflex bench`'s split of the time (issue 21). Off by default: then a Scope costs one
// relaxed atomic load. On, each Scope reads the steady clock twice and adds the interval to
// one atomic counter (safe from the OpenMP element loops; the sum over threads is CPU time
// spent in the kinematics, which equals wall time only with one thread).
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>

namespace seaflex::hydro::kinematics_timer {

/// Starts (true) or stops (false) the accumulation; does not reset the total.
void enable(bool on);
/// Sets the accumulated total to zero.
void reset();
/// The accumulated time (s) since the last reset, summed over threads.
double seconds();

namespace detail {
extern std::atomic<bool> g_on;
extern std::atomic<std::int64_t> g_ns;
}  // namespace detail

/// Adds the time between its construction and destruction to the total when enabled.
class Scope {
 public:
  Scope() : on_(detail::g_on.load(std::memory_order_relaxed)) {
    if (on_) t0_ = std::chrono::steady_clock::now();
  }
  ~Scope() {
    if (on_)
      detail::g_ns.fetch_add(std::chrono::duration_cast<std::chrono::nanoseconds>(
                                 std::chrono::steady_clock::now() - t0_)
                                 .count(),
                             std::memory_order_relaxed);
  }
  Scope(const Scope&) = delete;
  Scope& operator=(const Scope&) = delete;

 private:
  bool on_;
  std::chrono::steady_clock::time_point t0_{};
};

}  // namespace seaflex::hydro::kinematics_timer
