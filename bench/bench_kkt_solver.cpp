// The sparse KKT backends of KktSolver (SparseLU, KLU, UMFPACK) on the Newton matrix of
// an implicit step, [km M - kq dQ/dq - kv dQ/dv, C_q^T; C_q, 0] with km = 1, kq = 1e-4,
// kv = 1e-2, of the standard benchmark riser bench/riser/riser_n<N>.yaml (300 m, pinned at
// the seabed, top fixed in x and y, 3 m/s current with Morison drag, inertia and added
// mass, gravity and buoyancy), N = 10, 100, 1000 ANCF elements, evaluated at its static
// equilibrium (bowed in the current; solve_statics before any timing). The
// state matters: at the straight initial state many entries of the fixed pattern are exact
// zeros, which UMFPACK drops from its factors and KLU and SparseLU keep. The riser bends in
// the x-z plane only, so the y couplings stay exact zeros at equilibrium too.
// Three benchmarks per backend and N:
//   BM_KktAnalyze/<backend>/N    the symbolic analysis (ordering) alone
//   BM_KktFactorize/<backend>/N  one numeric factorization (analysis done before the loop)
//   BM_KktSolve/<backend>/N      one forward/back substitution with the factors
// Results: docs/performance.md, "Sparse KKT backends".
#include <benchmark/benchmark.h>

#include <fmt/format.h>

#include <array>
#include <exception>
#include <map>
#include <string>
#include <utility>

#include "seaflex/io/model_loader.hpp"
#include "seaflex/solvers/kkt_solver.hpp"
#include "seaflex/solvers/statics.hpp"

namespace {

using seaflex::KktSolver;
using seaflex::LinearSolverKind;

constexpr std::array<LinearSolverKind, 3> kKinds{
    LinearSolverKind::kSparseLU, LinearSolverKind::kKlu, LinearSolverKind::kUmfpack};
constexpr std::array<int, 3> kElements{10, 100, 1000};

struct KktProblem {
  seaflex::SpMat A;
  seaflex::VecX b;
};

// The KKT matrix and a right-hand side [Q; -C], built once per N.
const KktProblem& problem(int elements) {
  static std::map<int, KktProblem> cache;
  auto it = cache.find(elements);
  if (it != cache.end()) return it->second;
  // the standard riser benchmark (bench/riser/riser_n<N>.yaml)
  const seaflex::io::Model model = seaflex::io::load_model_file(
      fmt::format("{}/bench/riser/riser_n{}.yaml", SEAFLEX_SOURCE_DIR, elements));
  const seaflex::System& system = *model.system;
  seaflex::State state = system.initial_state();
  seaflex::solve_statics(system, state, model.statics);  // throws when it fails
  seaflex::DaeEval eval = system.make_eval();
  seaflex::DaeRequest request;
  request.matrix = true;
  request.scales.km = 1.0;
  request.scales.kq = 1e-4;
  request.scales.kv = 1e-2;
  system.evaluate(state, request, eval);
  KktProblem p{eval.kkt.matrix(), seaflex::VecX::Zero(eval.kkt.matrix().rows())};
  p.A.makeCompressed();
  p.b.head(system.num_coordinates()) = eval.Q;
  p.b.tail(system.num_constraints()) = -eval.C;
  return cache.emplace(elements, std::move(p)).first->second;
}

// problem(), or nullptr (the benchmark skipped) when the model or statics fails.
const KktProblem* problem_or_skip(benchmark::State& st, int elements) {
  try {
    return &problem(elements);
  } catch (const std::exception& e) {
    st.SkipWithError(e.what());
    return nullptr;
  }
}

void add_counters(benchmark::State& st, const KktProblem& p, int elements) {
  st.SetComplexityN(elements);
  st.counters["rows"] = static_cast<double>(p.A.rows());
  st.counters["nonzeros"] = static_cast<double>(p.A.nonZeros());
}

void analyze(benchmark::State& st, LinearSolverKind kind, int elements) {
  const KktProblem* pp = problem_or_skip(st, elements);
  if (pp == nullptr) return;
  const KktProblem& p = *pp;
  KktSolver solver(kind);
  for (auto _ : st) {
    if (!solver.analyze(p.A)) {
      st.SkipWithError(solver.message().c_str());
      break;
    }
  }
  add_counters(st, p, elements);
}

void factorize(benchmark::State& st, LinearSolverKind kind, int elements) {
  const KktProblem* pp = problem_or_skip(st, elements);
  if (pp == nullptr) return;
  const KktProblem& p = *pp;
  KktSolver solver(kind);
  if (!solver.analyze(p.A)) {
    st.SkipWithError(solver.message().c_str());
    return;
  }
  for (auto _ : st) {
    if (!solver.factorize(p.A)) {
      st.SkipWithError(solver.message().c_str());
      break;
    }
  }
  add_counters(st, p, elements);
}

void solve(benchmark::State& st, LinearSolverKind kind, int elements) {
  const KktProblem* pp = problem_or_skip(st, elements);
  if (pp == nullptr) return;
  const KktProblem& p = *pp;
  KktSolver solver(kind);
  if (!solver.factorize(p.A)) {
    st.SkipWithError(solver.message().c_str());
    return;
  }
  seaflex::VecX x(p.b.size());
  for (auto _ : st) {
    solver.solve(p.b, x);
    benchmark::DoNotOptimize(x.data());
  }
  const double residual = (p.A * x - p.b).norm() / p.b.norm();
  st.counters["residual"] = residual;
  add_counters(st, p, elements);
}

// Names like BM_KktFactorize/klu/1000, grouped by operation, then backend.
[[maybe_unused]] const bool kRegistered = [] {
  using Fn = void (*)(benchmark::State&, LinearSolverKind, int);
  const std::array<std::pair<const char*, Fn>, 3> operations{{
      {"BM_KktAnalyze", analyze},
      {"BM_KktFactorize", factorize},
      {"BM_KktSolve", solve},
  }};
  for (const auto& [name, fn] : operations) {
    for (const LinearSolverKind kind : kKinds) {
      for (const int n : kElements) {
        const std::string full = fmt::format("{}/{}/{}", name, KktSolver::to_string(kind), n);
        benchmark::RegisterBenchmark(full.c_str(), fn, kind, n)->Unit(benchmark::kMicrosecond);
      }
    }
  }
  return true;
}();

}  // namespace
