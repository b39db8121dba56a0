// Static equilibrium: Newton-Raphson on the full nonlinear system
//   Q(q; lambda_load) - C_q^T mu = 0,   C(q) = 0
// with the exact tangent (kq = 1 in the KKT matrix), incremental load stepping
// (the load factor scales external loads and gravity), and, when an increment fails,
// a retry with an energy line search (Crisfield 1991, sec. 9.3) before the increment is
// halved. The thesis could not compute statics (section 4.2); this is seaflex's.
#pragma once

#include <functional>
#include <string>

#include "seaflex/solvers/kkt_solver.hpp"
#include "seaflex/solvers/stability.hpp"
#include "seaflex/system/dae.hpp"

namespace seaflex {

struct StaticsSettings {
  int load_steps = 1;           ///< initial number of equal load increments
  int max_iterations = 50;      ///< Newton iterations per increment
  double tolerance = 1e-8;      ///< residual relative to the largest force term
  double min_increment = 1e-4;  ///< smallest load increment before giving up
  double time = 0.0;            ///< time at which time-varying loads are evaluated
  bool line_search = true;      ///< retry a failed increment with the energy line search
  LinearSolverKind linear_solver = kDefaultLinearSolver;  ///< backend of the Newton solves
};

/// Which test ended the last increment's Newton iterations.
enum class StaticsCriterion {
  kResidual,  ///< force residual <= tolerance x the largest force term, |C| <= 1e-10 L
  kRoundOff,  ///< Newton update <= 1e-13 L with |C| <= 1e-10 L: the residual is at its
              ///< round-off floor (e.g. a structure whose forces are all round-off)
};

struct StaticsReport {
  int increments = 0;                                        ///< load increments taken
  int iterations = 0;                                        ///< Newton iterations in all
  double residual = 0.0;                                     ///< final relative force residual
  double constraint_violation = 0.0;                         ///< final max |C|
  StaticsCriterion criterion = StaticsCriterion::kResidual;  ///< of the last increment
  double tolerance = 0.0;                                    ///< settings.tolerance, for the report
  double force_scale = 0.0;   ///< the largest force term at the end (N)
  double update = 0.0;        ///< largest coordinate change of the last iteration (m)
  double length_scale = 1.0;  ///< L = max(1 m, |q|_inf) (m)
  /// the equilibrium's directions of negative stiffness (solvers/stability.hpp): a Newton
  /// solution may be an unstable one (a line folded by a poor first guess, a column far
  /// beyond its buckling load)
  StabilityReport stability;
};

/// One line on how statics converged: the criterion met and its numbers, e.g.
/// "relative residual 3.1e-12 <= tolerance 1e-08 (of the largest force, 1.2e+04 N),
/// constraint violation 2.0e-15 m".
std::string describe_convergence(const StaticsReport& report);

/// Called after each converged increment: (load factor, iterations of the increment, the
/// report so far, whose residual and criterion are those of the increment).
using StaticsProgress = std::function<void(double, int, const StaticsReport&)>;

/// Solves for equilibrium starting from state (q, lambda used as the initial guess).
/// On success the state holds q, v = 0 and the multipliers. Throws SolverError, naming
/// the load factor, residual and worst coordinate, when it cannot converge; the state
/// then holds the last converged increment.
StaticsReport solve_statics(const Dae& dae, State& state, const StaticsSettings& settings,
                            const StaticsProgress& progress = {});

}  // namespace seaflex
