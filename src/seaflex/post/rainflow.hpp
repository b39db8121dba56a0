// Rainflow cycle counting of a load history, ASTM E1049-85 (reapproved 2017) section 5.4.4
// "Rainflow Counting": the reversals (peaks and valleys) go on a stack; with X the range
// of the two most recent reversals and Y the range before it, while X >= Y: if Y holds
// the starting point S it is counted as one half cycle and S is dropped (S moves to the
// second point of Y), else Y is counted as one cycle and both its points are dropped. At
// the end of the history every range left on the stack counts as one half cycle.
//
// The counter streams: samples arrive one at a time (add), turning points are found on
// the fly (a sample equal to the previous one is no reversal; a plateau counts once), and
// each closed cycle goes to a sink at once. Memory is the stack of reversals not yet
// closed: for a stationary random history its length stays small (the residue, ranges
// that grow then shrink), so a 3-hour storm needs no more than a few dozen doubles per
// point; a history whose ranges grow without end keeps all its reversals.
#pragma once

#include <cmath>
#include <cstddef>
#include <span>
#include <vector>

namespace seaflex::post {

/// One counted cycle: range = |difference of its two reversals|, mean their average,
/// count 1 (a full cycle) or 0.5 (a half cycle).
struct RainflowCycle {
  double range = 0.0;
  double mean = 0.0;
  double count = 0.0;
};

class RainflowCounter {
 public:
  /// Feeds the next sample; calls sink(const RainflowCycle&) for every cycle it closes.
  template <class Sink>
  void add(double x, Sink&& sink) {
    if (!started_) {
      started_ = true;
      last_ = x;
      push(x, sink);  // the starting point S is a reversal
      return;
    }
    if (x == last_) return;
    const int dir = x > last_ ? 1 : -1;
    if (dir_ != 0 && dir != dir_) push(last_, sink);  // last_ was a peak or a valley
    dir_ = dir;
    last_ = x;
  }

  /// Ends the history: the last sample is a reversal, and every range left on the stack
  /// counts as a half cycle (ASTM E1049-85 5.4.4 step 6). The counter is then empty.
  template <class Sink>
  void finish(Sink&& sink) {
    if (started_ && dir_ != 0) push(last_, sink);
    for (std::size_t i = 0; i + 1 < stack_.size(); ++i)
      sink(RainflowCycle{std::abs(stack_[i + 1] - stack_[i]), 0.5 * (stack_[i + 1] + stack_[i]),
                         0.5});
    reset();
  }

  void reset() {
    stack_.clear();
    started_ = false;
    dir_ = 0;
    last_ = 0.0;
  }

  /// Reversals waiting on the stack (the memory the counter holds).
  std::size_t stack_size() const { return stack_.size(); }

 private:
  // ASTM E1049-85 5.4.4 steps 2 to 5 after a new reversal
  template <class Sink>
  void push(double r, Sink& sink) {
    stack_.push_back(r);
    while (stack_.size() >= 3) {
      const std::size_t n = stack_.size();
      const double X = std::abs(stack_[n - 1] - stack_[n - 2]);
      const double Y = std::abs(stack_[n - 2] - stack_[n - 3]);
      if (X < Y) break;
      const double mean = 0.5 * (stack_[n - 2] + stack_[n - 3]);
      if (n == 3) {  // Y holds the starting point S: a half cycle, S moves on
        sink(RainflowCycle{Y, mean, 0.5});
        stack_.erase(stack_.begin());
      } else {  // a full cycle: both points of Y go
        sink(RainflowCycle{Y, mean, 1.0});
        stack_.erase(stack_.end() - 3, stack_.end() - 1);
      }
    }
  }

  std::vector<double> stack_;
  bool started_ = false;
  int dir_ = 0;
  double last_ = 0.0;
};

/// Every cycle of a whole history, in the order they are closed (the residue's half
/// cycles last).
std::vector<RainflowCycle> rainflow(std::span<const double> history);

}  // namespace seaflex::post
