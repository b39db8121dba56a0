// Holds chosen coordinates of a body at fixed values: C_i = q_k(i) - value_i = 0.
// Serves the beam supports of the model file: a node pinned (r held), clamped (r and
// r' held), or with any subset of its position components held (e.g. x and y, with z
// free so a riser top can slide under a pull). Linear: C_q rows are unit rows, gamma = 0
// (thesis eq. 133 with C_qq = C_qt = C_tt = 0).
#pragma once

#include "seaflex/model/body.hpp"
#include "seaflex/model/constraint.hpp"

namespace seaflex {

class CoordinateLock : public Constraint {
 public:
  /// locals: coordinates of body (local indices) to hold at values; labels name the rows.
  CoordinateLock(std::string name, const Body& body, std::vector<Index> locals,
                 std::vector<double> values, std::vector<std::string> labels);

  Index num_rows() const override { return static_cast<Index>(locals_.size()); }
  std::vector<Index> coordinates() const override;
  bool is_linear() const override { return true; }
  void evaluate(const State& state, ConstraintEval& out) const override;
  void add_multiplier_hessian(const State& state, const Eigen::Ref<const VecX>& mu,
                              Eigen::Ref<MatX> H) const override;
  std::string row_name(Index row) const override;

  /// The body and the local coordinates held, one per row (support reactions read them).
  const Body& body() const { return body_; }
  const std::vector<Index>& locals() const { return locals_; }
  const std::vector<std::string>& labels() const { return labels_; }

 private:
  const Body& body_;
  std::vector<Index> locals_;
  std::vector<double> values_;
  std::vector<std::string> labels_;
};

}  // namespace seaflex
