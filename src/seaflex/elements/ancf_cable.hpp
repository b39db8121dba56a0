// ANCF gradient-deficient cable element: kinematics, mass and external load kernels.
// Thesis section 2.2 (Berzeri & Shabana 2000; Gerstmayr & Shabana 2006).
//
// Symbols (thesis notation):
//   e   = [r0; r0'; rl; rl'] the 12 nodal coordinates (eq. 26)
//   R   = [r0 r0' rl rl'] the same numbers viewed as a 3x4 matrix, column i = node vector i
//   xi  = x / l in [0, 1], l the element's reference (stress-free) length
//   s_i the Hermite functions of eq. (4); r(x) = S(x) e = R s   (eq. 3)
// Every 12x12 matrix of this element is a scalar 4x4 matrix B times the 3x3 identity,
// kron(B, I3); the kernels work with B and R and expand only when writing out.
#pragma once

#include <Eigen/Core>

#include "seaflex/core/types.hpp"

namespace seaflex::ancf_cable {

using Vec4 = Eigen::Vector4d;
using Mat4 = Eigen::Matrix4d;
using Vec12 = Eigen::Matrix<double, 12, 1>;
using Mat12 = Eigen::Matrix<double, 12, 12>;
using Mat34 = Eigen::Matrix<double, 3, 4>;

/// Hermite shape functions s1..s4 at xi (thesis eq. 4).
Vec4 shape(double xi, double l);
/// Their derivatives with respect to the arc-length parameter x (not xi).
Vec4 shape_dx(double xi, double l);
/// Second derivatives with respect to x.
Vec4 shape_dxx(double xi, double l);

/// The 12 coordinates viewed as R = [r0 r0' rl rl'] (a view: e must outlive it).
inline Eigen::Map<const Mat34> as_nodes(const Vec12& e) {
  return Eigen::Map<const Mat34>(e.data());
}
/// No view of a temporary: it would dangle.
Eigen::Map<const Mat34> as_nodes(Vec12&& e) = delete;

/// R with r0 subtracted from both position columns: [0, r0', rl - r0, rl']. Strains and
/// curvatures depend on r' and r'' only, and s1' + s3' = s1'' + s3'' = 0, so every elastic
/// quantity computed from it is exact, and free of the round-off that positions far
/// from the origin would bring into the quadratic forms.
Mat34 relative_nodes(const Vec12& e);

/// kron(B, I3): the 12x12 matrix whose (i, j) 3x3 block is B(i, j) I.
Mat12 expand(const Mat4& B);

/// K += scale kron(a b^T, B): block (i, j) += scale a_i b_j B. The tangent of a load per
/// length f(r, r', r_dot) spread with the shape functions, Q = int S^T f dx: a = S and
/// b = S (for df/dr, df/dr_dot) or b = S_x (for df/dr').
void add_shape_product(Mat12& K, const Vec4& a, const Vec4& b, const Mat3& B, double scale);

/// Consistent mass matrix, rho_A = mass per unit length (kg/m): thesis eq. (10).
Mat12 mass_matrix(double rho_A, double l);

/// Generalized force of a uniform load f (N/m) over the element: (int_0^l S dx)^T f,
/// thesis eq. (127).
Vec12 uniform_load(const Vec3& f, double l);

/// Coordinates of a straight, unstrained element from r0 along the unit direction t.
Vec12 straight(const Vec3& r0, const Vec3& t, double l);

}  // namespace seaflex::ancf_cable
