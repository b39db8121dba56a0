// Elastic forces of the ANCF cable element, thesis section 2.2.3, with exact tangents.
//
// Strain energy (eq. 15): U = 1/2 int_0^l (EA eps^2 + EI kappa^2) dx, where
//   eps   = 1/2 (r'.r' - 1)                              (eq. 12, Green-Lagrange)
//   kappa = |r' x r''| / |r'|^3                          (eq. 14)
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
//   kExact  kappa^2 = (g h - p^2) / g^3, g = r'.r', h = r''.r'', p = r'.r'' (identity
//           |a x b|^2 = |a|^2 |b|^2 - (a.b)^2 applied to eq. 14), Gauss quadrature.
//   kT1     kappa ~ |r''| (eq. 36-42): constant stiffness K_t = EI int S''^T S'' dx.
//   kT2     kappa^2 ~ r''.r'' / fbar^4 with the element-average stretch
//           fbar^2 = (1/l) int r'.r' dx (eq. 51-55). Implemented as the potential
//           U_t = 1/2 e^T K_t e / fbar^4 whose gradient gives K_t1 = K_t / fbar^4
//           (eq. 58) and the K_t2 term of eq. (59) with the factor 2 EI kbar^2/(l fbar^6)
//           that follows from differentiating fbar (eq. 54); eq. (59) itself is
//           garbled in the text. Meant to be used with kL2 (thesis).
// Conventions: add_* functions add the elastic force Q = -dU/de to Q and the tangent
// stiffness K = -dQ/de to K (when K is not null), and return the strain energy.
#pragma once

#include <string_view>
#include <vector>

#include "seaflex/elements/ancf_cable.hpp"

namespace seaflex::ancf_cable {

enum class AxialModel { kExact, kL1, kL2 };
enum class BendingModel { kExact, kT1, kT2 };

/// "exact", "L1", "L2"; "exact", "T1", "T2". Used by the model loader and reports.
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
  double add_bending_exact(const Vec12& e, Vec12& Q, Mat12* K) const;
  double add_bending_t1(const Vec12& e, Vec12& Q, Mat12* K) const;
  double add_bending_t2(const Vec12& e, Vec12& Q, Mat12* K) const;

  /// Axial strain (eq. 12) and curvature (eq. 14) at xi, whatever the selected model.
  double axial_strain(const Vec12& e, double xi) const;
  double curvature(const Vec12& e, double xi) const;

  double length() const { return l_; }
  AxialModel axial_model() const { return axial_; }
  BendingModel bending_model() const { return bending_; }

 private:
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
