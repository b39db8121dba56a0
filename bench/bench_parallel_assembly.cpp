// Cost of one full assembly (Q and the Newton matrix km M - kq dQ/dq - kv dQ/dv, scales
// 1, 0.3, 0.7: what a Newton iteration of an implicit integrator asks) and of one
// forces-only evaluation (an RK4 stage), for the riser of examples/riser_in_current.yaml
// meshed with 1000 elements (Morison loads in current and waves, t = 20 s within the
// wave ramp) and for a 32 x 32 plate, on 1 and 2 threads (core/parallel.hpp). The
// results are bit-identical for any thread count; only the time changes.
#include <benchmark/benchmark.h>

#include <fmt/format.h>

#include <cmath>
#include <string>

#include "seaflex/core/parallel.hpp"
#include "seaflex/io/model_loader.hpp"

namespace {

seaflex::io::Model riser(int elements) {
  const std::string yaml = fmt::format(R"(title: benchmark riser in current and waves
environment:
  gravity: 9.81
  water: {{density: 1025, depth: 300}}
  current: {{speed: 3.0, direction: 0}}
  waves: {{type: airy, height: 3.0, period: 10.5, direction: 0, ramp: {{start: 5, duration: 30}}}}
bodies:
  riser:
    type: ancf_beam
    start: [0, 0, -300]
    end: [0, 0, 10]
    elements: {}
    outer_diameter: 0.7
    inner_diameter: 0.4
    youngs_modulus: 210e9
    density: 7850
hydrodynamics:
  riser: {{cd: 0.65, cm: 1.6}}
supports:
  - {{body: riser, node: start, type: pinned}}
  - {{body: riser, node: end, type: fixed, fix: [x, y]}}
)",
                                       elements);
  return seaflex::io::load_model_text(yaml, fmt::format("bench_riser_{}", elements));
}

seaflex::io::Model plate(int n) {
  const std::string yaml = fmt::format(R"(title: benchmark plate
environment:
  gravity: 9.81
bodies:
  plate:
    type: ancf_plate
    corner: [0, 0, 0]
    edge1: [10, 0, 0]
    edge2: [0, 10, 0]
    elements: [{0}, {0}]
    thickness: 0.1
    youngs_modulus: 210e9
    poisson_ratio: 0.3
    density: 7950
)",
                                       n);
  return seaflex::io::load_model_text(yaml, fmt::format("bench_plate_{}", n));
}

// every coordinate moved by about 1e-3, velocities of 0.2 m/s, t = 20 s
seaflex::State perturbed(const seaflex::System& system) {
  seaflex::State s = system.initial_state();
  for (seaflex::Index i = 0; i < s.q.size(); ++i) {
    s.q[i] += 1e-3 * std::sin(0.7 * static_cast<double>(i));
    s.v[i] = 0.2 * std::cos(1.3 * static_cast<double>(i));
  }
  s.t = 20.0;
  return s;
}

void run(benchmark::State& st, const seaflex::io::Model& model, bool matrix) {
  const int threads = static_cast<int>(st.range(1));
  seaflex::set_threads(threads);
  const seaflex::System& system = *model.system;
  const seaflex::State state = perturbed(system);
  seaflex::DaeEval eval = system.make_eval();
  seaflex::DaeRequest request;
  request.constraints = false;
  request.matrix = matrix;
  request.scales = {1.0, 0.3, 0.7};
  for (auto _ : st) {
    system.evaluate(state, request, eval);
    benchmark::DoNotOptimize(eval.Q.data());
    benchmark::DoNotOptimize(eval.kkt.matrix().valuePtr());
  }
  st.counters["threads"] = seaflex::threads();
  seaflex::set_threads(1);
}

void BM_RiserAssembly(benchmark::State& st) {
  run(st, riser(static_cast<int>(st.range(0))), true);
}
BENCHMARK(BM_RiserAssembly)
    ->ArgNames({"N", "threads"})
    ->Args({1000, 1})
    ->Args({1000, 2})
    ->UseRealTime()
    ->Unit(benchmark::kMicrosecond);

void BM_RiserForces(benchmark::State& st) {
  run(st, riser(static_cast<int>(st.range(0))), false);
}
BENCHMARK(BM_RiserForces)
    ->ArgNames({"N", "threads"})
    ->Args({1000, 1})
    ->Args({1000, 2})
    ->UseRealTime()
    ->Unit(benchmark::kMicrosecond);

void BM_PlateAssembly(benchmark::State& st) {
  run(st, plate(static_cast<int>(st.range(0))), true);
}
BENCHMARK(BM_PlateAssembly)
    ->ArgNames({"n", "threads"})
    ->Args({32, 1})
    ->Args({32, 2})
    ->UseRealTime()
    ->Unit(benchmark::kMicrosecond);

}  // namespace
