// The abstract constrained mechanical system that solvers and integrators see:
//   M q'' + C_q^T lambda = Q(q, v, t),   C(q, t) = 0          (thesis eq. 132)
// An integrator never includes a concrete element; a hand-written pendulum can drive
// it in a test.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "seaflex/math/sparse_block_assembler.hpp"
#include "seaflex/model/assembly.hpp"
#include "seaflex/model/constraint.hpp"
#include "seaflex/model/state.hpp"

namespace seaflex {

/// What one evaluation computes.
struct DaeRequest {
  bool forces = true;        ///< Q
  bool constraints = true;   ///< C, Cdot = C_q v + C_t, gamma
  bool matrix = false;       ///< the KKT matrix below
  MatrixScales scales;       ///< km, kq, kv of the top-left block
  double load_factor = 1.0;  ///< scales external loads (static load stepping)
  /// adds kq * d(C_q^T lambda)/dq (state.lambda) to the top-left block (Newton methods)
  bool multiplier_hessian = false;
  /// C_q^T lambda (state.lambda) into DaeEval::CqT_lambda (residuals of implicit methods)
  bool reaction_forces = false;
  /// when not null, adds kq * d(M(q) a)/dq for this a to the top-left block (bodies and
  /// loads whose mass matrix depends on q: rigid bodies, turning added mass)
  const VecX* acceleration = nullptr;
  /// when not null (with matrix; only if Dae::supports_product()), the top-left block is not
  /// stored: DaeEval::product gets (km M - kq dQ/dq - kv dQ/dv) x in its first n entries
  /// instead, from the same element blocks, and the constraint blocks are left out (e.g.
  /// M(q) a with scales {1, 0, 0} without forming M(q))
  const VecX* product_with = nullptr;
  /// C_q alone into DaeEval::Cq (m x n), without the KKT matrix (only if
  /// Dae::supports_constraint_jacobian(); e.g. a projection's directions C_q^T)
  bool constraint_jacobian = false;
};

/// Results and workspace of evaluations; allocated once by Dae::make_eval().
/// kkt = [km M - kq dQ/dq - kv dQ/dv (+ kq d(C_q^T lambda)/dq),  C_q^T;  C_q,  0]
struct DaeEval {
  VecX Q;
  VecX C;
  VecX Cdot;
  VecX gamma;
  VecX CqT_lambda;  ///< C_q^T lambda, when DaeRequest::reaction_forces
  VecX product;     ///< n + m: the top-left block times DaeRequest::product_with, first n
  VecX product_x;   ///< n + m: workspace, product_with and zeros
  math::SparseBlockAssembler kkt;
  math::SparseBlockAssembler Cq;  ///< m x n: C_q, when DaeRequest::constraint_jacobian
  std::vector<ConstraintEval> constraint_buffers;
  std::vector<MatX> hessian_buffers;
};

class Dae {
 public:
  virtual ~Dae() = default;
  virtual Index num_coordinates() const = 0;
  virtual Index num_constraints() const = 0;
  virtual DaeEval make_eval() const = 0;
  virtual void evaluate(const State& state, const DaeRequest& request, DaeEval& out) const = 0;
  /// True when M is constant and C_q is constant, so the KKT matrix with km = 1,
  /// kq = kv = 0 never changes.
  virtual bool constant_mass_kkt() const = 0;
  /// True when M does not depend on the state (constraints may be nonlinear); false is
  /// always safe.
  virtual bool constant_mass() const { return false; }
  /// True when evaluate() honours DaeRequest::product_with.
  virtual bool supports_product() const { return false; }
  /// True when evaluate() honours DaeRequest::constraint_jacobian.
  virtual bool supports_constraint_jacobian() const { return false; }
  /// Names for messages: "beam.n3.r'.z", "support beam.n0: x".
  virtual std::string coordinate_name(Index i) const = 0;
  virtual std::string constraint_name(Index row) const = 0;
  /// Largest fraction (<= 1) of a Newton update dq that keeps every body within its safe
  /// step (a rigid body's attitude turns by at most about 30 degrees); 1 by default.
  virtual double step_scale(const State& /*state*/, const VecX& /*dq*/) const { return 1.0; }
  /// The shortest length over which coordinates are differenced into strains (m), the
  /// smallest Body::length_scale(); +inf when no body has one.
  virtual double length_scale() const { return std::numeric_limits<double>::infinity(); }
  /// Constraint rows whose multipliers are outputs only: the rows of a body that touch that
  /// body alone and are as many as its coordinates (a vessel on an imposed motion, a body
  /// fixed to the ground), so that they fix its coordinates by themselves. Their multipliers
  /// appear in that body's equations of motion alone, and those equations, whatever the
  /// multipliers, constrain nothing else: the other unknowns of a Newton step do not depend
  /// on them (generalized-alpha leaves them out of its convergence measure). Ascending.
  virtual std::vector<Index> reaction_only_rows() const { return {}; }
  /// Forces with memory: start(state) once before a time simulation, accept_step(state)
  /// after every accepted step (DESIGN: memory enters only through z or accept_step).
  virtual void start(const State& /*state*/) {}
  virtual void accept_step(const State& /*state*/) {}
};

}  // namespace seaflex
