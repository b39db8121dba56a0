// A point-mass pendulum in Cartesian coordinates with the nonlinear constraint
// x^2 + z^2 - L^2 = 0, written by hand against the Dae interface: it drives the
// integrators in tests without any element code.
#pragma once

#include <cmath>

#include "seaflex/system/dae.hpp"

namespace seaflex::test_support {

class PendulumDae : public Dae {
 public:
  PendulumDae(double mass, double length, double g) : m_(mass), L_(length), g_(g) {
    pattern_.resize(3, 3);
    const std::vector<Index> q{0, 1}, row{2};
    mass_block_ = pattern_.declare_block(q, q);
    cq_ = pattern_.declare_block(row, q);
    cqt_ = pattern_.declare_block(q, row);
    pattern_.finalize();
  }
  Index num_coordinates() const override { return 2; }
  Index num_constraints() const override { return 1; }
  DaeEval make_eval() const override {
    DaeEval e;
    e.Q = VecX::Zero(2);
    e.C = e.Cdot = e.gamma = VecX::Zero(1);
    e.CqT_lambda = VecX::Zero(2);
    e.kkt = pattern_;
    return e;
  }
  void evaluate(const State& s, const DaeRequest& r, DaeEval& out) const override {
    const double x = s.q[0], z = s.q[1], vx = s.v[0], vz = s.v[1];
    out.Q << 0.0, -m_ * g_ * r.load_factor;
    out.C[0] = x * x + z * z - L_ * L_;
    out.Cdot[0] = 2 * x * vx + 2 * z * vz;
    out.gamma[0] = -2 * (vx * vx + vz * vz);  // thesis eq. (133)
    if (r.reaction_forces) out.CqT_lambda = Vec3(2 * x, 2 * z, 0).head(2) * s.lambda[0];
    if (r.matrix) {
      out.kkt.set_zero();
      // km M + kq d(C_q^T lambda)/dq = (km m + kq 2 lambda) I (Q is constant)
      const double hess = r.multiplier_hessian ? 2.0 * s.lambda[0] * r.scales.kq : 0.0;
      out.kkt.add(mass_block_, (r.scales.km * m_ + hess) * MatX::Identity(2, 2));
      const MatX Cq = (MatX(1, 2) << 2 * x, 2 * z).finished();
      out.kkt.add(cq_, Cq);
      out.kkt.add_transposed(cqt_, Cq);
    }
  }
  bool constant_mass_kkt() const override { return false; }
  bool constant_mass() const override { return true; }
  std::string coordinate_name(Index i) const override { return i == 0 ? "x" : "z"; }
  std::string constraint_name(Index) const override { return "rod"; }

  State start(double theta0) const {
    State s;
    s.q = Vec3(L_ * std::sin(theta0), -L_ * std::cos(theta0), 0).head(2);
    s.v = VecX::Zero(2);
    s.lambda = VecX::Zero(1);
    return s;
  }
  double energy(const State& s) const { return 0.5 * m_ * s.v.squaredNorm() + m_ * g_ * s.q[1]; }

 private:
  double m_, L_, g_;
  math::SparseBlockAssembler pattern_;
  math::BlockId mass_block_, cq_, cqt_;
};

}  // namespace seaflex::test_support
