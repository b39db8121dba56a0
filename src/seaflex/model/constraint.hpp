// A kinematic constraint C(q, t) = 0 with rows, the coordinates it touches, its
// Jacobian C_q, C_t and the acceleration right-hand side gamma of thesis eq. (133):
//   C_q q'' = gamma = -(C_q q')_q q' - 2 C_qt q' - C_tt.
#pragma once

#include <string>
#include <vector>

#include "seaflex/model/channel.hpp"
#include "seaflex/model/state.hpp"

namespace seaflex {

/// Buffers a constraint fills; sized once by the System (rows x touched coordinates).
struct ConstraintEval {
  VecX C;      ///< residual
  MatX Cq;     ///< dC/dq on the touched coordinates
  VecX Ct;     ///< dC/dt
  VecX gamma;  ///< acceleration right-hand side (eq. 133)
};

class Constraint {
 public:
  explicit Constraint(std::string name) : name_(std::move(name)) {}
  virtual ~Constraint() = default;
  Constraint(const Constraint&) = delete;
  Constraint& operator=(const Constraint&) = delete;

  const std::string& name() const { return name_; }

  virtual Index num_rows() const = 0;
  /// Global coordinates the constraint touches (valid after numbering).
  virtual std::vector<Index> coordinates() const = 0;
  /// True when C_q is constant (lets integrators factor the KKT matrix once).
  virtual bool is_linear() const = 0;

  virtual void evaluate(const State& state, ConstraintEval& out) const = 0;

  /// H += d(C_q^T mu)/dq for multipliers mu of this constraint's rows (touched x touched).
  /// Needed by Newton's method; zero for linear constraints.
  virtual void add_multiplier_hessian(const State& state, const Eigen::Ref<const VecX>& mu,
                                      Eigen::Ref<MatX> H) const = 0;

  /// Name of a row for messages, e.g. "support beam.n0: x".
  virtual std::string row_name(Index row) const = 0;

  /// Appends output channels (reactions from the multipliers state.lambda, whose rows
  /// for this constraint start at row_offset); none by default.
  virtual void add_channels(ChannelList& /*channels*/, Index /*row_offset*/) const {}

 private:
  std::string name_;
};

}  // namespace seaflex
