// A wall-time accumulator around the wave kinematics (Ocean::fluid and Ocean::elevation),
// for `seaflex bench`'s split of the time (issue 21). Off by default: then a Scope costs one
// relaxed atomic load. On, one Scope in kSample, drawn at random per thread (xorshift, so
// that no periodic pattern of calls aliases with it), reads the steady clock twice and adds
// kSample times the interval to one atomic counter: an unbiased estimate of the total whose
// cost is 1/kSample of timing every call (timing all of them took 10 % of a grid run; a
// million calls make the sampling error ~0.4 %). Safe from the OpenMP element loops; the
// sum over threads is CPU time spent in the kinematics, wall time only with one thread.
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
inline constexpr std::uint32_t kSample = 16;
// true for one call in kSample, at random (Marsaglia 2003, xorshift32)
inline bool sampled() {
  thread_local std::uint32_t x = 2463534242u;
  x ^= x << 13;
  x ^= x >> 17;
  x ^= x << 5;
  return x % kSample == 0;
}
}  // namespace detail

/// Adds the time between its construction and destruction to the total when enabled.
class Scope {
 public:
  Scope() : on_(detail::g_on.load(std::memory_order_relaxed) && detail::sampled()) {
    if (on_) t0_ = std::chrono::steady_clock::now();
  }
  ~Scope() {
    if (on_)
      detail::g_ns.fetch_add(detail::kSample * std::chrono::duration_cast<std::chrono::nanoseconds>(
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
