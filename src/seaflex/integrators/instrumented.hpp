// Evaluations, factorizations and solves that count themselves and their wall time into
// IntegratorStats (the split that `seaflex bench` prints). Shared by the integrators.
#pragma once

#include <chrono>

#include "seaflex/integrators/integrator.hpp"
#include "seaflex/solvers/kkt_solver.hpp"

namespace seaflex::instrumented {

using Clock = std::chrono::steady_clock;

inline double since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

inline void evaluate(const Dae& dae, const State& state, const DaeRequest& request, DaeEval& eval,
                     IntegratorStats& stats) {
  const auto t0 = Clock::now();
  dae.evaluate(state, request, eval);
  ++stats.evaluations;
  stats.assembly_s += since(t0);
}

inline bool factorize(KktSolver& solver, const SpMat& A, IntegratorStats& stats) {
  const auto t0 = Clock::now();
  const bool ok = solver.factorize(A);
  ++stats.factorizations;
  stats.factorize_s += since(t0);
  return ok;
}

inline void solve(const KktSolver& solver, const VecX& b, VecX& x, IntegratorStats& stats) {
  const auto t0 = Clock::now();
  solver.solve(b, x);
  ++stats.solves;
  stats.solve_s += since(t0);
}

}  // namespace seaflex::instrumented
