#include "seaflex/integrators/generalized_alpha.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "seaflex/core/errors.hpp"
#include "seaflex/integrators/instrumented.hpp"

namespace seaflex {

namespace {
constexpr double kEps = std::numeric_limits<double>::epsilon();
}  // namespace

GeneralizedAlphaSettings GeneralizedAlphaSettings::from_rho_inf(double rho) {
  if (!(rho >= 0.0 && rho <= 1.0))
    throw std::invalid_argument("generalized-alpha: rho_inf must lie in [0, 1]");
  GeneralizedAlphaSettings s;
  // Chung & Hulbert (1993) eq. (25), (17), (20), as in Arnold & Bruls (2007) sec. 2
  s.alpha_m = (2.0 * rho - 1.0) / (rho + 1.0);
  s.alpha_f = rho / (rho + 1.0);
  s.gamma = 0.5 + s.alpha_f - s.alpha_m;
  s.beta = 0.25 * (s.gamma + 0.5) * (s.gamma + 0.5);
  return s;
}

GeneralizedAlphaSettings GeneralizedAlphaSettings::hht(double rho) {
  if (!(rho >= 0.5 && rho <= 1.0))
    throw std::invalid_argument("HHT-alpha: rho_inf must lie in [1/2, 1]");
  GeneralizedAlphaSettings s;
  // Hilber, Hughes & Taylor (1977): alpha in [0, 1/3], rho_inf = (1 - alpha)/(1 + alpha)
  s.alpha_m = 0.0;
  s.alpha_f = (1.0 - rho) / (1.0 + rho);
  s.gamma = 0.5 + s.alpha_f;
  s.beta = 0.25 * (1.0 + s.alpha_f) * (1.0 + s.alpha_f);
  return s;
}

GeneralizedAlpha::GeneralizedAlpha(GeneralizedAlphaSettings settings)
    : s_(settings),
      newton_solver_(settings.linear_solver),
      initial_solver_(settings.linear_solver) {
  if (!(s_.alpha_m < 1.0 && s_.alpha_f < 1.0 && s_.beta > 0.0 && s_.gamma > 0.0))
    throw std::invalid_argument("generalized-alpha: need alpha_m, alpha_f < 1 and beta, gamma > 0");
  if (s_.max_iterations < 1 || !(s_.tolerance > 0.0))
    throw std::invalid_argument("generalized-alpha: need max_iterations >= 1, tolerance > 0");
}

void GeneralizedAlpha::prepare(const Dae& dae) {
  n_ = dae.num_coordinates();
  m_ = dae.num_constraints();
  eval_ = dae.make_eval();
  constant_mass_ = dae.constant_mass();
  if (!constant_mass_) mass_eval_ = dae.make_eval();
  for (VecX* x : {&a_n_, &abar_n_, &a_, &abar_, &Ma_}) *x = VecX::Zero(n_);
  rhs_ = VecX::Zero(n_ + m_);
  sol_ = VecX::Zero(n_ + m_);
  prepared_ = true;
}

void GeneralizedAlpha::start(const Dae& dae, State& state) {
  if (!prepared_) prepare(dae);
  q_scale_ = std::max(1.0, state.q.lpNorm<Eigen::Infinity>());
  // consistent initial accelerations and multipliers (thesis eq. 132-133):
  // [M C_q^T; C_q 0] [a; lambda] = [Q; gamma]
  DaeRequest req;
  req.matrix = true;
  req.scales.km = 1.0;
  instrumented::evaluate(dae, state, req, eval_, stats_);
  if (constant_mass_) mass_ = eval_.kkt.matrix().topLeftCorner(n_, n_);
  if (!initial_solver_.factorize(eval_.kkt.matrix()))
    throw SolverError(fmt::format("generalized-alpha: the augmented matrix [M C_q^T; C_q 0] is "
                                  "singular at the start ({}): a body without mass or redundant "
                                  "constraints",
                                  initial_solver_.message()),
                      state.t);
  rhs_.head(n_) = eval_.Q;
  rhs_.tail(m_) = eval_.gamma;
  initial_solver_.solve(rhs_, sol_);
  if (!sol_.allFinite())
    throw SolverError("generalized-alpha: the initial accelerations are not finite", state.t);
  a_n_ = sol_.head(n_);
  abar_n_ = a_n_;  // Arnold & Bruls (2007) eq. (10): abar_0 = a_0
  state.lambda = sol_.tail(m_);
  factored_h_ = 0.0;
  started_ = true;
}

bool GeneralizedAlpha::save(CheckpointWriter& out) const {
  out.put("ga.started", static_cast<long>(started_));
  out.put("ga.q_scale", q_scale_);
  out.put("ga.a_n", a_n_);
  out.put("ga.abar_n", abar_n_);
  out.put("ga.factored_h", factored_h_);
  if (factored_h_ > 0.0) {
    out.put("ga.factored_at.t", factored_at_.t);
    out.put("ga.factored_at.q", factored_at_.q);
    out.put("ga.factored_at.v", factored_at_.v);
    out.put("ga.factored_at.lambda", factored_at_.lambda);
  }
  return true;
}

void GeneralizedAlpha::restore(const Dae& dae, const CheckpointReader& in) {
  if (!prepared_) prepare(dae);
  started_ = in.integer("ga.started") != 0;
  q_scale_ = in.number("ga.q_scale");
  a_n_ = in.vector("ga.a_n");
  abar_n_ = in.vector("ga.abar_n");
  factored_h_ = in.number("ga.factored_h");
  if (a_n_.size() != n_ || abar_n_.size() != n_)
    throw std::invalid_argument("generalized-alpha: the checkpoint is for another model");
  if (factored_h_ > 0.0) {
    factored_at_.t = in.number("ga.factored_at.t");
    factored_at_.q = in.vector("ga.factored_at.q");
    factored_at_.v = in.vector("ga.factored_at.v");
    factored_at_.lambda = in.vector("ga.factored_at.lambda");
    // the same matrix at the same iterate, factored again: modified Newton goes on with
    // exactly the matrix the saved run had
    const double h = factored_h_;
    const double bp = (1.0 - s_.alpha_m) / (s_.beta * h * h * (1.0 - s_.alpha_f));
    const double gp = s_.gamma / (s_.beta * h);
    DaeRequest req;
    req.reaction_forces = m_ > 0;
    req.matrix = true;
    req.scales = MatrixScales{1.0, 1.0 / bp, gp / bp};
    req.multiplier_hessian = true;
    instrumented::evaluate(dae, factored_at_, req, eval_, stats_);
    if (constant_mass_) {
      DaeRequest mreq;
      mreq.forces = false;
      mreq.constraints = false;
      mreq.matrix = true;
      mreq.scales.km = 1.0;
      DaeEval mass_eval = dae.make_eval();
      dae.evaluate(factored_at_, mreq, mass_eval);
      mass_ = mass_eval.kkt.matrix().topLeftCorner(n_, n_);
    }
    if (!instrumented::factorize(newton_solver_, eval_.kkt.matrix(), stats_))
      throw SolverError("generalized-alpha: the restored Newton matrix is singular",
                        factored_at_.t);
  } else if (constant_mass_ && started_) {
    throw std::invalid_argument("generalized-alpha: a checkpoint before the first step");
  }
}

void GeneralizedAlpha::update_multipliers(const Dae& dae, State& state) {
  if (!started_) start(dae, state);
}

void GeneralizedAlpha::update_iterate(const State& state_n, double h) {
  const double am = s_.alpha_m, af = s_.alpha_f;
  // Arnold & Bruls (2007) eq. (7)-(9)
  abar_ = ((1.0 - af) * a_ + af * a_n_ - am * abar_n_) / (1.0 - am);
  trial_.q =
      state_n.q + h * state_n.v + (h * h * (0.5 - s_.beta)) * abar_n_ + (h * h * s_.beta) * abar_;
  trial_.v = state_n.v + (h * (1.0 - s_.gamma)) * abar_n_ + (h * s_.gamma) * abar_;
}

void GeneralizedAlpha::predict() {
  const double am = s_.alpha_m, af = s_.alpha_f;
  // abar_{n+1} = -(1/2 - beta)/beta abar_n, and a_{n+1} from eq. (9) of Arnold & Bruls
  const double c = -(0.5 - s_.beta) / s_.beta;
  a_ = ((1.0 - am) * c * abar_n_ - af * a_n_ + am * abar_n_) / (1.0 - af);
}

void GeneralizedAlpha::mass_times(const Dae& dae, const State& state, const VecX& a, bool in_eval,
                                  VecX& out) {
  const SpMat* M = &mass_;
  if (!constant_mass_ && in_eval) {
    M = &eval_.kkt.matrix();  // assembled with the forces (km = 1, kq = kv = 0)
  } else if (!constant_mass_) {
    DaeRequest req;
    req.forces = false;
    req.constraints = false;
    req.matrix = true;
    req.scales.km = 1.0;
    instrumented::evaluate(dae, state, req, mass_eval_, stats_);
    M = &mass_eval_.kkt.matrix();
  }
  // out = M a over the top-left n x n block, without a temporary
  out.setZero();
  for (Index j = 0; j < n_; ++j)
    for (SpMat::InnerIterator it(*M, j); it; ++it)
      if (it.row() < n_) out[it.row()] += it.value() * a[j];
}

StepReport GeneralizedAlpha::step(const Dae& dae, State& state, double h) {
  if (!started_) start(dae, state);
  ++stats_.steps;
  StepReport report;
  const double bp = (1.0 - s_.alpha_m) / (s_.beta * h * h * (1.0 - s_.alpha_f));  // beta'
  const double gp = s_.gamma / (s_.beta * h);                                     // gamma'
  const double tol = s_.tolerance * q_scale_;
  trial_ = state;
  trial_.t = state.t + h;
  // predictor: the a_{n+1} for which q_{n+1} = q_n + h v_n (abar_{n+1} = -(1/2 - beta)/beta
  // abar_n): the iterations start from where the body would coast, not from an
  // extrapolation of accelerations, which after a sudden load (a tensioner switched on, a
  // snap) carry the step far from the solution and make Newton diverge
  predict();
  bool want_fresh = s_.newton == NewtonMode::kFull || factored_h_ != h;
  double previous = 0.0;       // |dq| of the previous update
  double last_theta = 0.0;     // the previous contraction rate (0: none yet)
  double first_norm = -1.0;    // |dq| of the step's first update
  bool fresh_in_step = false;  // the matrix was factored during this step
  int diverging = 0;           // consecutive growing updates with a fresh Jacobian
  auto fail = [&](std::string message) {
    report.ok = false;
    report.message = std::move(message);
    return report;
  };
  Index worst = 0;  // the coordinate of the largest component of the last update
  // what is likely wrong when Newton fails, for the user
  const char* cause =
      "the time step is too long for the motion (a sudden load, a line going slack or taut, "
      "an impact) or a stiffness changes abruptly; try step_control: adaptive or a shorter "
      "time_step";
  for (int it = 1;; ++it) {
    if (it > s_.max_iterations)
      return fail(
          fmt::format("Newton did not converge in {} iterations (step {:g} s; last "
                      "update {:.3g} m against a tolerance of {:.3g} m, largest at {}): {}",
                      s_.max_iterations, h, previous, tol, dae.coordinate_name(worst), cause));
    ++report.iterations;
    ++stats_.iterations;
    update_iterate(state, h);
    DaeRequest req;
    req.reaction_forces = m_ > 0;
    const bool refresh = want_fresh || !newton_solver_.factorized();
    if (refresh) {
      req.matrix = true;
      req.scales = MatrixScales{1.0, 1.0 / bp, gp / bp};
      req.multiplier_hessian = true;
    } else if (!constant_mass_) {  // M(q) in the same pass as the forces
      req.matrix = true;
      req.scales = MatrixScales{1.0, 0.0, 0.0};
    }
    try {
      instrumented::evaluate(dae, trial_, req, eval_, stats_);
      mass_times(dae, trial_, a_, !refresh, Ma_);
    } catch (const SolverError& e) {  // an element cannot be evaluated at this iterate
      return fail(e.what());
    }
    if (refresh) {
      if (!instrumented::factorize(newton_solver_, eval_.kkt.matrix(), stats_))
        return fail(
            fmt::format("the Newton matrix is singular ({}): a mechanism, a body "
                        "without mass or supports, or redundant constraints",
                        newton_solver_.message()));
      factored_h_ = h;
      factored_at_ = trial_;
      want_fresh = s_.newton == NewtonMode::kFull;
    }
    // -[r / beta'; C], r = M a + C_q^T lambda - Q
    rhs_.head(n_) = (eval_.Q - Ma_) / bp;
    if (m_ > 0) {
      rhs_.head(n_) -= eval_.CqT_lambda / bp;
      rhs_.tail(m_) = -eval_.C;
    }
    instrumented::solve(newton_solver_, rhs_, sol_, stats_);
    if (!sol_.allFinite()) {
      Index bad = 0;
      while (bad < n_ && std::isfinite(eval_.Q[bad])) ++bad;
      return fail(bad < n_ ? fmt::format("the force on {} is not finite (NaN/Inf): an element "
                                         "or load cannot be evaluated at this iterate; {}",
                                         dae.coordinate_name(bad), cause)
                           : std::string("the Newton update is not finite: a nearly singular "
                                         "Newton matrix (a mechanism or a body without "
                                         "supports)"));
    }
    a_ += bp * sol_.head(n_);
    trial_.lambda += bp * sol_.tail(m_);
    const double norm = n_ > 0 ? sol_.head(n_).cwiseAbs().maxCoeff(&worst) : 0.0;
    // convergence (Hairer & Wanner, Solving ODEs II, sec. IV.8): the error left after an
    // update dq is about theta/(1 - theta) |dq| with the contraction rate theta. A matrix
    // from an earlier step contracts unevenly (the first update removes the predictor's
    // error, later ones the matrix's), so then theta is the larger of the last two rates.
    // An update at round-off level (1e3 eps of the step's first update, or 16 eps of q)
    // also ends the iterations: nothing is left to gain.
    if (refresh) fresh_in_step = true;
    if (first_norm < 0.0) first_norm = norm;
    const double floor =
        std::max(1e3 * kEps * first_norm, 16.0 * kEps * trial_.q.lpNorm<Eigen::Infinity>());
    bool converged = norm <= std::max(tol, floor);
    if (previous > 0.0) {
      const double theta = norm / previous;
      const double rate =
          fresh_in_step ? theta : (last_theta > 0.0 ? std::max(theta, last_theta) : 1.0);
      if (rate < 1.0 && rate / (1.0 - rate) * norm <= tol) converged = true;
      last_theta = theta;
      // modified Newton: a Jacobian at this iterate when the contraction is slow, or too
      // slow to reach the tolerance within the remaining iterations
      const bool too_slow =
          theta >= 1.0 || std::pow(theta, s_.max_iterations - it) / (1.0 - theta) * norm > tol;
      if (!converged && (theta > 0.5 || too_slow) && !refresh) {
        want_fresh = true;   // a Jacobian at this iterate, or, when the stale matrix has
        if (theta >= 1.0) {  // driven the iterate away, at the predictor again
          predict();
          trial_.lambda = state.lambda;
          previous = last_theta = 0.0;
          continue;
        }
      }
      diverging = !converged && refresh && theta >= 1.0 ? diverging + 1 : 0;
      if (diverging >= 2)
        return fail(
            fmt::format("Newton diverges (updates grow by {:.3g} with a fresh "
                        "Jacobian; step {:g} s; largest update at {}): {}",
                        theta, h, dae.coordinate_name(worst), cause));
    }
    if (converged) break;
    previous = norm;
  }
  update_iterate(state, h);
  // the constraints at the accepted positions (cheap: no forces, no matrix)
  if (m_ > 0) {
    DaeRequest req;
    req.forces = false;
    instrumented::evaluate(dae, trial_, req, eval_, stats_);
    report.residual = eval_.C.lpNorm<Eigen::Infinity>();
  }
  state.t = trial_.t;
  state.q = trial_.q;
  state.v = trial_.v;
  state.lambda = trial_.lambda;
  a_n_ = a_;
  abar_n_ = abar_;
  return report;
}

}  // namespace seaflex
