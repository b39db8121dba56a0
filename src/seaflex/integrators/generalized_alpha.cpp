#include "seaflex/integrators/generalized_alpha.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "seaflex/core/errors.hpp"
#include "seaflex/integrators/instrumented.hpp"

namespace seaflex {

namespace {
constexpr double kEps = std::numeric_limits<double>::epsilon();
// a step with a reused matrix that needs more iterations than this refactors the next
constexpr int kRefreshIterations = 3;
// new matrices in a row that start from the stored rate before one measures it again
constexpr int kRateReuses = 8;
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
  // a stale Newton matrix is refactored with the pivot order of an earlier one (saved in
  // checkpoints, so that a restart factors the same; kkt_solver.hpp)
  newton_solver_.set_reuse_pivots(true);
  if (!(s_.alpha_m < 1.0 && s_.alpha_f < 1.0 && s_.beta > 0.0 && s_.gamma > 0.0))
    throw std::invalid_argument("generalized-alpha: need alpha_m, alpha_f < 1 and beta, gamma > 0");
  if (s_.max_iterations < 1 || !(s_.tolerance > 0.0))
    throw std::invalid_argument("generalized-alpha: need max_iterations >= 1, tolerance > 0");
  if (!(s_.refresh_rate > 0.0 && s_.refresh_rate < 1.0))
    throw std::invalid_argument("generalized-alpha: refresh_rate must lie in (0, 1)");
}

void GeneralizedAlpha::prepare(const Dae& dae) {
  n_ = dae.num_coordinates();
  m_ = dae.num_constraints();
  eval_ = dae.make_eval();
  constant_mass_ = dae.constant_mass();
  product_ = dae.supports_product();
  length_scale_ = dae.length_scale();
  // the multipliers measured for convergence: all but the reaction-only rows
  measured_rows_.clear();
  const std::vector<Index> reaction_only = dae.reaction_only_rows();
  if (!reaction_only.empty())
    for (Index r = 0, k = 0; r < m_; ++r) {
      if (k < static_cast<Index>(reaction_only.size()) && reaction_only[k] == r)
        ++k;
      else
        measured_rows_.push_back(r);
    }
  all_rows_measured_ = reaction_only.empty();
  if (!constant_mass_) mass_eval_ = dae.make_eval();
  if (m_ > 0 && s_.constraints == ConstraintLevel::kStabilizedIndex2)
    projection_eval_ = dae.make_eval();
  for (VecX* x : {&a_n_, &abar_n_, &a_, &abar_, &Ma_, &corr_, &factored_a_, &a_prev_, &abar_prev_,
                  &local_error_})
    *x = VecX::Zero(n_);
  rhs_ = VecX::Zero(n_ + m_);
  sol_ = VecX::Zero(n_ + m_);
  eta_ = VecX::Zero(m_);
  dy_ = VecX::Zero(n_);
  prepared_ = true;
}

void GeneralizedAlpha::start(const Dae& dae, State& state) {
  if (!prepared_) prepare(dae);
  carried_theta_ = reuse_theta_ = reuse_h_ = 0.0;  // no rates before the first step
  steps_on_matrix_ = 0;
  rate_reuses_ = 0;
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
  // from statics: the equilibrium's round-off is not a load (model/state.hpp); what the
  // dynamic forces at t0 add to the static ones (a wave, a changed load) still accelerates
  if (state.static_residual.size() == n_) rhs_.head(n_) -= state.static_residual;
  rhs_.tail(m_) = eval_.gamma;
  initial_solver_.solve(rhs_, sol_);
  if (!sol_.allFinite())
    throw SolverError("generalized-alpha: the initial accelerations are not finite", state.t);
  a_n_ = sol_.head(n_);
  abar_n_ = a_n_;  // Arnold & Bruls (2007) eq. (10): abar_0 = a_0
  state.lambda = sol_.tail(m_);
  // the model's acceleration and force scales: the initial accelerations, and each
  // coordinate's applied force and constraint reaction over its mass (a model at rest in
  // equilibrium has a = 0 but carries its weight through the reactions)
  const SpMat& K0 = eval_.kkt.matrix();
  VecX reaction = VecX::Zero(n_);
  for (Index j = 0; j < n_; ++j)
    for (SpMat::InnerIterator it(K0, j); it; ++it)
      if (it.row() >= n_) reaction[j] += it.value() * state.lambda[it.row() - n_];
  a_scale_ = n_ > 0 ? a_n_.lpNorm<Eigen::Infinity>() : 0.0;
  f_scale_ = m_ > 0 ? state.lambda.lpNorm<Eigen::Infinity>() : 0.0;
  for (Index j = 0; j < n_; ++j) {
    const double f = std::abs(eval_.Q[j]) + std::abs(reaction[j]);
    f_scale_ = std::max(f_scale_, f);
    const double mjj = K0.coeff(j, j);
    if (mjj > 0.0) a_scale_ = std::max(a_scale_, f / mjj);
  }
  factored_h_ = 0.0;
  projection_ready_ = false;
  started_ = true;
}

bool GeneralizedAlpha::save(CheckpointWriter& out) const {
  out.put("ga.started", static_cast<long>(started_));
  out.put("ga.q_scale", q_scale_);
  out.put("ga.a_scale", a_scale_);
  out.put("ga.f_scale", f_scale_);
  out.put("ga.a_n", a_n_);
  out.put("ga.abar_n", abar_n_);
  out.put("ga.factored_h", factored_h_);
  out.put("ga.refresh_next", static_cast<long>(refresh_next_));
  out.put("ga.h_last", h_last_);
  out.put("ga.theta", carried_theta_);
  out.put("ga.reuse_theta", reuse_theta_);
  out.put("ga.reuse_h", reuse_h_);
  out.put("ga.steps_on_matrix", steps_on_matrix_);
  out.put("ga.rate_reuses", static_cast<long>(rate_reuses_));
  if (projection_ready_ && std::isfinite(projection_t_)) out.put("ga.projection_t", projection_t_);
  if (h_last_ > 0.0) {
    out.put("ga.a_before", a_before_);
    out.put("ga.lambda_before", lambda_before_);
  }
  if (factored_h_ > 0.0) {
    out.put("ga.factored_at.t", factored_at_.t);
    out.put("ga.factored_at.q", factored_at_.q);
    out.put("ga.factored_at.v", factored_at_.v);
    out.put("ga.factored_at.lambda", factored_at_.lambda);
    out.put("ga.factored_a", factored_a_);
    // the matrix whose pivot order the current factors reused (restore factors it first)
    const std::vector<double>& source = newton_solver_.pivot_source();
    if (!source.empty())
      out.put("ga.pivot_source",
              VecX(Eigen::Map<const VecX>(source.data(), static_cast<Index>(source.size()))));
  }
  return true;
}

void GeneralizedAlpha::restore(const Dae& dae, const CheckpointReader& in) {
  if (!prepared_) prepare(dae);
  started_ = in.integer("ga.started") != 0;
  q_scale_ = in.number("ga.q_scale");
  a_scale_ = in.number("ga.a_scale");
  f_scale_ = in.number("ga.f_scale");
  a_n_ = in.vector("ga.a_n");
  abar_n_ = in.vector("ga.abar_n");
  factored_h_ = in.number("ga.factored_h");
  refresh_next_ = in.integer("ga.refresh_next") != 0;
  // the predictor's memory (absent from checkpoints written before it: no extrapolation)
  h_last_ = in.has("ga.h_last") ? in.number("ga.h_last") : 0.0;
  carried_theta_ = in.has("ga.theta") ? in.number("ga.theta") : 0.0;
  reuse_theta_ = in.has("ga.reuse_theta") ? in.number("ga.reuse_theta") : 0.0;
  reuse_h_ = in.has("ga.reuse_h") ? in.number("ga.reuse_h") : 0.0;
  // (a checkpoint from before these entries: the matrix's age unknown, no rate stored from it)
  steps_on_matrix_ = in.has("ga.steps_on_matrix") ? in.integer("ga.steps_on_matrix") : 2;
  rate_reuses_ =
      in.has("ga.rate_reuses") ? static_cast<int>(in.integer("ga.rate_reuses", 0, kRateReuses)) : 0;
  if (h_last_ > 0.0) {
    a_before_ = in.vector("ga.a_before");
    lambda_before_ = in.vector("ga.lambda_before");
    if (a_before_.size() != n_ || lambda_before_.size() != m_)
      throw std::invalid_argument("generalized-alpha: the checkpoint is for another model");
  }
  projection_ready_ = false;
  // (a checkpoint from before this entry: C_q at the state's own time)
  restored_projection_t_ = in.has("ga.projection_t") ? in.number("ga.projection_t")
                                                     : std::numeric_limits<double>::quiet_NaN();
  if (a_n_.size() != n_ || abar_n_.size() != n_)
    throw std::invalid_argument("generalized-alpha: the checkpoint is for another model");
  if (factored_h_ > 0.0) {
    factored_at_.t = in.number("ga.factored_at.t");
    factored_at_.q = in.vector("ga.factored_at.q");
    factored_at_.v = in.vector("ga.factored_at.v");
    factored_at_.lambda = in.vector("ga.factored_at.lambda");
    factored_a_ = in.vector("ga.factored_a");
    if (factored_at_.q.size() != n_ || factored_at_.v.size() != n_ ||
        factored_at_.lambda.size() != m_ || factored_a_.size() != n_)
      throw std::invalid_argument("generalized-alpha: the checkpoint is for another model");
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
    req.acceleration = &factored_a_;
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
    if (in.has("ga.pivot_source")) {
      // the saved run's factors reused the pivot order of this matrix: set the same order
      SpMat source = eval_.kkt.matrix();
      const VecX values = in.vector("ga.pivot_source");
      if (values.size() != source.nonZeros())
        throw std::invalid_argument("generalized-alpha: the checkpoint is for another model");
      std::copy(values.data(), values.data() + values.size(), source.valuePtr());
      if (!instrumented::factorize(newton_solver_, source, stats_))
        throw SolverError("generalized-alpha: the restored Newton matrix is singular",
                          factored_at_.t);
    }
    if (!instrumented::factorize(newton_solver_, eval_.kkt.matrix(), stats_))
      throw SolverError("generalized-alpha: the restored Newton matrix is singular",
                        factored_at_.t);
  } else if (constant_mass_ && started_) {
    throw std::invalid_argument("generalized-alpha: a checkpoint before the first step");
  }
}

void GeneralizedAlpha::reject_step() {
  a_n_ = a_prev_;
  abar_n_ = abar_prev_;
  a_scale_ = a_scale_prev_;
  f_scale_ = f_scale_prev_;
  refresh_next_ = refresh_prev_;
  reuse_theta_ = 0.0;         // a rate the rejected step may have stored: measured again
  h_last_ = 0.0;              // the retried step starts from the last step's values
  projection_ready_ = false;  // C_q at the restored state, at the next step
}

void GeneralizedAlpha::update_multipliers(const Dae& dae, State& state) {
  if (!started_) start(dae, state);
}

void GeneralizedAlpha::prepare_iterate(const State& state_n, double h) {
  const double am = s_.alpha_m, af = s_.alpha_f;
  // Arnold & Bruls (2007) eq. (7)-(9) without the terms in a_{n+1} (update_iterate)
  abar_base_ = (af * a_n_ - am * abar_n_) / (1.0 - am);
  q_base_ = state_n.q + h * state_n.v + (h * h * (0.5 - s_.beta)) * abar_n_;
  v_base_ = state_n.v + (h * (1.0 - s_.gamma)) * abar_n_;
  iterate_h_ = h;
}

void GeneralizedAlpha::update_iterate() {
  const double h = iterate_h_;
  // Arnold & Bruls (2007) eq. (7)-(9): abar = ((1 - af) a + af a_n - am abar_n) / (1 - am),
  // q = q_n + h v_n + h^2 ((1/2 - beta) abar_n + beta abar) (+ the projection's correction),
  // v = v_n + h ((1 - gamma) abar_n + gamma abar), the terms without a from prepare_iterate
  abar_ = ((1.0 - s_.alpha_f) / (1.0 - s_.alpha_m)) * a_ + abar_base_;
  trial_.q = q_base_ + (h * h * s_.beta) * abar_ + corr_;
  trial_.v = v_base_ + (h * s_.gamma) * abar_;
}

void GeneralizedAlpha::predict_coasting() {
  const double am = s_.alpha_m, af = s_.alpha_f;
  // abar_{n+1} = -(1/2 - beta)/beta abar_n, and a_{n+1} from eq. (9) of Arnold & Bruls
  const double c = -(0.5 - s_.beta) / s_.beta;
  a_ = ((1.0 - am) * c * abar_n_ - af * a_n_ + am * abar_n_) / (1.0 - af);
}

void GeneralizedAlpha::mass_times(const Dae& dae, const State& state, const VecX& a, bool in_eval,
                                  VecX& out) {
  const SpMat* M = &mass_;
  if (!constant_mass_ && in_eval) {
    if (product_) {  // M(q) a summed with the forces, element by element
      out = eval_.product.head(n_);
      return;
    }
    M = &eval_.kkt.matrix();  // assembled with the forces (km = 1, kq = kv = 0)
  } else if (!constant_mass_) {
    DaeRequest req;
    req.forces = false;
    req.constraints = false;
    req.matrix = true;
    req.scales.km = 1.0;
    if (product_) req.product_with = &a;
    instrumented::evaluate(dae, state, req, mass_eval_, stats_);
    if (product_) {
      out = mass_eval_.product.head(n_);
      return;
    }
    M = &mass_eval_.kkt.matrix();
  }
  // out = M a over the top-left n x n block, without a temporary
  out.setZero();
  for (Index j = 0; j < n_; ++j)
    for (SpMat::InnerIterator it(*M, j); it; ++it)
      if (it.row() < n_) out[it.row()] += it.value() * a[j];
}

void GeneralizedAlpha::project_predictor(const Dae& dae, double a_per_v, double q_per_a) {
  // the predicted velocities onto C_q v + C_t = 0 and then the positions onto C = 0, both
  // along R = C_q(q_n)^T (the projection's own directions): dv = R eta with
  // C_q R eta = -Cdot, made through the accelerations (dv/da = gamma'/beta'), then
  // dq = R eta with C_q R eta = -C kept in the projection's correction. The velocity
  // projection moves the positions by da / beta' (q_per_a); C there is taken to first order,
  // C + C_q da / beta' with the C_q of the same evaluation (C_q(q_n) when the Dae cannot give
  // C_q alone), without evaluating the constraints again: the predictor only starts the
  // iterations, whose solution it does not change
  DaeRequest req;
  req.forces = false;
  req.constraint_jacobian = dae.supports_constraint_jacobian();
  update_iterate();
  instrumented::evaluate(dae, trial_, req, eval_, stats_);
  solve_projection(-eval_.Cdot);
  dy_.noalias() = constraint_jacobian_.transpose() * eta_;
  a_.noalias() += a_per_v * dy_;
  predicted_C_ = -eval_.C;  // -C at the positions the velocities' projection moves to
  if (req.constraint_jacobian)
    predicted_C_.noalias() -= (a_per_v * q_per_a) * (eval_.Cq.matrix() * dy_);
  else
    predicted_C_.noalias() -= (a_per_v * q_per_a) * (constraint_jacobian_ * dy_);
  solve_projection(predicted_C_);
  corr_.noalias() = constraint_jacobian_.transpose() * eta_;
}

void GeneralizedAlpha::prepare_projection(const Dae& dae, const State& state) {
  // C_q(q_n) alone: no forces, no mass (the bodies assemble nothing with zero scales)
  projection_t_ = state.t;
  DaeRequest req;
  req.forces = false;
  if (dae.supports_constraint_jacobian()) {  // C_q alone, without the KKT matrix
    req.constraint_jacobian = true;
    instrumented::evaluate(dae, state, req, projection_eval_, stats_);
    constraint_jacobian_ = projection_eval_.Cq.matrix();
  } else {
    req.matrix = true;
    req.scales = MatrixScales{0.0, 0.0, 0.0};
    instrumented::evaluate(dae, state, req, projection_eval_, stats_);
    constraint_jacobian_ = projection_eval_.kkt.matrix().bottomLeftCorner(m_, n_);
  }
  auto not_finite = [&] {
    return SolverError(
        "the constraint Jacobian C_q is not finite (NaN/Inf): a joint or support cannot be "
        "evaluated at this state",
        state.t);
  };
  // C_q C_q^T is positive semi-definite: a pivot that is not positive means dependent rows
  projection_is_dense_ = m_ <= s_.dense_projection_rows;
  if (projection_is_dense_) {
    // C_q C_q^T summed coordinate by coordinate into an m x m array (a coordinate's column of
    // C_q has a few entries: the sum costs sum_k nnz_k^2) and factored as the dense matrix it
    // is (Eigen's LLT, m^3/6 multiply-adds: 9e3 instructions for the storm's 19 rows, where
    // a sparse LDL^T of the same matrix stored with every entry took 3e4): no sparse product
    // and no allocation per step
    projection_dense_.setZero(m_, m_);
    for (Index k = 0; k < constraint_jacobian_.outerSize(); ++k)
      for (SpMat::InnerIterator a(constraint_jacobian_, k); a; ++a)
        for (SpMat::InnerIterator b(constraint_jacobian_, k); b; ++b)
          projection_dense_(a.row(), b.row()) += a.value() * b.value();
    if (!projection_dense_.allFinite()) throw not_finite();
    projection_dense_solver_.compute(projection_dense_);  // fails on a pivot <= 0
    projection_ready_ = projection_dense_solver_.info() == Eigen::Success;
  } else {
    projection_matrix_ = constraint_jacobian_ * constraint_jacobian_.transpose();
    projection_matrix_.makeCompressed();
    if (!Eigen::Map<const VecX>(projection_matrix_.valuePtr(), projection_matrix_.nonZeros())
             .allFinite())
      throw not_finite();
    if (!projection_analyzed_) {
      projection_solver_.analyzePattern(projection_matrix_);
      projection_analyzed_ = true;
    }
    projection_solver_.factorize(projection_matrix_);  // fails on a pivot = 0 only
    projection_ready_ = projection_solver_.info() == Eigen::Success &&
                        (projection_solver_.vectorD().array() > 0.0).all();
  }
  if (!projection_ready_)
    throw SolverError(
        "the constraint rows are dependent (C_q C_q^T is singular): redundant joints or "
        "supports; seaflex check names them",
        state.t);
}

StepReport GeneralizedAlpha::step(const Dae& dae, State& state, double h) {
  if (!started_) start(dae, state);
  ++stats_.steps;
  StepReport report;
  const double bp = (1.0 - s_.alpha_m) / (s_.beta * h * h * (1.0 - s_.alpha_f));  // beta'
  const double gp = s_.gamma / (s_.beta * h);                                     // gamma'
  const bool index2 = s_.constraints == ConstraintLevel::kStabilizedIndex2 && m_ > 0;
  auto fail = [&](std::string message) {
    report.ok = false;
    report.message = std::move(message);
    return report;
  };
  trial_ = state;
  trial_.t = state.t + h;
  prepare_iterate(state, h);
  // predictor: the accelerations and multipliers extrapolated from the last two steps
  // (see the file header; the last step's values at the first step and after a rejected
  // one); when a stale matrix drives the iterate away from it (a sudden load, a snap) the
  // iterations restart from where the body would coast
  a_ = a_n_;
  if (h_last_ > 0.0) {
    const double r = h / h_last_;
    a_ += r * (a_n_ - a_before_);
    trial_.lambda += r * (state.lambda - lambda_before_);
  }
  corr_.setZero();
  if (index2 && !projection_ready_) {
    try {
      // the checkpoint's time (restore), when it is the state's to round-off (a damaged
      // entry is not followed: the state's own time then)
      if (std::abs(restored_projection_t_ - state.t) <= 1e-12 * (1.0 + std::abs(state.t))) {
        State at = state;
        at.t = restored_projection_t_;
        prepare_projection(dae, at);
      } else {
        prepare_projection(dae, state);
      }
    } catch (const SolverError& e) {
      return fail(e.what());
    }
  }
  restored_projection_t_ = std::numeric_limits<double>::quiet_NaN();
  if (index2) {
    try {
      project_predictor(dae, bp / gp, 1.0 / bp);
    } catch (const SolverError& e) {
      return fail(e.what());
    }
  }
  const bool refresh_at_start = refresh_next_;
  bool want_fresh = s_.newton == NewtonMode::kFull || factored_h_ != h || refresh_next_;
  refresh_next_ = false;
  double previous = 0.0;       // the previous update, in units of the tolerance
  double last_theta = 0.0;     // the previous contraction rate (0: none yet)
  int rates = 0;               // contraction rates observed with this step's matrix
  double first_norm = -1.0;    // the step's first update, in units of the tolerance
  bool fresh_in_step = false;  // the matrix was factored during this step
  int diverging = 0;           // consecutive growing updates with a fresh Jacobian
  bool coasting = false;       // restarted from the coasting predictor
  // the last update: its largest acceleration component and coordinate, its largest
  // multiplier component, the largest projection, and their tolerances
  double last_da = 0.0, last_dl = 0.0, last_dy = 0.0, a_tol = 0.0, f_tol = 0.0, q_tol = 0.0;
  Index worst = 0;
  const char* diverge_cause =
      "the time step is too long for the motion (a sudden load, a line going slack or taut, "
      "an impact) or a stiffness changes abruptly; try step_control: adaptive or a shorter "
      "time_step";
  int restart_at = 0;  // the iterations before the last restart from the predictor
  for (int it = 1;; ++it) {
    if (it - restart_at > s_.max_iterations) {
      const bool one_update = last_theta == 0.0 && !coasting;  // no rate observed yet
      const bool contracting = last_theta > 0.0 && last_theta < 0.5 && !coasting;
      return fail(fmt::format(
          "Newton did not converge in {} iterations (step {:g} s): the last update of the "
          "accelerations was {:.3g} (tolerance {:.3g}), largest at {}, of the multipliers "
          "{:.3g} (tolerance {:.3g}){}: {}",
          s_.max_iterations, h, last_da, a_tol, dae.coordinate_name(worst), last_dl, f_tol,
          index2 ? fmt::format(", of the constraint projection {:.3g} m (tolerance {:.3g} m)",
                               last_dy, q_tol)
                 : std::string(),
          one_update ? std::string("one iteration cannot show convergence; raise max_iterations")
          : contracting
              ? fmt::format("the iterations converge, but slowly (each update {:.2g} times the "
                            "previous); raise max_iterations, or use newton: full",
                            last_theta)
              : std::string(diverge_cause)));
    }
    ++report.iterations;
    ++stats_.iterations;
    update_iterate();
    DaeRequest req;
    req.reaction_forces = m_ > 0;
    const bool refresh = want_fresh || !newton_solver_.factorized();
    if (refresh) {
      req.matrix = true;
      req.scales = MatrixScales{1.0, 1.0 / bp, gp / bp};
      req.multiplier_hessian = true;
      req.acceleration = &a_;      // kq d(M(q) a)/dq
    } else if (!constant_mass_) {  // M(q) a in the same pass as the forces
      req.matrix = true;
      req.scales = MatrixScales{1.0, 0.0, 0.0};
      if (product_) req.product_with = &a_;
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
      // a new matrix: the stored rate of an earlier matrix one step after its factorization,
      // for the same step length, not after a restart from the coasting predictor, and not
      // for more than kRateReuses matrices in a row (file header); else none until its own
      // rates are seen
      const bool reuse =
          !coasting && reuse_theta_ > 0.0 && reuse_h_ == h && rate_reuses_ < kRateReuses;
      carried_theta_ = reuse ? reuse_theta_ : 0.0;
      if (reuse) ++rate_reuses_;
      steps_on_matrix_ = 0;
      factored_at_ = trial_;
      factored_a_ = a_;
      want_fresh = s_.newton == NewtonMode::kFull || coasting;  // a hard step: full Newton
    }
    // -[r / beta'; c], r = M a + C_q^T lambda - Q; c = C (index 3) or Cdot / gamma'
    rhs_.head(n_) = (eval_.Q - Ma_) / bp;
    if (m_ > 0) {
      rhs_.head(n_) -= eval_.CqT_lambda / bp;
      if (index2)
        rhs_.tail(m_) = -eval_.Cdot / gp;
      else
        rhs_.tail(m_) = -eval_.C;
    }
    instrumented::solve(newton_solver_, rhs_, sol_, stats_);
    if (index2) {
      // the projection onto C = 0 along R = C_q(q_n)^T: C_q (dq + R deta) = -C with
      // C_q dq = -Cdot / gamma', solved with C_q(q_n) C_q(q_n)^T for C_q R
      solve_projection(eval_.Cdot / gp - eval_.C);
      dy_.noalias() = constraint_jacobian_.transpose() * eta_;
    }
    if (!sol_.allFinite() || (index2 && !dy_.allFinite())) {
      Index bad = 0;
      while (bad < n_ && std::isfinite(eval_.Q[bad])) ++bad;
      return fail(bad < n_ ? fmt::format("the force on {} is not finite (NaN/Inf): an element "
                                         "or load cannot be evaluated at this iterate; {}",
                                         dae.coordinate_name(bad), diverge_cause)
                           : std::string("the Newton update is not finite: a nearly singular "
                                         "Newton matrix (a mechanism or a body without "
                                         "supports)"));
    }
    a_ += bp * sol_.head(n_);
    trial_.lambda += bp * sol_.tail(m_);
    if (index2) corr_ += dy_;
    // the update against the tolerances (see the file header): relative to the larger of
    // the model's scale and the iterate itself (a model that starts without loads, moving,
    // has no acceleration scale yet), and at least a few ulps of the quantity
    constexpr double kUlps = 64.0 * kEps;
    const double a_now = n_ > 0 ? a_.lpNorm<Eigen::Infinity>() : 0.0;
    const double l_now = m_ > 0 ? trial_.lambda.lpNorm<Eigen::Infinity>() : 0.0;
    a_tol = std::max(s_.tolerance * std::max(a_scale_, a_now), kUlps * a_now);
    f_tol = m_ > 0 ? std::max(s_.tolerance * std::max(f_scale_, l_now), kUlps * l_now) : 1.0;
    q_tol = std::max(s_.tolerance * std::min(q_scale_, length_scale_),
                     kUlps * trial_.q.lpNorm<Eigen::Infinity>());
    last_da = n_ > 0 ? bp * sol_.head(n_).cwiseAbs().maxCoeff(&worst) : 0.0;
    // the reaction-only multipliers (a body on an imposed motion) are not measured: the
    // step's other unknowns do not depend on them (Dae::reaction_only_rows)
    last_dl = 0.0;
    if (all_rows_measured_) {
      if (m_ > 0) last_dl = bp * sol_.tail(m_).lpNorm<Eigen::Infinity>();
    } else {
      for (const Index r : measured_rows_) last_dl = std::max(last_dl, std::abs(sol_[n_ + r]));
      last_dl *= bp;
    }
    last_dy = index2 ? dy_.lpNorm<Eigen::Infinity>() : 0.0;
    auto ratio = [](double d, double tol) { return tol > 0.0 ? d / tol : (d > 0.0 ? 1e300 : 0.0); };
    const double norm =
        std::max({ratio(last_da, a_tol), ratio(last_dl, f_tol), ratio(last_dy, q_tol)});
    // convergence (Hairer & Wanner, Solving ODEs II, sec. IV.8): the error left after an
    // update is about theta/(1 - theta) times the update with the contraction rate theta. A
    // matrix from an earlier step contracts unevenly (the first update removes the
    // predictor's error, later ones the matrix's), so then theta is the larger of the last
    // two rates. An update at round-off level (1e3 eps of the step's first update) also ends
    // the iterations: nothing is left to gain.
    if (refresh) fresh_in_step = true;
    if (first_norm < 0.0) first_norm = norm;
    bool converged = norm <= std::max(1.0, 1e3 * kEps * first_norm);
    if (previous > 0.0) {
      const double theta = norm / previous;
      const double earlier = last_theta > 0.0       ? last_theta
                             : carried_theta_ > 0.0 ? std::pow(carried_theta_, 0.8)
                                                    : 1.0;
      const double rate = fresh_in_step ? theta : std::max(theta, earlier);
      if (rate < 1.0 && rate / (1.0 - rate) * norm <= 1.0) converged = true;
      last_theta = theta;
      ++rates;
      // modified Newton: a Jacobian at this iterate when the contraction is slower than
      // refresh_rate, or too slow to reach the tolerance within the remaining iterations
      const bool too_slow =
          theta >= 1.0 ||
          std::pow(theta, s_.max_iterations - (it - restart_at)) / (1.0 - theta) * norm > 1.0;
      if (!converged && (theta > s_.refresh_rate || too_slow) && !refresh) {
        want_fresh = true;   // a Jacobian at this iterate, or, when the stale matrix has
        if (theta >= 1.0) {  // driven the iterate away, at the predictor again
          if (!coasting) restart_at = it;  // one fresh budget of iterations, once
          coasting = true;
          predict_coasting();
          corr_.setZero();
          trial_.lambda = state.lambda;
          previous = last_theta = carried_theta_ = 0.0;
          rates = 0;
          continue;
        }
      }
      diverging = !converged && refresh && theta >= 1.0 ? diverging + 1 : 0;
      if (diverging >= 1 && !coasting) {
        // a fresh Jacobian diverges from the last step's acceleration (a sudden load
        // makes it a poor guess): once more from the coasting position
        coasting = true;
        restart_at = it;
        predict_coasting();
        corr_.setZero();
        trial_.lambda = state.lambda;
        previous = last_theta = carried_theta_ = 0.0;
        rates = 0;
        diverging = 0;
        want_fresh = true;
        continue;
      }
      if (diverging >= 2)
        return fail(
            fmt::format("Newton diverges (updates grow by {:.3g} with a fresh "
                        "Jacobian; step {:g} s; largest update at {}): {}",
                        theta, h, dae.coordinate_name(worst), diverge_cause));
    }
    if (converged) break;
    previous = norm;
  }
  update_iterate();
  // the constraints at the accepted positions (cheap: no forces, no matrix); with index 2
  // also their Jacobian, the next step's projection R = C_q(q_{n+1})^T
  if (index2) {
    try {
      prepare_projection(dae, trial_);
    } catch (const SolverError& e) {
      return fail(e.what());
    }
    report.residual = projection_eval_.C.lpNorm<Eigen::Infinity>();
  } else if (m_ > 0) {
    DaeRequest req;
    req.forces = false;
    instrumented::evaluate(dae, trial_, req, eval_, stats_);
    report.residual = eval_.C.lpNorm<Eigen::Infinity>();
  }
  state.t = trial_.t;
  state.q = trial_.q;
  state.v = trial_.v;
  lambda_before_ = state.lambda;
  state.lambda = trial_.lambda;
  // the local error of the positions (Zienkiewicz & Xie 1991 with abar, see the file header)
  local_error_ = (h * h) * ((0.5 - s_.beta) * abar_n_ + s_.beta * abar_ - a_n_ / 3.0 - a_ / 6.0);
  a_prev_ = a_n_;
  abar_prev_ = abar_n_;
  a_scale_prev_ = a_scale_;
  f_scale_prev_ = f_scale_;
  refresh_prev_ = refresh_at_start;
  a_before_ = a_n_;
  h_last_ = h;
  // the rate of a stale matrix beyond the update that removed the predictor's error
  if (!fresh_in_step && rates >= 2) {
    carried_theta_ = last_theta;
    if (steps_on_matrix_ == 1) {  // the first step that reused the matrix (file header)
      reuse_theta_ = last_theta;
      reuse_h_ = h;
      rate_reuses_ = 0;
    }
  }
  ++steps_on_matrix_;
  a_n_ = a_;
  abar_n_ = abar_;
  // a matrix that has aged so that the step needed more than refresh_iterations
  // iterations is rebuilt at the start of the next step (the contraction slows as the
  // motion carries the iterate away from where the matrix was factored)
  if (!fresh_in_step && report.iterations > kRefreshIterations) refresh_next_ = true;
  a_scale_ = std::max(a_scale_, a_n_.size() > 0 ? a_n_.lpNorm<Eigen::Infinity>() : 0.0);
  if (m_ > 0) f_scale_ = std::max(f_scale_, state.lambda.lpNorm<Eigen::Infinity>());
  return report;
}

}  // namespace seaflex
