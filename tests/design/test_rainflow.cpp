// Rainflow counting (post/rainflow.hpp) against ASTM E1049-85 (reapproved 2017), the
// example of section 5.4.4: load history Fig. 6 (a), counted in Table 4.
#include <gtest/gtest.h>

#include <map>
#include <random>

#include "seaflex/post/rainflow.hpp"

namespace seaflex::post {
namespace {

std::map<double, double> histogram(const std::vector<RainflowCycle>& cycles) {
  std::map<double, double> h;
  for (const auto& c : cycles) h[c.range] += c.count;
  return h;
}

// ASTM E1049-85 Fig. 6 history and Table 4 (rainflow counting): range (units) -> cycles.
// The ranges are whole numbers, the counts multiples of 0.5: equality is exact.
TEST(Rainflow, AstmE1049Example) {
  const std::vector<double> history = {-2, 1, -3, 5, -1, 3, -4, 4, -2};
  const auto h = histogram(rainflow(history));
  const std::map<double, double> table4 = {{3, 0.5}, {4, 1.5}, {6, 0.5}, {8, 1.0}, {9, 0.5}};
  EXPECT_EQ(h, table4);
}

// The same history sampled with intermediate points and plateaus: only reversals count.
TEST(Rainflow, IntermediatePointsAndPlateausAreNoReversals) {
  const std::vector<double> history = {-2, -1, 0,   1,  1,  1, -3, -3, 0,  2, 5,
                                       -1, 3,  2.5, -4, -4, 0, 4,  4,  -2, -2};
  const auto h = histogram(rainflow(history));
  const std::map<double, double> table4 = {{3, 0.5}, {4, 1.5}, {6, 0.5}, {8, 1.0}, {9, 0.5}};
  EXPECT_EQ(h, table4);
}

// Cycle means: the counted cycle (-1, 3) of the example has mean 1; the half cycle (-4, 5)
// has mean 0.5.
TEST(Rainflow, CycleMeans) {
  const std::vector<double> history = {-2, 1, -3, 5, -1, 3, -4, 4, -2};
  bool full = false, nine = false;
  for (const auto& c : rainflow(history)) {
    if (c.count == 1.0 && c.range == 4.0) full = c.mean == 1.0;
    if (c.range == 9.0) nine = c.mean == 0.5 && c.count == 0.5;
  }
  EXPECT_TRUE(full);
  EXPECT_TRUE(nine);
}

// Counting is conservative: the sum of counted ranges times two (full) or one (half)
// equals the total variation of the history (each reversal-to-reversal excursion is in
// exactly one cycle, ASTM E1049 5.4.4). A random walk of 100 000 samples, fixed seed.
// The stack stays small (the residue): its bound is asserted loosely (< 200).
TEST(Rainflow, RangesAccountForTheWholeVariation) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> n01;
  std::vector<double> x(100000);
  double v = 0.0;
  for (auto& xi : x) xi = v = 0.9 * v + n01(rng);
  double variation = 0.0;
  for (std::size_t i = 1; i < x.size(); ++i) variation += std::abs(x[i] - x[i - 1]);
  RainflowCounter counter;
  double counted = 0.0;
  std::size_t max_stack = 0;
  const auto sink = [&](const RainflowCycle& c) { counted += 2.0 * c.count * c.range; };
  for (double xi : x) {
    counter.add(xi, sink);
    max_stack = std::max(max_stack, counter.stack_size());
  }
  counter.finish(sink);
  EXPECT_NEAR(counted, variation, 1e-9 * variation);
  EXPECT_LT(max_stack, 200u);
}

}  // namespace
}  // namespace seaflex::post
