#include "seaflex/post/rainflow.hpp"

namespace seaflex::post {

std::vector<RainflowCycle> rainflow(std::span<const double> history) {
  std::vector<RainflowCycle> cycles;
  RainflowCounter counter;
  const auto sink = [&](const RainflowCycle& c) { cycles.push_back(c); };
  for (double x : history) counter.add(x, sink);
  counter.finish(sink);
  return cycles;
}

}  // namespace seaflex::post
