#include "seaflex/integrators/rk4_augmented.hpp"

#include <fmt/format.h>

#include <cmath>

#include "seaflex/integrators/instrumented.hpp"

namespace seaflex {

Rk4Augmented::Rk4Augmented(Stabilization stabilization, double alpha, double beta)
    : stabilization_(stabilization), alpha_(alpha), beta_(beta) {}

void Rk4Augmented::prepare(const Dae& dae) {
  n_ = dae.num_coordinates();
  m_ = dae.num_constraints();
  eval_ = dae.make_eval();
  constant_kkt_ = dae.constant_mass_kkt();
  for (VecX* k : {&k1q_, &k2q_, &k3q_, &k4q_, &k1v_, &k2v_, &k3v_, &k4v_, &local_error_})
    k->resize(n_);
  rhs_.resize(n_ + m_);
  sol_.resize(n_ + m_);
  lambda_.resize(m_);
  prepared_ = true;
}

bool Rk4Augmented::factor_at(const Dae& dae, const State& state) {
  if (constant_kkt_ && solver_.factorized()) return true;
  DaeRequest req;
  req.forces = false;
  req.constraints = false;
  req.matrix = true;
  req.scales.km = 1.0;
  instrumented::evaluate(dae, state, req, eval_, stats_);
  return factorize_evaluated();
}

bool Rk4Augmented::factorize_evaluated() {
  if (instrumented::factorize(solver_, eval_.kkt.matrix(), stats_)) return true;
  failure_ = fmt::format(
      "the augmented matrix [M C_q^T; C_q 0] is singular ({}): a body "
      "without mass or redundant constraints",
      solver_.message());
  return false;
}

void Rk4Augmented::accelerations(const Dae& dae, const State& state, VecX& a, VecX& lambda) {
  if (!prepared_) prepare(dae);
  DaeRequest req;
  req.forces = true;
  req.constraints = true;
  const bool refactor = !(constant_kkt_ && solver_.factorized());
  if (refactor) {  // one pass for Q, C, gamma and [M C_q^T; C_q 0] (rigid bodies, joints)
    req.matrix = true;
    req.scales.km = 1.0;
  }
  instrumented::evaluate(dae, state, req, eval_, stats_);
  if (refactor && !factorize_evaluated()) {
    a = VecX::Constant(n_, std::nan(""));
    return;
  }
  rhs_.head(n_) = eval_.Q;
  rhs_.tail(m_) = eval_.gamma;  // thesis eq. (133)
  if (stabilization_ == Stabilization::kBaumgarte)
    rhs_.tail(m_) -= 2.0 * alpha_ * eval_.Cdot + beta_ * beta_ * eval_.C;
  instrumented::solve(solver_, rhs_, sol_, stats_);
  a = sol_.head(n_);
  lambda = sol_.tail(m_);
}

void Rk4Augmented::update_multipliers(const Dae& dae, State& state) {
  if (!prepared_) prepare(dae);
  if (!factor_at(dae, state)) {
    state.lambda.setConstant(std::nan(""));  // no stale reactions in the output
    return;
  }
  accelerations(dae, state, k1v_, state.lambda);
}

bool Rk4Augmented::project(const Dae& dae, State& state, double& violation) {
  DaeRequest req;
  req.forces = false;
  req.constraints = true;
  const double tol = 1e-12 * std::max(1.0, state.q.lpNorm<Eigen::Infinity>());
  // positions: [M C_q^T; C_q 0][dq; mu] = [0; -C], a Newton step towards C = 0
  for (int it = 0; it < 5; ++it) {
    instrumented::evaluate(dae, state, req, eval_, stats_);
    violation = eval_.C.lpNorm<Eigen::Infinity>();
    if (violation <= tol) break;
    if (!factor_at(dae, state)) return false;
    rhs_.head(n_).setZero();
    rhs_.tail(m_) = -eval_.C;
    instrumented::solve(solver_, rhs_, sol_, stats_);
    state.q += sol_.head(n_);
  }
  // velocities: [M C_q^T; C_q 0][dv; mu] = [0; -(C_q v + C_t)], unless already at
  // round-off (always so for linear constraints: every RK4 stage satisfies C_q a = gamma)
  instrumented::evaluate(dae, state, req, eval_, stats_);
  violation = eval_.C.lpNorm<Eigen::Infinity>();
  if (eval_.Cdot.lpNorm<Eigen::Infinity>() <=
      1e-14 * std::max(1.0, state.v.lpNorm<Eigen::Infinity>()))
    return true;
  if (!factor_at(dae, state)) return false;
  rhs_.head(n_).setZero();
  rhs_.tail(m_) = -eval_.Cdot;
  instrumented::solve(solver_, rhs_, sol_, stats_);
  state.v += sol_.head(n_);
  return true;
}

StepReport Rk4Augmented::step(const Dae& dae, State& state, double h) {
  if (!prepared_) prepare(dae);
  StepReport report;
  failure_.clear();
  stage_ = state;
  // thesis eq. (179) on y = (q, v), y' = (v, q'')
  k1q_ = state.v;
  accelerations(dae, state, k1v_, lambda_);
  stage_.t = state.t + 0.5 * h;
  stage_.q = state.q + 0.5 * h * k1q_;
  stage_.v = state.v + 0.5 * h * k1v_;
  k2q_ = stage_.v;
  accelerations(dae, stage_, k2v_, lambda_);
  stage_.q = state.q + 0.5 * h * k2q_;
  stage_.v = state.v + 0.5 * h * k2v_;
  k3q_ = stage_.v;
  accelerations(dae, stage_, k3v_, lambda_);
  stage_.t = state.t + h;
  stage_.q = state.q + h * k3q_;
  stage_.v = state.v + h * k3v_;
  k4q_ = stage_.v;
  accelerations(dae, stage_, k4v_, lambda_);
  state.q += (h / 6.0) * (k1q_ + 2.0 * k2q_ + 2.0 * k3q_ + k4q_);
  state.v += (h / 6.0) * (k1v_ + 2.0 * k2v_ + 2.0 * k3v_ + k4v_);
  state.t += h;
  // the local error of the positions: the embedded third-order solution with the weights
  // (1/6, 1/3, 1/3, 0, 1/6) on k1..k4 and k5 = f(t + h, y_{n+1}) (it satisfies the four
  // order conditions of order 3, Hairer, Norsett & Wanner, Solving ODEs I, sec. II.2), whose
  // difference from RK4 is h/6 (k4 - k5); the position part of k5 is v_{n+1}, so that it
  // costs no evaluation
  local_error_ = (h / 6.0) * (k4q_ - state.v);
  report.iterations = 4;
  ++stats_.steps;
  stats_.iterations += 4;
  if (!failure_.empty()) {
    report.ok = false;
    report.message = failure_;
    return report;
  }
  if (m_ > 0 && stabilization_ == Stabilization::kProjection) {
    if (!project(dae, state, report.residual)) {
      report.ok = false;
      report.message = failure_;
      return report;
    }
  } else if (m_ > 0) {
    DaeRequest req;
    req.forces = false;
    instrumented::evaluate(dae, state, req, eval_, stats_);
    report.residual = eval_.C.lpNorm<Eigen::Infinity>();
  }
  return report;
}

}  // namespace seaflex
