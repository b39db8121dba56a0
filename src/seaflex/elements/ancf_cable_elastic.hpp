// Elastic forces of the ANCF cable element, thesis section 2.2.3, with exact tangents.
//
// Strain energy (eq. 15): U = 1/2 int_0^l (EA eps^2 + EI kappa^2) dx, x the reference
// (unstretched) arc length, where
//   eps   = 1/2 (r'.r' - 1)                              (eq. 12, Green-Lagrange)
//   kappa = |r' x r''| / |r'|^n                          (n = 3: eq. 14; n = 2: below)
// Axial models:
//   kExact  Green-Lagrange strain by Gauss quadrature (the default).
//   kL1     constant strain eps = (d - l)/l from the node distance d (eq. 23-27).
//           Not derived from a potential: its tangent is not symmetric.
//   kL2     the same polynomial as kExact in closed form (eq. 28-35). The thesis's
//           coefficients A..F are garbled in the text; the closed form here is the
//           equivalent constant tensor D_ijkl = int s_i' s_j' s_k' s_l' dx, computed once
//           per length (Gerstmayr & Shabana 2006, Nonlinear Dyn. 45:109-130, sec. 3);
//           the force is then a cubic polynomial in e with no quadrature per evaluation.
//           Its energy carries a round-off floor of about EA l 1e-16 (the closed form
//           subtracts terms of size l), far below any physical strain.
// Bending models:
//   kExact  the curvature per reference length, kappa_0 = |r' x r''| / |r'|^2 = d theta/dx
//           (theta the angle of the tangent; the elastic line of Reissner 1972, ZAMP
//           23:795-804, and of the geometrically exact beam of Simo & Vu-Quoc 1986):
//           kappa_0^2 = (g h - p^2) / g^2, g = r'.r', h = r''.r'', p = r'.r''. Invariant
//           under a uniform scaling of r(x): a pure couple M bends the axis into a circle
//           without stretching it (the default; see docs/theory/ancf_cable.md).
//   kExactDeformed  the thesis's curvature per deformed length, eq. (14):
//           kappa^2 = (g h - p^2) / g^3 (identity |a x b|^2 = |a|^2 |b|^2 - (a.b)^2),
//           integrated over the reference length (eq. 13). Since kappa = kappa_0 / |r'|,
//           stretching lowers the bending energy: a couple M lengthens the axis by the
//           strain eps ~ M^2 / (EI EA). Kept for comparison with the thesis.
//   Both exact models by Gauss quadrature, with one kernel for the power g^-n.
//   kT1     kappa ~ |r''| (eq. 36-42): constant stiffness K_t = EI int S''^T S'' dx.
//   kT2     kappa^2 ~ r''.r'' / fbar^4 with the element-average stretch
//           fbar^2 = (1/l) int r'.r' dx (eq. 51-55). Implemented as the potential
//           U_t = 1/2 e^T K_t e / fbar^4 whose gradient gives K_t1 = K_t / fbar^4
//           (eq. 58) and the K_t2 term of eq. (59) with the factor 2 EI kbar^2/(l fbar^6)
//           that follows from differentiating fbar (eq. 54); eq. (59) itself is
//           garbled in the text. Meant to be used with kL2 (thesis).
// Forces alone (no tangent) of the default models (exact axial with exact or
// exact_deformed bending) with 2 to 8 quadrature points are computed in one pass over the
// points, vectorized across them (r' and r'' of all points as one 3 x 4 by 4 x G product,
// the force as 3 x G by G x 4 products): the same sums as the separate functions, in
// another order (round-off; CableElastic.FusedForcesEqualTheSeparateModels).
// Conventions: add_* functions add the elastic force Q = -dU/de to Q and the tangent
// stiffness K = -dQ/de to K (when K is not null), and return the strain energy.
#pragma once

#include <string_view>
#include <vector>

#include "seaflex/elements/ancf_cable.hpp"

namespace seaflex::ancf_cable {

enum class AxialModel { kExact, kL1, kL2 };
enum class BendingModel { kExact, kExactDeformed, kT1, kT2 };

/// "exact", "L1", "L2"; "exact", "exact_deformed", "T1", "T2". Used by the model loader and
/// reports.
std::string_view to_string(AxialModel m);
std::string_view to_string(BendingModel m);

/// int_0^l s_i' s_j' dx: the 4x4 core of thesis eq. (27) divided by l.
Mat4 axial_matrix(double l);
/// int_0^l s_i'' s_j'' dx: thesis eq. (42) divided by EI.
Mat4 bending_matrix(double l);

/// Everything about one element's elasticity that depends only on its reference length
/// and section: quadrature tables and constant matrices, computed once.
class CableElasticity {
 public:
  /// l: reference length (m); EA (N); EI (N m^2); gauss_points for the quadrature models.
  CableElasticity(double l, double EA, double EI, AxialModel axial, BendingModel bending,
                  int gauss_points = 5);

  /// Adds the forces of the selected axial and bending models; returns the strain energy.
  double add_forces(const Vec12& e, Vec12& Q, Mat12* K) const;

  double add_axial_exact(const Vec12& e, Vec12& Q, Mat12* K) const;
  double add_axial_l1(const Vec12& e, Vec12& Q, Mat12* K) const;
  double add_axial_l2(const Vec12& e, Vec12& Q, Mat12* K) const;
  /// kappa_0 = |r' x r''| / |r'|^2, per reference length (the default exact model).
  double add_bending_exact(const Vec12& e, Vec12& Q, Mat12* K) const;
  /// kappa = |r' x r''| / |r'|^3, per deformed length (thesis eq. 14).
  double add_bending_exact_deformed(const Vec12& e, Vec12& Q, Mat12* K) const;
  double add_bending_t1(const Vec12& e, Vec12& Q, Mat12* K) const;
  double add_bending_t2(const Vec12& e, Vec12& Q, Mat12* K) const;

  /// Green-Lagrange axial strain (eq. 12) at xi, whatever the selected model.
  double axial_strain(const Vec12& e, double xi) const;
  /// Curvature vector r' x r'' / |r'|^n of the selected bending model at xi (1/m): n = 2
  /// (per reference length) for kExact, n = 3 (thesis eq. 14) for kExactDeformed and for
  /// T1 and T2, which approximate eq. (14). EI times it is the bending moment vector.
  Vec3 curvature_vector(const Vec12& e, double xi) const;
  /// The same from r' and r'' at the point (shape_dx and shape_dxx of length() times the
  /// relative nodes), for callers that share them between quantities.
  Vec3 curvature_vector(const Vec3& rp, const Vec3& rpp) const;
  /// |curvature_vector(e, xi)| (1/m).
  double curvature(const Vec12& e, double xi) const;

  double length() const { return l_; }
  AxialModel axial_model() const { return axial_; }
  BendingModel bending_model() const { return bending_; }

 private:
  // the exact bending energy 1/2 EI int |r' x r''|^2 / |r'|^(2 n) dx for n = power
  double add_bending_power(const Vec12& e, Vec12& Q, Mat12* K, int power) const;
  // the exact axial and bending (power n) forces, no tangent, G quadrature points at once
  template <int G>
  double add_exact_forces(const Vec12& e, Vec12& Q, int power) const;

  double l_, EA_, EI_;
  AxialModel axial_;
  BendingModel bending_;
  std::vector<double> w_;            // quadrature weights times l (integrate over x)
  std::vector<Vec4> ds_;             // s_i' at the quadrature points
  std::vector<Vec4> dds_;            // s_i'' at the quadrature points
  Mat4 B1_;                          // int s_i' s_j' dx
  Mat4 B2_;                          // int s_i'' s_j'' dx
  Eigen::Matrix<double, 16, 16> D_;  // D(4i+j, 4k+m) = int s_i' s_j' s_k' s_m' dx
};

}  // namespace seaflex::ancf_cable
