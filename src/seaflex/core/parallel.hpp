// Thread count of the element loops, and a deterministic parallel loop over colored
// elements.
//
// Determinism: elements that share a node add into the same entries of Q and of the
// system matrix, and floating-point addition is not associative, so a parallel loop must
// not let the thread count decide the order of those additions. The elements are split
// into colors such that no two elements of one color share a coordinate (a beam chain:
// even and odd elements; a plate mesh: 4 colors by (i mod 2, j mod 2)). The colors run one
// after the other; within a color the elements run in parallel and write disjoint entries.
// Every entry therefore receives its contributions in the same order (color by color)
// whatever the number of threads, and the results are bit-identical for 1, 2, 3, ...
// threads and for a build without OpenMP. The serial path (one thread, or fewer than
// kMinParallelElements elements) walks the same color order.
//
// Chosen over "compute per-element results into buffers in parallel, scatter serially":
// coloring needs no per-element buffers (1.2 kB per beam element, 18 kB per plate element
// for the tangent), has no serial scatter phase, and keeps assembly reentrant (the
// kernels' scratch lives on each thread's stack). See docs/performance.md.
#pragma once

#include <span>
#include <vector>

namespace seaflex {

/// Sets the number of threads of the element loops (>= 1). Throws std::invalid_argument
/// for n < 1. In a build without OpenMP the value is accepted and threads() stays 1.
/// Global to the process; do not call while an evaluation runs.
void set_threads(int n);
/// Threads of the element loops: the last set_threads(), else OMP_NUM_THREADS when that
/// environment variable is set (OpenMP's own reading of it), else 1.
int threads();
/// True when seaflex was built with OpenMP.
bool parallel_available();

/// Bodies or forces with fewer elements than this run serially (thread start-up would
/// cost more than it saves). The order of additions is the same either way.
inline constexpr int kMinParallelElements = 64;

/// Elements grouped by color; no two elements of one color may share a coordinate.
class ElementColoring {
 public:
  ElementColoring() = default;
  /// color_of[el] in 0..k-1; within a color the elements keep their index order.
  explicit ElementColoring(std::span<const int> color_of);

  int size() const { return static_cast<int>(order_.size()); }
  int num_colors() const { return static_cast<int>(begin_.size()) - 1; }
  /// The elements of color c, in increasing index order.
  std::span<const int> color(int c) const {
    return {order_.data() + begin_[c], static_cast<std::size_t>(begin_[c + 1] - begin_[c])};
  }

 private:
  std::vector<int> order_;        // elements, color by color
  std::vector<int> begin_ = {0};  // color c: order_[begin_[c] .. begin_[c + 1])
};

namespace detail {
using ElementFn = void (*)(const void* context, int element);
void for_each_colored(const ElementColoring& coloring, ElementFn fn, const void* context);
}  // namespace detail

/// Calls body(element) for every element, color after color; the elements of one color in
/// parallel (OpenMP, static schedule) when threads() > 1 and coloring.size() >=
/// kMinParallelElements. body must only write entries that belong to its element's
/// coordinates and keep its scratch local. An exception thrown by body is rethrown after
/// the color finishes (the one of the lowest-numbered element in the color).
template <class Body>
void for_each_colored(const ElementColoring& coloring, const Body& body) {
  detail::for_each_colored(
      coloring, [](const void* context, int el) { (*static_cast<const Body*>(context))(el); },
      &body);
}

}  // namespace seaflex
