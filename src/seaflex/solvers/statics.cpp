#include "seaflex/solvers/statics.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "seaflex/core/errors.hpp"
#include "seaflex/core/interrupt.hpp"
#include "seaflex/solvers/kkt_solver.hpp"

namespace seaflex {

namespace {

struct Residual {
  double force = 0.0;       // ||Q - C_q^T mu||_inf / scale
  double constraint = 0.0;  // ||C||_inf
  Index worst = 0;          // coordinate of the largest force residual
  bool finite = true;
};

class NewtonStatics {
 public:
  NewtonStatics(const Dae& dae, const StaticsSettings& settings)
      : dae_(dae),
        s_(settings),
        eval_(dae.make_eval()),
        solver_(settings.linear_solver),
        n_(dae.num_coordinates()),
        m_(dae.num_constraints()) {
    rhs_.resize(n_ + m_);
  }

  // residual r = Q - C_q^T mu and the Newton matrix at the state (C_q^T mu is read off
  // the KKT matrix, whose off-diagonal blocks hold C_q)
  Residual residual(const State& state, double load_factor) {
    DaeRequest req;
    req.matrix = true;
    req.scales.kq = 1.0;
    req.multiplier_hessian = true;
    req.load_factor = load_factor;
    try {
      dae_.evaluate(state, req, eval_);
    } catch (const SolverError& e) {
      // an element cannot be evaluated at this trial state (a spring's ends met): treat it
      // as a non-finite residual, so the step is cut or the increment halved
      failure_ = e.what();
      Residual res;
      res.finite = false;
      return res;
    }
    VecX lam_full = VecX::Zero(n_ + m_);
    lam_full.tail(m_) = state.lambda;
    const VecX CqT_mu = (eval_.kkt.matrix() * lam_full).head(n_);
    r_ = eval_.Q - CqT_mu;
    Residual res;
    const double scale =
        std::max({eval_.Q.lpNorm<Eigen::Infinity>(), CqT_mu.lpNorm<Eigen::Infinity>(), 1e-12});
    res.force = r_.lpNorm<Eigen::Infinity>() / scale;
    force_scale_ = scale;
    res.constraint = m_ > 0 ? eval_.C.lpNorm<Eigen::Infinity>() : 0.0;
    res.finite = r_.allFinite() && eval_.C.allFinite();
    r_.cwiseAbs().maxCoeff(&res.worst);
    return res;
  }

  // Newton iterations at a fixed load factor; true on convergence. Converged when the
  // force residual is below the tolerance relative to the largest force term, or when the
  // Newton update is at round-off level (then the residual is at its noise floor, e.g. an
  // unloaded structure whose forces are all round-off), with the constraints satisfied.
  bool solve(State& state, double load_factor, bool line_search, int& iterations, Residual& res) {
    failure_.clear();
    driven_ = 0;
    const double q_scale = std::max(1.0, state.q.lpNorm<Eigen::Infinity>());
    q_scale_ = q_scale;
    const double c_tol = 1e-10 * q_scale;
    res = residual(state, load_factor);
    criterion_ = StaticsCriterion::kResidual;
    update_ = 0.0;
    last_fall_ = 0.0;
    for (int it = 0; it < s_.max_iterations; ++it) {
      if (!res.finite || interrupt_signal() != 0) return false;  // a signal: see solve_statics
      if (res.force <= s_.tolerance && res.constraint <= c_tol) return true;
      // Levenberg-Marquardt-style regularization of the Newton matrix only (the residual,
      // hence the equilibrium, is untouched): K_ii += eps = 1e-6 F / L (F the largest
      // force, L the model's size): below 1e-6 of any stiffness whose deflection under the
      // loads is smaller than the model, and large enough that the round-off residual
      // (1e-16 F) moves a free mode by no more than 1e-10 L. (A scaling by K_ii would
      // stiffen bending modes, whose coordinates also carry EA/l.) No term in max |K_jj|:
      // a beam's largest diagonal is 12 EI / l^3, which grows as N^3 with the number of
      // elements; 1e-14 of it, added to every node, outweighed the stiffness of a riser's
      // tensioned-string mode per node (~ T pi^2 / (L N)) at 10,000 elements of 3 cm, and
      // statics then stopped as "a mode that the loads drive" (issue 22).
      // A mode without stiffness that no force drives (a free spin about a hanging line, a
      // rigid body about a beam's axis, which carries no torsion) then does not move,
      // instead of taking a step of round-off over a round-off pivot.
      regularize();
      if (!solver_.factorize(eval_.kkt.matrix())) {
        failure_ = fmt::format(
            "the tangent matrix is singular ({}): a mechanism, a body without "
            "supports, or coordinates without stiffness",
            solver_.message());
        return false;
      }
      rhs_.head(n_) = r_;
      rhs_.tail(m_) = -eval_.C;
      solver_.solve(rhs_, dx_);
      if (!dx_.allFinite()) {
        failure_ = "the Newton update is not finite: the tangent matrix is nearly singular";
        return false;
      }
      ++iterations;
      {
        // share of the step's work dq . r that the regularization does: below 1e-10 for a
        // well-posed step; near 1 when a load drives a mode that only the regularization
        // holds (an undriven free mode does not move and does no work). A hanging line
        // gains its pendulum stiffness from its tension after the first steps, so only a
        // mode that stays without stiffness for three iterations is a mechanism.
        const double reg_work = eps_ * dx_.head(n_).squaredNorm();
        const double work = std::abs(dx_.head(n_).dot(r_));
        // (with the forces already balanced, only C is being closed: nothing is driven)
        const bool held = res.force > s_.tolerance && reg_work > 0.5 * work && reg_work > 0.0;
        driven_ = held ? driven_ + 1 : 0;
        if (driven_ >= 3) {
          Index worst = 0;
          dx_.head(n_).cwiseAbs().maxCoeff(&worst);
          failure_ = fmt::format(
              "the tangent matrix is singular in a mode that the loads drive (largest at "
              "{}): a mechanism, a body without supports, or coordinates without stiffness",
              dae_.coordinate_name(worst));
          return false;
        }
      }
      // trust region: no coordinate moves by more than a tenth of the model's size in one
      // iteration (a step held only by the regularization would be astronomical)
      {
        const double largest = dx_.head(n_).lpNorm<Eigen::Infinity>();
        if (largest > 0.1 * q_scale) dx_ *= 0.1 * q_scale / largest;
      }
      // attitude steps of rigid bodies are limited (a full Newton step can carry a body
      // onto the mirror branch of its joint conditions, e.g. upside down)
      dx_ *= dae_.step_scale(state, dx_.head(n_));
      const double update = dx_.head(n_).lpNorm<Eigen::Infinity>();
      update_ = update;
      start_ = state;
      const double g0 = dx_.head(n_).dot(r_);
      const double before = res.force;
      take_step(state, 1.0, load_factor, res);
      if (line_search) this->line_search(state, load_factor, g0, res);
      last_fall_ = res.finite && res.force > 0.0 ? before / res.force : 0.0;
      if (res.finite && res.force <= s_.tolerance && res.constraint <= c_tol) return true;
      if (res.finite && update <= 1e-13 * q_scale && res.constraint <= c_tol) {
        criterion_ = StaticsCriterion::kRoundOff;
        return true;
      }
    }
    return res.finite && res.force <= s_.tolerance && res.constraint <= c_tol;
  }

  // K_ii += eps on the coordinate block (see solve)
  void regularize() {
    SpMat& K = eval_.kkt.matrix();
    eps_ = 1e-6 * force_scale_ / std::max(1.0, q_scale_);
    for (Index c = 0; c < n_; ++c)
      for (SpMat::InnerIterator it(K, c); it; ++it)
        if (it.row() == c) it.valueRef() += eps_;
  }

  // Least-squares multipliers C_q^T mu ~ Q at the start, from [I C_q^T; C_q 0][x; mu] =
  // [Q; 0]: without them the first Newton matrix lacks the d(C_q^T mu)/dq stiffness that
  // holds a mode only gravity restrains through a joint (a hanging body's swing), and is
  // singular there.
  void estimate_multipliers(State& state, double load_factor) {
    DaeRequest req;
    req.matrix = true;
    req.scales = MatrixScales{0.0, 0.0, 0.0};
    req.load_factor = load_factor;
    dae_.evaluate(state, req, eval_);
    SpMat& K = eval_.kkt.matrix();
    for (Index c = 0; c < n_; ++c)
      for (SpMat::InnerIterator it(K, c); it; ++it)
        if (it.row() == c) it.valueRef() = 1.0;
    if (!solver_.factorize(K)) return;  // leave zero multipliers: Newton reports the problem
    rhs_.head(n_) = eval_.Q;
    rhs_.tail(m_).setZero();
    solver_.solve(rhs_, dx_);
    if (dx_.allFinite()) state.lambda = dx_.tail(m_);
  }

  void take_step(State& state, double alpha, double load_factor, Residual& res) {
    state.q = start_.q + alpha * dx_.head(n_);
    state.lambda = start_.lambda + alpha * dx_.tail(m_);
    res = residual(state, load_factor);
  }

  // Energy line search (Crisfield 1991, Non-linear Finite Element Analysis of Solids and
  // Structures, vol. 1, sec. 9.3): along the Newton direction dq, g(alpha) = dq . r(q +
  // alpha dq) is minus the derivative of the potential. The full step stands while the
  // potential still falls at alpha = 1 (g > 0) or has nearly stopped (|g| <= 0.8 g0);
  // after an overshoot the minimum is bracketed and found by regula falsi. A step to a
  // non-finite state is halved. (A residual-norm search stalls Newton at large rotations,
  // where full steps raise the residual on their way to convergence.)
  void line_search(State& state, double load_factor, double g0, Residual& res) {
    double alpha = 1.0;
    for (int k = 0; k < 8 && !res.finite; ++k) {
      alpha *= 0.5;
      take_step(state, alpha, load_factor, res);
    }
    if (!res.finite || !(g0 > 0.0)) return;
    double g = dx_.head(n_).dot(r_);
    if (g > 0.0 || std::abs(g) <= 0.8 * g0) return;
    double a_lo = 0.0, g_lo = g0, a_hi = alpha, g_hi = g;
    for (int k = 0; k < 6; ++k) {
      alpha = std::clamp(a_hi - g_hi * (a_hi - a_lo) / (g_hi - g_lo), 0.1 * a_hi, a_hi);
      take_step(state, alpha, load_factor, res);
      if (!res.finite) return;
      g = dx_.head(n_).dot(r_);
      if (std::abs(g) <= 0.8 * g0) return;
      if (g > 0.0) {
        a_lo = alpha;
        g_lo = g;
      } else {
        a_hi = alpha;
        g_hi = g;
      }
    }
  }

  const Dae& dae_;
  StaticsSettings s_;
  DaeEval eval_;
  KktSolver solver_;
  Index n_, m_;
  VecX r_, rhs_, dx_;
  State start_;
  std::string failure_;  // why the last solve failed, when it was not plain non-convergence
  StaticsCriterion criterion_ = StaticsCriterion::kResidual;  // what ended the last solve
  double update_ = 0.0;       // largest coordinate change of the last iteration (m)
  double last_fall_ = 0.0;    // residual before / after the last iteration (> 1: it fell)
  double eps_ = 0.0;          // the regularization of the last Newton matrix
  int driven_ = 0;            // consecutive iterations whose step only the regularization held
  double force_scale_ = 1.0;  // largest force term at the last residual (N)
  double q_scale_ = 1.0;      // size of the model (m)
};

}  // namespace

std::string describe_convergence(const StaticsReport& r) {
  if (r.criterion == StaticsCriterion::kRoundOff)
    return fmt::format(
        "Newton update {:.2e} m <= 1e-13 x the model size ({:.3g} m): the force residual, "
        "{:.2e} N, is at its round-off floor; constraint violation {:.2e}",
        r.update, r.length_scale, r.residual * r.force_scale, r.constraint_violation);
  return fmt::format(
      "relative residual {:.2e} <= tolerance {:.2e} (of the largest force term, {:.3g} N); "
      "constraint violation {:.2e}",
      r.residual, r.tolerance, r.force_scale, r.constraint_violation);
}

StaticsReport solve_statics(const Dae& dae, State& state, const StaticsSettings& settings,
                            const StaticsProgress& progress) {
  NewtonStatics newton(dae, settings);
  state.t = settings.time;
  state.v.setZero();
  if (state.lambda.size() != dae.num_constraints())
    state.lambda = VecX::Zero(dae.num_constraints());
  StaticsReport report;
  double factor = 0.0;
  double increment = 1.0 / std::max(1, settings.load_steps);
  if (dae.num_constraints() > 0 && state.lambda.isZero(0.0))
    newton.estimate_multipliers(state, increment);
  Residual res;
  while (factor < 1.0) {
    // SIGINT/SIGTERM (core/interrupt.hpp): stop at the last converged increment, in state
    if (const int sig = interrupt_signal(); sig != 0)
      throw Interrupted(
          sig, fmt::format("in statics after the increment to load factor {:.6g}", factor));
    const double target = std::min(1.0, factor + increment);
    const State saved = state;
    int iterations = 0;
    // plain Newton first (quadratic convergence); the line search only when that fails,
    // before the increment is cut: it is a safeguard, and it slows converging problems
    bool ok = newton.solve(state, target, false, iterations, res);
    if (!ok && settings.line_search) {
      state = saved;
      ok = newton.solve(state, target, true, iterations, res);
    }
    report.iterations += iterations;
    if (ok) {
      factor = target;
      ++report.increments;
      report.residual = res.force;
      report.constraint_violation = res.constraint;
      report.criterion = newton.criterion_;
      report.tolerance = settings.tolerance;
      report.force_scale = newton.force_scale_;
      report.update = newton.update_;
      report.length_scale = newton.q_scale_;
      if (progress) progress(factor, iterations, report);
      continue;
    }
    state = saved;
    if (interrupt_signal() != 0) continue;  // not a failure: the loop's start stops
    const double tried = increment;
    increment *= 0.5;
    if (increment < settings.min_increment) {
      // the advice follows the cause: a singular matrix or an element that cannot be
      // evaluated (newton.failure_), NaN, Newton still converging when it ran out of
      // iterations (more iterations cure it), or no convergence even at the smallest
      // increment (the model, not the increment, is the problem)
      std::string cause;
      if (!newton.failure_.empty())
        cause = newton.failure_;
      else if (!res.finite)
        cause = "NaN or Inf in the residual: a force cannot be evaluated at this state";
      else if (newton.last_fall_ >= 2.0)
        cause = fmt::format(
            "Newton was still converging (its last iteration reduced the residual {:.3g}-fold) "
            "when it reached statics.max_iterations ({}): raise max_iterations",
            newton.last_fall_, settings.max_iterations);
      else
        cause = fmt::format(
            "no convergence even with the load increment halved to {:.3g} (statics."
            "min_increment {:g}): the model may have no equilibrium near this load (a "
            "mechanism: check the supports and joints; a buckling or snap-through load; a "
            "load larger than the structure can carry)",
            tried, settings.min_increment);
      throw SolverError(
          fmt::format("statics did not converge at load factor {:.6g} (last converged {:.6g}): "
                      "relative residual {:.3e} after {} iterations, largest at {}; {}",
                      target, factor, res.force, iterations, dae.coordinate_name(res.worst), cause),
          settings.time);
    }
  }
  // the residual of the converged state at load factor 1 (every Newton step ends with the
  // residual of the state it leaves): what dynamics takes as round-off (model/state.hpp)
  state.static_residual = newton.r_;
  // the stability of the equilibrium, from the Newton matrix (kq = 1, the multipliers'
  // Hessian, not regularized) that the last iteration evaluated at this state
  report.stability =
      check_stability(newton.eval_.kkt.matrix(), dae.num_coordinates(), dae.num_constraints());
  return report;
}

}  // namespace seaflex
