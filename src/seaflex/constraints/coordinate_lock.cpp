#include "seaflex/constraints/coordinate_lock.hpp"

#include <stdexcept>

namespace seaflex {

CoordinateLock::CoordinateLock(std::string name, const Body& body, std::vector<Index> locals,
                               std::vector<double> values, std::vector<std::string> labels)
    : Constraint(std::move(name)),
      body_(body),
      locals_(std::move(locals)),
      values_(std::move(values)),
      labels_(std::move(labels)) {
  if (locals_.size() != values_.size() || locals_.size() != labels_.size())
    throw std::invalid_argument("CoordinateLock: locals, values and labels differ in size");
  for (Index i : locals_)
    if (i < 0 || i >= body_.num_coordinates())
      throw std::out_of_range("CoordinateLock: coordinate outside the body");
}

std::vector<Index> CoordinateLock::coordinates() const {
  std::vector<Index> dofs;
  for (Index i : locals_) dofs.push_back(body_.offset() + i);
  return dofs;
}

void CoordinateLock::evaluate(const State& state, ConstraintEval& out) const {
  out.Cq.setZero();
  for (std::size_t r = 0; r < locals_.size(); ++r) {
    out.C[r] = state.q[body_.offset() + locals_[r]] - values_[r];
    out.Cq(r, r) = 1.0;
  }
  out.Ct.setZero();
  out.gamma.setZero();
}

void CoordinateLock::add_multiplier_hessian(const State&, const Eigen::Ref<const VecX>&,
                                            Eigen::Ref<MatX>) const {
  // linear constraint: C_q is constant, d(C_q^T mu)/dq = 0
}

std::string CoordinateLock::row_name(Index row) const {
  return name() + ": " + labels_[row];
}

}  // namespace seaflex
