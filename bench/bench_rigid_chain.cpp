// Cost of one Rk4Augmented::step for a chain of N rigid bodies on ball joints (a
// hanging spatial N-pendulum: 7N coordinates, 4N constraint rows), N = 8, 64, 512.
// Unlike the cantilever, the augmented matrix changes with the state (Euler-parameter
// mass matrix, nonlinear joints), so every RK4 stage refactors it: the figures show that
// the sparse factorization keeps the step linear in N.
#include <benchmark/benchmark.h>

#include <fmt/format.h>

#include <memory>

#include "seaflex/constraints/joint.hpp"
#include "seaflex/elements/rigid_body.hpp"
#include "seaflex/forces/gravity.hpp"
#include "seaflex/integrators/rk4_augmented.hpp"
#include "seaflex/system/system.hpp"

namespace {

// links 1 m long along -z with a small tilt, 10 kg, rod-like inertia
std::unique_ptr<seaflex::System> chain(int n) {
  using namespace seaflex;
  auto sys = std::make_unique<System>();
  std::vector<const RigidBody*> links;
  const Mat3 inertia = Vec3(0.85, 0.85, 0.02).asDiagonal();
  for (int i = 0; i < n; ++i) {
    RigidBodyInitial init;
    init.position = Vec3(0.01 * i, 0.0, -0.5 - i);
    init.angular_velocity = Vec3(0.1, 0.05 * (i % 3), 0.0);
    links.push_back(static_cast<const RigidBody*>(&sys->add_body(
        std::make_unique<RigidBody>(fmt::format("link{}", i), 10.0, inertia, init))));
  }
  for (int i = 0; i < n; ++i) {
    std::unique_ptr<Marker> from =
        i == 0 ? std::unique_ptr<Marker>(std::make_unique<GroundMarker>(Vec3(0.0, 0.0, 0.0)))
               : std::make_unique<RigidBodyMarker>(*links[i - 1], Vec3(0.0, 0.0, -0.5));
    // joint points placed where the links meet at the start (x offsets of 0.01 m per link)
    auto to = std::make_unique<RigidBodyMarker>(*links[i], Vec3(i == 0 ? 0.0 : -0.01, 0.0, 0.5));
    sys->add_constraint(std::make_unique<Joint>(fmt::format("j{}", i), JointType::kBall,
                                                std::move(from), std::move(to)));
  }
  std::vector<const Body*> bodies(links.begin(), links.end());
  sys->add_force(std::make_unique<Gravity>(Vec3(0, 0, -9.81), bodies));
  sys->finalize();
  return sys;
}

void BM_Rk4StepRigidChain(benchmark::State& st) {
  const int n = static_cast<int>(st.range(0));
  const auto system = chain(n);
  seaflex::State state = system->initial_state();
  seaflex::Rk4Augmented rk4;
  if (!rk4.step(*system, state, 1e-4).ok) {  // warm-up: sizes buffers, analyzes the pattern
    st.SkipWithError("warm-up step failed");
    return;
  }
  for (auto _ : st) {
    seaflex::StepReport report = rk4.step(*system, state, 1e-4);
    benchmark::DoNotOptimize(report);
    benchmark::DoNotOptimize(state.q.data());
  }
  if (!state.q.allFinite()) st.SkipWithError("state not finite");
  st.SetComplexityN(n);
  st.counters["per_body"] = benchmark::Counter(
      n, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_Rk4StepRigidChain)->Arg(8)->Arg(64)->Arg(512)->Complexity(benchmark::oN);

}  // namespace
