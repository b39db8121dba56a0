#include "seaflex/forces/plate_pressure.hpp"

#include "seaflex/math/gauss_legendre.hpp"

namespace seaflex {

using ancf_plate::Mat48;
using ancf_plate::Vec48;

namespace {
Mat3 skew(const Vec3& v) {
  Mat3 S;
  S << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return S;
}
}  // namespace

PlatePressure::PlatePressure(std::string name, const AncfPlate& plate, double pressure,
                             TimeSignal factor, std::optional<Vec3> direction)
    : Force(std::move(name)),
      plate_(plate),
      pressure_(pressure),
      factor_(std::move(factor)),
      direction_(direction ? std::optional<Vec3>(direction->normalized()) : std::nullopt) {}

void PlatePressure::declare_blocks(math::SparseBlockAssembler& matrix) {
  blocks_.clear();
  if (direction_) return;  // a fixed-direction load has no tangent
  std::vector<Index> dofs(48);
  for (int el = 0; el < plate_.num_elements(); ++el) {
    for (int k = 0; k < 48; ++k) dofs[k] = plate_.offset() + plate_.element_locals(el)[k];
    blocks_.push_back(matrix.declare_block(dofs, dofs));
  }
}

Vec48 PlatePressure::follower_force(const Vec48& e, double p, double a, double b, Mat48* dQ) {
  static const math::QuadratureRule rule = math::gauss_legendre_unit(5);
  const auto R = ancf_plate::as_nodes(e);
  Vec48 Q = Vec48::Zero();
  Eigen::Map<ancf_plate::Mat316> F(Q.data());
  for (std::size_t i = 0; i < rule.points.size(); ++i)
    for (std::size_t j = 0; j < rule.points.size(); ++j) {
      const double w = rule.weights[i] * rule.weights[j] * a * b * p;
      const ancf_plate::ShapeValues s = ancf_plate::shape(rule.points[i], rule.points[j], a, b);
      const Vec3 r1 = R * s.N1, r2 = R * s.N2;
      F.noalias() += w * r1.cross(r2) * s.N.transpose();  // thesis eq. (126)
      if (!dQ) continue;
      // d(r1 x r2) = -[r2]x dr1 + [r1]x dr2
      const Mat3 S1 = skew(r1), S2 = skew(r2);
      for (int l = 0; l < 16; ++l) {
        const Mat3 D = w * (-s.N1[l] * S2 + s.N2[l] * S1);
        for (int m = 0; m < 16; ++m) dQ->block<3, 3>(3 * m, 3 * l) += s.N[m] * D;
      }
    }
  return Q;
}

void PlatePressure::assemble(const State& state, double load_factor, AssemblyTarget& target) const {
  const double p = load_factor * pressure_ * factor_(state.t);
  const double a = plate_.a(), b = plate_.b();
  if (direction_) {
    if (!target.forces) return;
    const Vec48 Q = ancf_plate::uniform_load(p * *direction_, a, b);  // thesis eq. (128)
    for (int el = 0; el < plate_.num_elements(); ++el)
      for (int k = 0; k < 48; ++k)
        (*target.forces)[plate_.offset() + plate_.element_locals(el)[k]] += Q[k];
    return;
  }
  const bool tangent = target.matrix && target.scales.kq != 0.0;
  Mat48 dQ;
  for (int el = 0; el < plate_.num_elements(); ++el) {
    if (tangent) dQ.setZero();
    const Vec48 Q =
        follower_force(plate_.element_coordinates(state.q, el), p, a, b, tangent ? &dQ : nullptr);
    if (target.forces)
      for (int k = 0; k < 48; ++k)
        (*target.forces)[plate_.offset() + plate_.element_locals(el)[k]] += Q[k];
    if (tangent) target.matrix->add(blocks_[el], dQ, -target.scales.kq);
  }
}

double PlatePressure::potential_energy(const State&) const {
  return 0.0;
}

}  // namespace seaflex
