#include "seaflex/post/plate_results.hpp"

#include <cmath>

namespace seaflex::post {

const std::array<PlateQuantityInfo, kPlateQuantityCount>& plate_quantities() {
  static const std::array<PlateQuantityInfo, kPlateQuantityCount> kInfo = {{
      {"moment_11", "N m/m"},
      {"moment_22", "N m/m"},
      {"moment_12", "N m/m"},
      {"membrane_11", "N/m"},
      {"membrane_22", "N/m"},
      {"membrane_12", "N/m"},
      {"stress_11_top", "Pa"},
      {"stress_22_top", "Pa"},
      {"stress_12_top", "Pa"},
      {"stress_von_mises_top", "Pa"},
      {"stress_11_bottom", "Pa"},
      {"stress_22_bottom", "Pa"},
      {"stress_12_bottom", "Pa"},
      {"stress_von_mises_bottom", "Pa"},
  }};
  return kInfo;
}

void compute_plate_results(const AncfPlate& plate, const State& state, MatX& out) {
  using Q = PlateQuantity;
  const auto& mat = plate.material();
  const double C = mat.membrane_rigidity(), D = mat.flexural_rigidity();
  const double nu = mat.poisson_ratio, h = mat.thickness;
  const double a = plate.a(), b = plate.b();
  // strains and curvatures summed over the elements at each node, then averaged
  MatX sum = MatX::Zero(plate.num_nodes(), 6);  // eps11, eps22, eps12, k11, k22, k12
  VecX count = VecX::Zero(plate.num_nodes());
  for (int ei = 0; ei < plate.nx(); ++ei)
    for (int ej = 0; ej < plate.ny(); ++ej) {
      const ancf_plate::Vec48 e = plate.element_coordinates(state.q, plate.element_number(ei, ej));
      const ancf_plate::Mat316 R = ancf_plate::relative_nodes(e);
      for (int c1 = 0; c1 < 2; ++c1)
        for (int c2 = 0; c2 < 2; ++c2) {
          const ancf_plate::ShapeValues s = ancf_plate::shape(c1, c2, a, b);
          const Vec3 r1 = R * s.N1, r2 = R * s.N2;
          const Vec3 n = r1.cross(r2);
          const double f3 = std::pow(n.norm(), 3);
          const int node = plate.node_number(ei + c1, ej + c2);
          sum(node, 0) += 0.5 * (r1.dot(r1) - 1.0);  // thesis eq. (80)
          sum(node, 1) += 0.5 * (r2.dot(r2) - 1.0);
          sum(node, 2) += 0.5 * r1.dot(r2);
          sum(node, 3) += (R * s.N11).dot(n) / f3;  // thesis eq. (82)
          sum(node, 4) += (R * s.N22).dot(n) / f3;
          sum(node, 5) += (R * s.N12).dot(n) / f3;
          count[node] += 1.0;
        }
    }
  out.resize(plate.num_nodes(), kPlateQuantityCount);
  for (Index k = 0; k < plate.num_nodes(); ++k) {
    const auto v = sum.row(k) / count[k];
    const double m11 = D * (v(3) + nu * v(4)), m22 = D * (v(4) + nu * v(3));
    const double m12 = D * (1.0 - nu) * v(5);
    const double n11 = C * (v(0) + nu * v(1)), n22 = C * (v(1) + nu * v(0));
    const double n12 = C * (1.0 - nu) * v(2);
    auto row = out.row(k);
    row(static_cast<int>(Q::kM11)) = m11;
    row(static_cast<int>(Q::kM22)) = m22;
    row(static_cast<int>(Q::kM12)) = m12;
    row(static_cast<int>(Q::kN11)) = n11;
    row(static_cast<int>(Q::kN22)) = n22;
    row(static_cast<int>(Q::kN12)) = n12;
    // surfaces: membrane plus or minus bending, linear through the thickness
    for (int side = 0; side < 2; ++side) {
      const double sign = side == 0 ? -1.0 : 1.0;  // top (+n side) is compressed by m > 0
      const double s11 = n11 / h + sign * 6.0 * m11 / (h * h);
      const double s22 = n22 / h + sign * 6.0 * m22 / (h * h);
      const double s12 = n12 / h + sign * 6.0 * m12 / (h * h);
      const int base = side == 0 ? static_cast<int>(Q::kS11Top) : static_cast<int>(Q::kS11Bottom);
      row(base) = s11;
      row(base + 1) = s22;
      row(base + 2) = s12;
      row(base + 3) = std::sqrt(s11 * s11 - s11 * s22 + s22 * s22 + 3.0 * s12 * s12);
    }
  }
}

}  // namespace seaflex::post
