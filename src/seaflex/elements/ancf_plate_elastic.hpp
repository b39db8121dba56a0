// Elastic forces of the ANCF thin plate, thesis section 2.3.3, with exact tangents.
// Derivations and the thesis equations that had to be re-read: docs/theory/ancf_plate.md.
//
// Kirchhoff strain energy of an isotropic plate (thesis eq. 75-79), p1, p2 arc lengths
// of the flat, unstrained reference rectangle (its metric is the identity):
//   U = U_eps + U_kappa
//   U_eps   = int (C/2) [eps11^2 + eps22^2 + 2 nu eps11 eps22 + (1 - nu)/2 gam^2] dP
//   U_kappa = int (D/2) [k11^2 + k22^2 + 2 nu k11 k22 + 2 (1 - nu) k12^2] dP
//   C = E h / (1 - nu^2),  D = E h^3 / (12 (1 - nu^2))
// (eq. 76-79 with D_11 = D_22 = D, D_12 = E h^3 / (12 (1 + nu)), D_1122 = nu D; the
// midplane factor 6/h^2 of eq. 76 turns D into C/2), with
//   eps_ij = 1/2 (r_i . r_j - delta_ij), gam = 2 eps12 = r_1 . r_2       (eq. 80)
//   k_ij = r_ij . n / |n|^3,  n = r_1 x r_2                              (eq. 82-83)
// Midplane models:
//   kExact  eps of eq. (80) at each point, Gauss quadrature with gauss_points^2 points.
//   kL1     strains constant over the element from the corner vectors (eq. 90):
//             eps11 = 1/2 (|r_a0 - r_00| / a + |r_ab - r_0b| / a) - 1
//             eps22 = 1/2 (|r_0b - r_00| / b + |r_ab - r_a0| / b) - 1
//             eps12 = 1/8 sum over the corners of r_p1 . r_p2
//           (the beam's chord strain, eq. 24, averaged over two opposite edges) and
//           Q = -(sum N_ij int S^ij dP) e (eq. 91-93): the constant strains times the
//           gradient of the pointwise strains (eq. 88). Not the gradient of a potential,
//           in the thesis as here: the tangent is not symmetric (docs/theory/ancf_plate.md);
//           the returned energy is that of the constant strains.
//   kL3     the Green-Lagrange strains with no simplification (eq. 94-97): a polynomial
//           energy integrated exactly. The closed form of eq. (95-97) contracts 256x256
//           tensors per evaluation; Gauss quadrature with 7 x 7 points gives the same
//           polynomial integral exactly at a fraction of the cost, and is used.
// Transverse models:
//   kExact  k_ij of eq. (82) at each point, Gauss quadrature.
//   kT2     n replaced by the mean of the normals at the four corners (eq. 102-111).
//   kT3     n replaced by its mean over the element, (1/ab) int r_1 x r_2 dP (eq. 112-119).
//           Both: U = phi / (2 f^6), phi = n^T R W R^T n, f = |n|, W the constant 16x16
//           matrix int [D (S11 S11^T + S22 S22^T + nu (S11 S22^T + S22 S11^T)) +
//           2 D (1 - nu) S12 S12^T] dP (eq. 109-110, 118-119): no quadrature per
//           evaluation. The force is the exact gradient, including the derivative of
//           the mean normal (eq. 104-107, 114-116); the small-deformation shortcut of
//           eq. (111) is not used.
// Conventions: add_* functions add the elastic force Q = -dU/de to Q and the tangent
// K = -dQ/de to K (when K is not null), and return the strain energy.
#pragma once

#include <string_view>
#include <vector>

#include "seaflex/elements/ancf_plate_shape.hpp"

namespace seaflex::ancf_plate {

enum class MidplaneModel { kExact, kL1, kL3 };
enum class TransverseModel { kExact, kT2, kT3 };

/// "exact", "L1", "L3"; "exact", "T2", "T3".
std::string_view to_string(MidplaneModel m);
std::string_view to_string(TransverseModel m);

/// Thickness and isotropic material of a plate. All SI.
struct PlateMaterial {
  double thickness = 0.0;       ///< h (m)
  double youngs_modulus = 0.0;  ///< E (Pa)
  double poisson_ratio = 0.0;   ///< nu, -1 < nu < 0.5
  double density = 0.0;         ///< rho (kg/m^3)

  double membrane_rigidity() const {  ///< C = E h / (1 - nu^2) (N/m)
    return youngs_modulus * thickness / (1.0 - poisson_ratio * poisson_ratio);
  }
  double flexural_rigidity() const {  ///< D = E h^3 / (12 (1 - nu^2)) (N m)
    return membrane_rigidity() * thickness * thickness / 12.0;
  }
  double mass_per_area() const { return density * thickness; }  ///< mu (kg/m^2)
};

/// Everything about one element's elasticity that depends only on its size and
/// material: quadrature tables and constant matrices, computed once.
class PlateElasticity {
 public:
  /// a, b: element edge lengths (m); gauss_points per direction for the exact models.
  PlateElasticity(double a, double b, const PlateMaterial& material, MidplaneModel midplane,
                  TransverseModel transverse, int gauss_points = 5);

  /// Adds the forces of the selected models; returns the strain energy.
  double add_forces(const Vec48& e, Vec48& Q, Mat48* K) const;

  double add_midplane_exact(const Vec48& e, Vec48& Q, Mat48* K) const;
  double add_midplane_l1(const Vec48& e, Vec48& Q, Mat48* K) const;
  double add_midplane_l3(const Vec48& e, Vec48& Q, Mat48* K) const;
  double add_transverse_exact(const Vec48& e, Vec48& Q, Mat48* K) const;
  double add_transverse_t2(const Vec48& e, Vec48& Q, Mat48* K) const;
  double add_transverse_t3(const Vec48& e, Vec48& Q, Mat48* K) const;

  /// Green-Lagrange strains (eps11, eps22, eps12) and curvatures (k11, k22, k12) of
  /// eq. (80, 82) at (xi1, xi2), whatever the selected models.
  Vec3 midplane_strain(const Vec48& e, double xi1, double xi2) const;
  Vec3 curvature(const Vec48& e, double xi1, double xi2) const;

  double a() const { return a_; }
  double b() const { return b_; }
  MidplaneModel midplane_model() const { return midplane_; }
  TransverseModel transverse_model() const { return transverse_; }

 private:
  // quadrature point: weight (times a b) and the shape derivatives as the 16x5 matrix
  // [N1 N2 N11 N22 N12]
  struct Point {
    double w = 0.0;
    Eigen::Matrix<double, 16, 5> G;
  };
  std::vector<Point> make_rule(int n) const;
  double add_midplane_quadrature(const std::vector<Point>& rule, const Vec48& e, Vec48& Q,
                                 Mat48* K) const;
  double add_transverse_averaged(const Mat16& Cn, const Vec48& e, Vec48& Q, Mat48* K) const;

  double a_, b_;
  PlateMaterial material_;
  MidplaneModel midplane_;
  TransverseModel transverse_;
  double C_, D_, nu_;
  std::vector<Point> rule_;        // gauss_points^2 (exact models)
  std::vector<Point> rule_exact_;  // 7 x 7 (L3)
  Mat16 S11_, S22_, Sg_;           // int N1 N1^T, N2 N2^T, N1 N2^T + N2 N1^T (L1, eq. 93)
  Mat16 W_;                        // bending matrix of T2/T3 (eq. 109-110)
  Mat16 C2_, C3_;                  // mean normal n = sum C_mn r_m x r_n (T2, T3)
};

}  // namespace seaflex::ancf_plate
