#include "seaflex/forces/point_load.hpp"

#include <stdexcept>

namespace seaflex {

PointLoad::PointLoad(std::string name, std::unique_ptr<Attachment> point, VectorSignal force)
    : Force(std::move(name)), point_(std::move(point)), force_(std::move(force)) {}

void PointLoad::declare_blocks(math::SparseBlockAssembler& matrix) {
  dofs_ = point_->coordinates();
  if (static_cast<int>(dofs_.size()) > kMaxAttachmentCoordinates)
    throw std::logic_error("PointLoad: attachment depends on too many coordinates");
  block_ = dofs_.empty() ? -1 : matrix.declare_block(dofs_, dofs_);
}

void PointLoad::assemble(const State& state, double load_factor, AssemblyTarget& target) const {
  if (dofs_.empty()) return;
  const Vec3 F = load_factor * force_(state.t);
  const Index n = static_cast<Index>(dofs_.size());
  // fixed-capacity storage on the stack: no allocation per evaluation
  Eigen::Matrix<double, 3, Eigen::Dynamic, Eigen::ColMajor, 3, kMaxAttachmentCoordinates> J(3, n);
  point_->jacobian(state, J);
  if (target.forces) {
    for (Index i = 0; i < n; ++i) (*target.forces)[dofs_[i]] += J.col(i).dot(F);  // eq. (126)
  }
  if (target.matrix && target.scales.kq != 0.0) {
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::ColMajor,
                  kMaxAttachmentCoordinates, kMaxAttachmentCoordinates>
        dQ = MatX::Zero(n, n);
    point_->add_force_jacobian(state, F, dQ);
    target.matrix->add(block_, dQ, -target.scales.kq);
  }
}

double PointLoad::potential_energy(const State&) const {
  return 0.0;
}

}  // namespace seaflex
