// Generalized-alpha time integration of the index-3 equations of motion
//   M(q) q'' + C_q^T lambda = Q(q, q', t),   C(q, t) = 0                (thesis eq. 132)
// in the form of Arnold & Bruls (2007), "Convergence of the generalized-alpha scheme for
// constrained mechanical systems", Multibody Syst. Dyn. 18:185-202, eq. (7)-(10):
//   q_{n+1} = q_n + h v_n + h^2 (1/2 - beta) abar_n + h^2 beta abar_{n+1}
//   v_{n+1} = v_n + h (1 - gamma) abar_n + h gamma abar_{n+1}
//   (1 - alpha_m) abar_{n+1} + alpha_m abar_n = (1 - alpha_f) a_{n+1} + alpha_f a_n
// with the equations of motion and the position constraints enforced at t_{n+1}. The
// parameters follow Chung & Hulbert (1993) from the spectral radius at infinite
// frequency rho_inf in [0, 1]:
//   alpha_m = (2 rho - 1)/(rho + 1), alpha_f = rho/(rho + 1),
//   gamma = 1/2 + alpha_f - alpha_m, beta = (gamma + 1/2)^2 / 4,
// second-order accurate, unconditionally stable on linear problems, and without numerical
// dissipation at rho_inf = 1 (then the scheme is Newmark's average acceleration). The HHT
// parameters (alpha_m = 0, alpha_f = (1 - rho)/(1 + rho), rho in [1/2, 1]) are a special
// case with HHT-alpha's spectral properties (Hilber, Hughes & Taylor 1977).
//
// Newton iterations on the unknown a_{n+1}: with beta' = (1 - alpha_m)/(beta h^2 (1 -
// alpha_f)) and gamma' = gamma/(beta h), dq'' = beta' dq and dq' = gamma' dq, and the
// iteration matrix, scaled by 1/beta' (Bottasso, Dopico & Trainelli 2008) so that its
// condition does not grow as 1/h^2, is the System's Newton matrix with
//   km = 1, kq = 1/beta', kv = gamma'/beta'
// (plus kq d(C_q^T lambda)/dq):
//   [M + kv Ct + kq Kt,  C_q^T;  C_q, 0] [dq; dmu] = -[r / beta'; C],  dlambda = beta' dmu,
// r = M a + C_q^T lambda - Q. The dependence of M on q in M a is left out of the matrix
// (it only slows convergence). Full Newton refactors every iteration; modified Newton keeps
// a factorization across iterations and steps while the contraction rate of the updates
// stays below 1/2, and refactors with a fresh Jacobian otherwise.
#pragma once

#include "seaflex/integrators/integrator.hpp"
#include "seaflex/solvers/kkt_solver.hpp"

namespace seaflex {

enum class NewtonMode { kFull, kModified };

struct GeneralizedAlphaSettings {
  double alpha_m = 0.0;
  double alpha_f = 0.0;
  double gamma = 0.5;
  double beta = 0.25;
  NewtonMode newton = NewtonMode::kModified;
  int max_iterations = 12;  ///< Newton iterations per step before the step fails
  double tolerance = 1e-9;  ///< on the estimated error of q, relative to the model's size
  LinearSolverKind linear_solver = kDefaultLinearSolver;  ///< backend of the Newton solves
  /// Chung & Hulbert's parameters for a spectral radius rho_inf in [0, 1].
  static GeneralizedAlphaSettings from_rho_inf(double rho_inf);
  /// HHT-alpha's parameters (alpha_m = 0) for rho_inf in [1/2, 1].
  static GeneralizedAlphaSettings hht(double rho_inf);
};

class GeneralizedAlpha : public Integrator {
 public:
  explicit GeneralizedAlpha(GeneralizedAlphaSettings settings);

  std::string_view name() const override { return "generalized_alpha"; }
  void start(const Dae& dae, State& state) override;
  StepReport step(const Dae& dae, State& state, double h) override;
  /// The step's multipliers already satisfy the equations at t_{n+1}; before the first
  /// step, start() computes consistent ones.
  void update_multipliers(const Dae& dae, State& state) override;

  bool save(CheckpointWriter& out) const override;
  void restore(const Dae& dae, const CheckpointReader& in) override;

  const GeneralizedAlphaSettings& settings() const { return s_; }
  /// The true acceleration q'' at the last accepted step.
  const VecX& acceleration() const { return a_n_; }

 private:
  void prepare(const Dae& dae);
  // the first iterate of a step (a_)
  void predict();
  // abar_{n+1}, q_{n+1}, v_{n+1} of the iterate a_ = a_{n+1}, from the state at t_n
  void update_iterate(const State& state_n, double h);
  // M a: from the stored constant mass matrix, from eval_ (in_eval: assembled with km = 1
  // alone in the same pass as the forces), or from a mass-only evaluation
  void mass_times(const Dae& dae, const State& state, const VecX& a, bool in_eval, VecX& out);
  bool refactor(const Dae& dae, const State& trial, double h);

  GeneralizedAlphaSettings s_;
  bool prepared_ = false;
  bool started_ = false;
  bool constant_mass_ = false;
  Index n_ = 0, m_ = 0;
  double q_scale_ = 1.0;
  DaeEval eval_, mass_eval_;
  SpMat mass_;                // M, when constant
  KktSolver newton_solver_;   // the iteration matrix
  KktSolver initial_solver_;  // [M C_q^T; C_q 0] for the initial accelerations
  double factored_h_ = 0.0;   // the step the Newton matrix was factored for (0: none)
  State factored_at_;         // the iterate it was factored at (restart: factored again)
  VecX a_n_, abar_n_, a_, abar_, Ma_, rhs_, sol_;
  State trial_;
  std::string failure_;
};

}  // namespace seaflex
