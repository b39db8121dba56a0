// Classical fourth-order Runge-Kutta (thesis eq. 178-179) on the augmented (index-1)
// formulation (thesis eq. 132-133): at every stage
//   [M  C_q^T; C_q  0] [q''; lambda] = [Q; gamma_s]
// with gamma_s = gamma - 2 alpha Cdot - beta^2 C under Baumgarte stabilization
// (Baumgarte 1972), or gamma_s = gamma followed by a projection of q and v onto the
// constraint manifold after each step (mass-weighted, Bauchau & Laulusa 2008), which
// keeps the drift at round-off. When M and C_q are constant the KKT matrix is factored
// once for the whole run.
#pragma once

#include "seaflex/integrators/integrator.hpp"
#include "seaflex/solvers/kkt_solver.hpp"

namespace seaflex {

enum class Stabilization { kNone, kBaumgarte, kProjection };

class Rk4Augmented : public Integrator {
 public:
  /// alpha, beta (1/s): Baumgarte parameters, used with kBaumgarte.
  explicit Rk4Augmented(Stabilization stabilization = Stabilization::kProjection,
                        double alpha = 5.0, double beta = 5.0);

  std::string_view name() const override { return "rk4"; }
  StepReport step(const Dae& dae, State& state, double h) override;
  /// RK4 carries nothing from step to step but its factorization, which is rebuilt on
  /// demand (constant when it is reused): a restart only prepares.
  bool save(CheckpointWriter& /*out*/) const override { return true; }
  void restore(const Dae& dae, const CheckpointReader& /*in*/) override {
    if (!prepared_) prepare(dae);
  }
  void update_multipliers(const Dae& dae, State& state) override;
  /// Local error of the positions from an embedded third-order solution, O(h^4)
  /// (rk4_augmented.cpp); RK4 carries no memory, so a rejected step needs nothing undone.
  int local_error_order() const override { return 4; }

  /// Accelerations and multipliers at a state (one augmented solve); used for stages
  /// and for outputs that need lambda.
  void accelerations(const Dae& dae, const State& state, VecX& a, VecX& lambda);
  int factorizations() const { return solver_.factorizations(); }

 private:
  void prepare(const Dae& dae);
  bool factor_at(const Dae& dae, const State& state);
  bool factorize_evaluated();  ///< factors eval_.kkt; sets failure_ when singular
  bool project(const Dae& dae, State& state, double& violation);

  Stabilization stabilization_;
  double alpha_, beta_;
  bool prepared_ = false;
  bool constant_kkt_ = false;
  Index n_ = 0, m_ = 0;
  DaeEval eval_;
  KktSolver solver_;
  State stage_;
  VecX k1q_, k2q_, k3q_, k4q_, k1v_, k2v_, k3v_, k4v_;
  VecX rhs_, sol_, lambda_;
  std::string failure_;
};

}  // namespace seaflex
