// Cost of one Rk4Augmented::step (projection stabilization, the default) and of one
// Newton statics solve (solve_statics) for the clamped 10 m steel cantilever of
// examples/cantilever.yaml under gravity, meshed with N = 10, 100, 1000 elements and
// loaded through io::load_model_text. The model and state are built once per run,
// outside the timed loop. Two parts of a step are also timed on their own to explain
// its cost: one System::evaluate of forces and constraints (what each RK4 stage does
// before its solve) and one solve with the factored KKT matrix.
#include <benchmark/benchmark.h>

#include <fmt/format.h>

#include <exception>
#include <string>

#include "seaflex/integrators/rk4_augmented.hpp"
#include "seaflex/io/model_loader.hpp"
#include "seaflex/solvers/kkt_solver.hpp"
#include "seaflex/solvers/statics.hpp"

namespace {

// The step only has to keep the state finite. The highest ANCF bending frequency grows
// as 1/l^2: RK4 is stable below about 5.7e-5 s at N = 10 (examples/cantilever.yaml),
// hence about 5.6e-9 s at N = 1000, where 1e-7 s overflows to NaN within the timed loop.
constexpr double kTimeStep = 1e-9;  // s

seaflex::io::Model cantilever(int elements) {
  const std::string yaml = fmt::format(R"(title: benchmark cantilever
environment:
  gravity: 9.81
bodies:
  beam:
    type: ancf_beam
    start: [0, 0, 0]
    end: [10, 0, 0]
    elements: {}
    area: 0.01
    second_moment: 8.33e-6
    youngs_modulus: 210e9
    density: 7850
supports:
  - body: beam
    node: start
    type: clamped
statics:
  load_steps: 1
)",
                                       elements);
  return seaflex::io::load_model_text(yaml, fmt::format("bench_cantilever_{}", elements));
}

// Time per iteration divided by N, reported as the counter "per_element" (s).
void report_per_element(benchmark::State& st, int elements) {
  st.SetComplexityN(elements);
  st.counters["per_element"] = benchmark::Counter(
      elements, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void BM_Rk4Step(benchmark::State& st) {
  const int n = static_cast<int>(st.range(0));
  const seaflex::io::Model model = cantilever(n);
  const seaflex::System& system = *model.system;
  seaflex::State state = system.initial_state();
  seaflex::Rk4Augmented rk4;
  // Warm-up step, not timed: it sizes the work vectors and factors the KKT matrix
  // [M C_q^T; C_q 0], which is constant for this model and reused by every later step
  // (the counter "factorizations" stays 1). The loop measures the steady-state step.
  if (!rk4.step(system, state, kTimeStep).ok) {
    st.SkipWithError("warm-up step failed");
    return;
  }
  for (auto _ : st) {
    seaflex::StepReport report = rk4.step(system, state, kTimeStep);
    benchmark::DoNotOptimize(report);
    benchmark::DoNotOptimize(state.q.data());
  }
  if (!state.q.allFinite() || !state.v.allFinite()) st.SkipWithError("state not finite");
  report_per_element(st, n);
  st.counters["factorizations"] = rk4.factorizations();
}
BENCHMARK(BM_Rk4Step)->Arg(10)->Arg(100)->Arg(1000)->Complexity(benchmark::oN);

// One evaluation of Q, C, Cdot and gamma, as in Rk4Augmented::accelerations.
void BM_Rk4Part_Evaluate(benchmark::State& st) {
  const int n = static_cast<int>(st.range(0));
  const seaflex::io::Model model = cantilever(n);
  const seaflex::System& system = *model.system;
  const seaflex::State state = system.initial_state();
  seaflex::DaeEval eval = system.make_eval();
  seaflex::DaeRequest request;  // forces and constraints, no matrix
  for (auto _ : st) {
    system.evaluate(state, request, eval);
    benchmark::DoNotOptimize(eval.Q.data());
  }
  report_per_element(st, n);
}
BENCHMARK(BM_Rk4Part_Evaluate)->Arg(10)->Arg(100)->Arg(1000)->Complexity(benchmark::oN);

// One forward/back substitution with the factored KKT matrix (km = 1, kq = kv = 0), as
// in every RK4 stage and in the velocity projection.
void BM_Rk4Part_KktSolve(benchmark::State& st) {
  const int n = static_cast<int>(st.range(0));
  const seaflex::io::Model model = cantilever(n);
  const seaflex::System& system = *model.system;
  const seaflex::State state = system.initial_state();
  seaflex::DaeEval eval = system.make_eval();
  seaflex::DaeRequest request;
  request.matrix = true;
  request.scales.km = 1.0;
  system.evaluate(state, request, eval);
  seaflex::KktSolver solver;
  if (!solver.factorize(eval.kkt.matrix())) {
    st.SkipWithError("KKT matrix singular");
    return;
  }
  seaflex::VecX rhs = seaflex::VecX::Zero(system.num_coordinates() + system.num_constraints());
  rhs.head(system.num_coordinates()) = eval.Q;
  seaflex::VecX x(rhs.size());
  for (auto _ : st) {
    solver.solve(rhs, x);
    benchmark::DoNotOptimize(x.data());
  }
  report_per_element(st, n);
}
BENCHMARK(BM_Rk4Part_KktSolve)->Arg(10)->Arg(100)->Arg(1000)->Complexity(benchmark::oN);

// A full Newton statics solve from the straight, unloaded beam (settings of the YAML
// above: one load step, tolerance 1e-8); the state copy is not timed.
void BM_Statics(benchmark::State& st) {
  const int n = static_cast<int>(st.range(0));
  const seaflex::io::Model model = cantilever(n);
  const seaflex::State initial = model.system->initial_state();
  seaflex::State state;
  seaflex::StaticsReport report;
  for (auto _ : st) {
    st.PauseTiming();
    state = initial;
    st.ResumeTiming();
    try {
      report = seaflex::solve_statics(*model.system, state, model.statics);
    } catch (const std::exception& e) {
      st.SkipWithError(e.what());
      break;
    }
    benchmark::DoNotOptimize(state.q.data());
  }
  report_per_element(st, n);
  st.counters["newton_iterations"] = report.iterations;
  st.counters["residual"] = report.residual;
}
BENCHMARK(BM_Statics)
    ->Arg(10)
    ->Arg(100)
    ->Arg(1000)
    ->Complexity(benchmark::oN)
    ->Unit(benchmark::kMillisecond);

}  // namespace
