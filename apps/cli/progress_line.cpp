#include "progress_line.hpp"

#include <cstdio>

namespace seaflex::cli {

namespace {
double seconds(std::chrono::steady_clock::duration d) {
  return std::chrono::duration<double>(d).count();
}
}  // namespace

ProgressLine::ProgressLine(bool quiet, double earlier_wall_s, double start_fraction)
    : quiet_(quiet),
      earlier_(earlier_wall_s),
      fraction0_(start_fraction),
      start_(Clock::now()),
      last_(start_) {}

double ProgressLine::this_process() const {
  return seconds(Clock::now() - start_);
}

void ProgressLine::update(double t, double duration) {
  if (quiet_) return;
  const auto now = Clock::now();
  const double mine = seconds(now - start_);
  if (mine < 2.0 || seconds(now - last_) < 0.5) return;
  last_ = now;
  const double frac = duration > 0 ? t / duration : 1.0;
  // the time left at the pace of this process (its share of the run, frac - fraction0)
  const double done_here = frac - fraction0_;
  const double eta = done_here > 0 ? mine * (1.0 - frac) / done_here : 0.0;
  std::fprintf(stderr, "\r[seaflex] t = %.4g / %.4g s  %3.0f%%  elapsed %.1f s  remaining %.1f s  ",
               t, duration, 100.0 * frac, earlier_ + mine, eta);
  shown_ = true;
}

void ProgressLine::done() {
  if (shown_) std::fputc('\n', stderr);
  shown_ = false;
}

}  // namespace seaflex::cli
