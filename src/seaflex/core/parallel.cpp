#include "seaflex/core/parallel.hpp"

#include <algorithm>
#include <atomic>
#include <climits>
#include <cstdlib>
#include <exception>
#include <stdexcept>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace seaflex {

namespace {

std::atomic<int> g_threads{0};  // 0: not set, read the default on first use

int default_threads() {
#ifdef _OPENMP
  if (std::getenv("OMP_NUM_THREADS") != nullptr) return std::max(1, omp_get_max_threads());
#endif
  return 1;
}

}  // namespace

void set_threads(int n) {
  if (n < 1) throw std::invalid_argument("set_threads: the thread count must be at least 1");
#ifdef _OPENMP
  g_threads.store(n, std::memory_order_relaxed);
#else
  g_threads.store(1, std::memory_order_relaxed);
#endif
}

int threads() {
  int n = g_threads.load(std::memory_order_relaxed);
  if (n == 0) {
    n = default_threads();
    g_threads.store(n, std::memory_order_relaxed);
  }
  return n;
}

bool parallel_available() {
#ifdef _OPENMP
  return true;
#else
  return false;
#endif
}

ElementColoring::ElementColoring(std::span<const int> color_of) {
  int colors = 0;
  for (int c : color_of) {
    if (c < 0) throw std::invalid_argument("ElementColoring: negative color");
    colors = std::max(colors, c + 1);
  }
  begin_.assign(static_cast<std::size_t>(colors) + 1, 0);
  for (int c : color_of) ++begin_[static_cast<std::size_t>(c) + 1];
  for (int c = 0; c < colors; ++c) begin_[c + 1] += begin_[c];
  order_.resize(color_of.size());
  std::vector<int> next(begin_.begin(), begin_.end() - 1);
  for (std::size_t el = 0; el < color_of.size(); ++el)
    order_[next[color_of[el]]++] = static_cast<int>(el);
}

namespace detail {

void for_each_colored(const ElementColoring& coloring, ElementFn fn, const void* context) {
  const int nt = threads();
  const bool parallel = parallel_available() && nt > 1 && coloring.size() >= kMinParallelElements;
  for (int c = 0; c < coloring.num_colors(); ++c) {
    const std::span<const int> elements = coloring.color(c);
    const int n = static_cast<int>(elements.size());
    if (!parallel) {
      for (int i = 0; i < n; ++i) fn(context, elements[i]);
      continue;
    }
#ifdef _OPENMP
    // an exception must not leave the parallel region: keep the lowest element's
    std::exception_ptr error;
    int error_at = INT_MAX;
#pragma omp parallel for schedule(static) num_threads(nt)
    for (int i = 0; i < n; ++i) {
      try {
        fn(context, elements[i]);
      } catch (...) {
#pragma omp critical(seaflex_for_each_colored)
        if (i < error_at) {
          error_at = i;
          error = std::current_exception();
        }
      }
    }
    if (error) std::rethrow_exception(error);
#endif
  }
}

}  // namespace detail

}  // namespace seaflex
