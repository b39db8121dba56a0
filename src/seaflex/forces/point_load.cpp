#include "seaflex/forces/point_load.hpp"

#include <stdexcept>

#include "seaflex/math/rotation.hpp"

namespace seaflex {

PointLoad::PointLoad(std::string name, std::unique_ptr<Marker> point, VectorSignal force,
                     std::optional<VectorSignal> moment)
    : Force(std::move(name)),
      point_(std::move(point)),
      force_(std::move(force)),
      moment_(std::move(moment)) {}

void PointLoad::declare_blocks(math::SparseBlockAssembler& matrix) {
  dofs_ = point_->coordinates();
  if (static_cast<int>(dofs_.size()) > kMaxMarkerCoordinates)
    throw std::logic_error("PointLoad: marker depends on too many coordinates");
  block_ = dofs_.empty() ? -1 : matrix.declare_block(dofs_, dofs_);
}

void PointLoad::assemble(const State& state, double load_factor, AssemblyTarget& target) const {
  if (dofs_.empty()) return;
  const Index n = static_cast<Index>(dofs_.size());
  const bool tangent = target.matrix && target.scales.kq != 0.0;
  // fixed-capacity storage on the stack: no allocation per evaluation
  Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, kMaxMarkerCoordinates, 1> Q =
      VecX::Zero(n);
  MarkerSquare dQ;
  if (tangent) dQ.setZero(n, n);
  MarkerVectorEval e;
  const Vec3 F = load_factor * force_(state.t);
  point_->evaluate(MarkerVector::kPoint, state, e);
  Q += e.J.transpose() * F;  // eq. (126)
  if (tangent) point_->add_hessian(MarkerVector::kPoint, state, F, dQ);
  if (moment_) {
    const Vec3 M = load_factor * (*moment_)(state.t);
    const Mat3 Mx = math::skew(M);
    if (point_->has(MarkerVector::kAxisX)) {
      for (int k = 1; k <= 3; ++k) {
        const auto v = static_cast<MarkerVector>(k);
        point_->evaluate(v, state, e);
        Q += 0.5 * e.J.transpose() * M.cross(e.value);
        if (tangent) {
          point_->add_hessian(v, state, 0.5 * M.cross(e.value), dQ);
          dQ += 0.5 * e.J.transpose() * Mx * e.J;
        }
      }
    } else {
      point_->evaluate(MarkerVector::kAxisZ, state, e);
      const double t2 = e.value.squaredNorm();
      const Vec3 g = M.cross(e.value) / t2;
      Q += e.J.transpose() * g;
      if (tangent) {
        // d g / dt = (M~ - 2 g t^T) / |t|^2; the slope is linear in q (no Hessian term)
        const Mat3 dg = (Mx - 2.0 * g * e.value.transpose()) / t2;
        dQ += e.J.transpose() * dg * e.J;
      }
    }
  }
  if (target.forces)
    for (Index i = 0; i < n; ++i) (*target.forces)[dofs_[i]] += Q[i];
  if (tangent) target.matrix->add(block_, dQ, -target.scales.kq);
}

double PointLoad::potential_energy(const State&) const {
  return 0.0;
}

}  // namespace seaflex
