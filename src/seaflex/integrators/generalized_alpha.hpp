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
// Constraints (settings.constraints):
//   kStabilizedIndex2 (default): the stabilized index-2 form of Gear, Gupta & Leimkuhler
//     (1985), "Automatic integration of Euler-Lagrange equations with constraints", J.
//     Comput. Appl. Math. 12-13:77-90, as Arnold, Bruls & Cardona apply it to
//     generalized-alpha (Arnold, Cardona & Bruls 2016, "A Lie algebra approach to Lie group
//     time integration of constrained systems", CISM course 565; error analysis in Arnold,
//     Bruls & Cardona 2015, Numer. Math. 129:149-179): the velocity constraint C_q v + C_t = 0
//     determines lambda, and the position constraint C = 0 is held by a projection term
//     R eta added to q_{n+1}, with R = C_q(q_n)^T (GGL holds for any R with C_q R
//     invertible; R fixed over the step makes q_{n+1} independent of the Newton path, so
//     modified and full Newton give the same step). R eta is O(h^3) per step. Unlike the
//     index-3 form, the multipliers carry no 1/h^2 amplification of errors, so rho_inf = 1
//     (no numerical damping) stays stable on constrained systems (Arnold & Bruls 2007
//     show the index-3 form's multiplier errors are not damped there).
//   kIndex3: C(q_{n+1}) = 0 enforced directly (Arnold & Bruls 2007 eq. (10)).
//
// Newton iterations on the unknown a_{n+1}: with beta' = (1 - alpha_m)/(beta h^2 (1 -
// alpha_f)) and gamma' = gamma/(beta h), dq'' = beta' dq and dq' = gamma' dq, and the
// iteration matrix, scaled by 1/beta' (Bottasso, Dopico & Trainelli 2008) so that its
// condition does not grow as 1/h^2, is the System's Newton matrix with
//   km = 1, kq = 1/beta', kv = gamma'/beta'
// (plus kq d(C_q^T lambda)/dq and kq d(M(q) a)/dq for bodies whose mass depends on q):
//   S = M + kv Ct + kq Kt,  [S, C_q^T; C_q, 0] [dq; dmu] = -[r / beta'; c],
//   dlambda = beta' dmu,  r = M a + C_q^T lambda - Q,
// with c = C (index 3) or c = (C_q v + C_t) / gamma' (index 2; then the projection update
// deta solves C_q(q_n) C_q(q_n)^T deta = -C + Cdot / gamma', m x m, factored once per
// step: a dense Cholesky up to settings.dense_projection_rows rows, a sparse LDL^T beyond;
// and q_{n+1} gains R deta).
//
// Convergence (what the step solves for, not only positions): the Newton updates of the
// accelerations, of the multipliers and of the projection are measured against
//   tolerance x (the largest |q''| of the run, at least the initial max_i |Q_i|/M_ii),
//   tolerance x (the largest |lambda| of the run, at least the initial largest force),
//     except the multipliers of rows that hold a body by themselves (Dae::reaction_only_rows:
//     a vessel on an imposed motion): no other unknown of the step depends on them (they
//     enter that body's equations alone, which then constrain nothing else), and with a
//     heavy hull they would set the iterations (its inertia force changes by 1e5 N per step
//     against a tolerance of 0.05 N); they converge with the rest, to within the last
//     update times the contraction rate,
//   tolerance x (the smaller of the model's size, its largest initial coordinate but at
//     least 1 m, and its shortest element, Dae::length_scale(): a projection left at
//     tolerance x 300 m on a 0.3 m element is a strain error of 1e3 tolerance),
// and the error left after an update is estimated as theta/(1 - theta) times the update
// with the observed contraction rate theta (Hairer & Wanner, Solving ODEs II, sec. IV.8).
// Measuring accelerations keeps the velocity error per step below h tolerance x q''
// whatever h is: a position criterion lets the velocity error grow as 1/h.
// Local error estimate (for the adaptive step control, simulation/simulation.hpp):
// Zienkiewicz & Xie (1991), "A simple error estimator and adaptive time stepping procedure
// for dynamic analysis", Earthquake Eng. Struct. Dyn. 20:871-887, compare Newmark's
// positions with the Taylor series whose third derivative is the difference quotient of
// the accelerations,
//   q(t_n + h) ~ q_n + h v_n + h^2/2 a_n + h^2/6 (a_{n+1} - a_n),
// which gives e = (beta - 1/6) h^2 (a_{n+1} - a_n) for Newmark (abar = a). With the abar of
// generalized-alpha in the position update above, the same comparison reads
//   e = h^2 [(1/2 - beta) abar_n + beta abar_{n+1} - a_n/3 - a_{n+1}/6],
// which is Zienkiewicz & Xie's estimate when abar = a, and for a smooth motion equals
// h^3 q^(3) (beta + (alpha_m - alpha_f)/2 - 1/6) + O(h^4), because abar_n =
// a(t_n + (alpha_m - alpha_f) h) + O(h^2) (Arnold & Bruls 2007 sec. 3): the leading local
// error of the positions. It is exactly zero for a constant acceleration (a free fall) and
// large at a sudden change of the acceleration (an impact, a line going taut), which is
// what the step control must resolve.
// Modified Newton keeps a factorization across iterations and steps while the observed
// contraction rate stays below settings.refresh_rate, and refactors at the current
// iterate otherwise (the rate policy of Hairer & Wanner sec. IV.8 for simplified Newton).
// A matrix from an earlier step contracts unevenly (the first update removes the
// predictor's error, later ones the matrix's), so one rate observed within the step is not
// trusted alone: the second update is judged with the larger of its rate and the last rate
// of the previous step raised to the power 0.8 (the FACCON of Hairer & Wanner's RADAU5,
// sec. IV.8), which lets a smooth motion converge in two iterations. A new matrix has no
// rate of its own yet. RADAU5 keeps FACCON across its Jacobian updates, but the last rate
// of the matrix being replaced is that of a matrix too old (docs/performance.md, fifth
// session: 2.40 iterations per step). Here a new matrix starts from a stored rate: the
// last rate of the latest first step on a matrix (the step after its factorization) that
// took three or more iterations, at the same step length: how a matrix one step old
// contracts. It is used for at most kRateReuses = 8 new matrices in a row; the next one
// starts without a rate, so that its first step measures it again, and so does a matrix
// factored at a restart from the coasting predictor (a hard step) or after a rejected
// step. Without a stored rate every refactorization cost a third iteration in the next
// step (storm_n100, the 3-hour storm: 2.55 -> 2.43 iterations per step, docs/
// performance.md "A new matrix starts from a stored rate").
// Predictor: a_{n+1} and lambda_{n+1} extrapolated linearly from the last two steps,
//   a_{n+1} ~ a_n + (h / h_{n-1}) (a_n - a_{n-1})   (and the same for lambda),
// whose error is O(h^2) against O(h) for the last step's values; an imposed vessel motion
// changes the multipliers of a heavy hull by far more per step than anything else.
// With the index-2 form the predicted velocities are then projected onto C_q v + C_t = 0
// and the positions onto C = 0 along R (one evaluation of the constraints and their
// Jacobian alone, C at the projected positions then to first order, two solves with the
// projection's C_q C_q^T): otherwise the first update's projection moves
// the constrained points by Cdot / gamma' after the forces were evaluated, and the second
// update spends itself on the forces that move brings (on the storm riser's top, 1e4 times
// the tolerance: 3.24 -> 3.02 iterations and 772 -> 312 factorizations in 3000 steps). The
// step's solution is unchanged: the same equations, with R eta still in the range of R.
#pragma once

#include <limits>
#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/SparseCholesky>

#include "seaflex/integrators/integrator.hpp"
#include "seaflex/solvers/kkt_solver.hpp"

namespace seaflex {

enum class NewtonMode { kFull, kModified };
enum class ConstraintLevel { kStabilizedIndex2, kIndex3 };

struct GeneralizedAlphaSettings {
  double alpha_m = 0.0;
  double alpha_f = 0.0;
  double gamma = 0.5;
  double beta = 0.25;
  NewtonMode newton = NewtonMode::kModified;
  ConstraintLevel constraints = ConstraintLevel::kStabilizedIndex2;
  int max_iterations = 12;  ///< Newton iterations per step before the step fails
  /// on the estimated error of the accelerations, multipliers and positions, relative to
  /// the model's acceleration, force and size scales (see the file header)
  double tolerance = 1e-10;
  /// modified Newton refactors when the updates contract more slowly than this
  double refresh_rate = 0.25;
  LinearSolverKind linear_solver = kDefaultLinearSolver;  ///< backend of the Newton solves
  /// index 2: C_q C_q^T of up to this many constraint rows is summed into a dense m x m
  /// matrix, column by column of C_q (a few entries each), and factored by a dense
  /// Cholesky; beyond, a sparse product and a sparse LDL^T. The same matrix either way;
  /// both report dependent rows on a pivot that is not positive
  Index dense_projection_rows = 64;
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

  /// Local error of the positions: q_{n+1} against the cubic through the step's true
  /// accelerations (Zienkiewicz & Xie 1991, see the file header), O(h^3).
  int local_error_order() const override { return 3; }
  void reject_step() override;

  const GeneralizedAlphaSettings& settings() const { return s_; }
  /// The true acceleration q'' at the last accepted step.
  const VecX& acceleration() const { return a_n_; }
  /// Index 2: the projection's C_q C_q^T as last factored (at the last accepted state).
  MatX projection_matrix() const {
    return projection_is_dense_ ? projection_dense_ : MatX(projection_matrix_);
  }

 private:
  void prepare(const Dae& dae);
  // the iterate a_ for which q_{n+1} = q_n + h v_n (abar_{n+1} = -(1/2 - beta)/beta abar_n)
  void predict_coasting();
  // the parts of abar_{n+1}, q_{n+1}, v_{n+1} that do not depend on a_{n+1}, once per step
  void prepare_iterate(const State& state_n, double h);
  // abar_{n+1}, q_{n+1}, v_{n+1} of the iterate a_ = a_{n+1}, from the state at t_n and the
  // step given to prepare_iterate
  void update_iterate();
  // M a: from the stored constant mass matrix, from eval_ (in_eval: assembled with km = 1
  // alone in the same pass as the forces), or from a mass-only evaluation
  void mass_times(const Dae& dae, const State& state, const VecX& a, bool in_eval, VecX& out);
  bool refactor(const Dae& dae, const State& trial, double h);
  // C_q at the step's start and the factorization of C_q C_q^T (index 2)
  /// Index 2: the predictor's velocities and positions projected onto the constraints
  /// (a_per_v = beta'/gamma', the acceleration change per velocity change; q_per_a = 1/beta',
  /// the position change per acceleration change).
  void project_predictor(const Dae& dae, double a_per_v, double q_per_a);
  void prepare_projection(const Dae& dae, const State& state);
  // eta_ = (C_q C_q^T)^-1 rhs with the factors prepare_projection made (an expression:
  // written into eta_ and solved there, no temporary per iteration)
  template <class Rhs>
  void solve_projection(const Eigen::MatrixBase<Rhs>& rhs) {
    if (projection_is_dense_)
      eta_ = projection_dense_solver_.solve(rhs);
    else
      eta_ = projection_solver_.solve(rhs);
  }

  GeneralizedAlphaSettings s_;
  bool prepared_ = false;
  bool started_ = false;
  bool constant_mass_ = false;
  bool product_ = false;  // the Dae forms M(q) a without the matrix (Dae::supports_product)
  Index n_ = 0, m_ = 0;
  double q_scale_ = 1.0;                                           // the model's size (m)
  double length_scale_ = std::numeric_limits<double>::infinity();  // its shortest element (m)
  double a_scale_ = 0.0;  // the largest acceleration seen (m/s^2)
  double f_scale_ = 0.0;  // the largest multiplier or force seen (N)
  // the multiplier rows measured for convergence (Dae::reaction_only_rows left out)
  std::vector<Index> measured_rows_;
  bool all_rows_measured_ = true;
  DaeEval eval_, mass_eval_;
  SpMat mass_;                 // M, when constant
  KktSolver newton_solver_;    // the iteration matrix
  KktSolver initial_solver_;   // [M C_q^T; C_q 0] for the initial accelerations
  double factored_h_ = 0.0;    // the step the Newton matrix was factored for (0: none)
  bool refresh_next_ = false;  // the next step starts with a fresh matrix
  State factored_at_;          // the iterate it was factored at (restart: factored again)
  VecX factored_a_;            // and its accelerations (the d(M a)/dq term)
  VecX a_n_, abar_n_, a_, abar_, Ma_, rhs_, sol_;
  // index 2: the projection term R eta of q_{n+1}, R = C_q(q_n)^T, its update, and
  // C_q(q_n) C_q(q_n)^T factored once per step
  VecX corr_, dy_, eta_, predicted_C_;
  VecX abar_base_, q_base_, v_base_;  // prepare_iterate's parts, for its step iterate_h_
  double iterate_h_ = 0.0;
  DaeEval projection_eval_;
  SpMat constraint_jacobian_;
  // C_q C_q^T: up to settings.dense_projection_rows rows summed into projection_dense_ and
  // factored as a dense matrix (no sparse product per step); beyond, the sparse product
  MatX projection_dense_;
  Eigen::LLT<MatX> projection_dense_solver_;
  bool projection_is_dense_ = false;
  SpMat projection_matrix_;
  Eigen::SimplicialLDLT<SpMat> projection_solver_;
  bool projection_analyzed_ = false;
  bool projection_ready_ = false;  // factored for the current state
  // the time the projection's C_q was formed at: the end of the last step, state.t + h, which
  // may differ in its last bit from the time the simulation then gives the state (its own
  // count of steps); a checkpoint carries it, so that a restart forms the same C_q
  double projection_t_ = std::numeric_limits<double>::quiet_NaN();
  double restored_projection_t_ = std::numeric_limits<double>::quiet_NaN();
  State trial_;
  std::string failure_;
  // the memory before the last successful step, for reject_step()
  VecX a_prev_, abar_prev_;
  double a_scale_prev_ = 0.0, f_scale_prev_ = 0.0;
  bool refresh_prev_ = false;
  // the predictor's memory: the last step's length (0: none, no extrapolation), the
  // accelerations and multipliers before it, and its last contraction rate (0: none)
  double h_last_ = 0.0;
  VecX a_before_, lambda_before_;
  double carried_theta_ = 0.0;
  // the stored rate: the last rate of the last first step on a matrix that took three or
  // more iterations (0: none), the step length it was measured at, the steps completed on
  // the current matrix, and the new matrices that have started from the stored rate since
  // it was measured (see the file header, "Modified Newton")
  double reuse_theta_ = 0.0;
  double reuse_h_ = 0.0;
  long steps_on_matrix_ = 0;
  int rate_reuses_ = 0;
};

}  // namespace seaflex
