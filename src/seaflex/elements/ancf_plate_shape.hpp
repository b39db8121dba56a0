// ANCF thin plate element (Dmitrochenko & Pogorelov 2003; Yoo et al. 2004), thesis
// section 2.3.1-2.3.2: kinematics, mass and uniform-load kernels.
//
// Symbols (thesis notation):
//   p1 in [0, a], p2 in [0, b]: the plate's material coordinates along its two edges
//   s_i(p1/a; a), s_j(p2/b; b): the beam's Hermite functions of eq. (4)
//   S_ij = s_i(p1) s_j(p2)                                      (eq. 68)
//   e = [e_11; e_12; ...; e_44], 48 numbers, e_ij the 3-vector of S_ij     (eq. 66-67):
//     i = 1, 3: position-type in p1 at p1 = 0, a;  i = 2, 4: d/dp1 at p1 = 0, a
//     j = 1, 3: position-type in p2 at p2 = 0, b;  j = 2, 4: d/dp2 at p2 = 0, b
//   so e_11 = r(0, 0), e_21 = r_p1(0, 0), e_12 = r_p2(0, 0), e_22 = r_p1p2(0, 0),
//   e_31 = r(a, 0), e_13 = r(0, b), e_33 = r(a, b), and so on (eq. 61, 67).
//   R = the 3x16 matrix whose column c = 4 (i - 1) + (j - 1) is e_ij; r(p1, p2) = R N
//   with N_c = S_ij (the 16 scalar shape functions).
// Every 48x48 matrix of the element is kron(B, I3) of a 16x16 scalar matrix B; the
// kernels work with B and R and expand only when writing out (as ancf_cable does).
#pragma once

#include <Eigen/Core>
#include <array>

#include "seaflex/core/types.hpp"

namespace seaflex::ancf_plate {

using Vec16 = Eigen::Matrix<double, 16, 1>;
using Mat16 = Eigen::Matrix<double, 16, 16>;
using Vec48 = Eigen::Matrix<double, 48, 1>;
using Mat48 = Eigen::Matrix<double, 48, 48>;
using Mat316 = Eigen::Matrix<double, 3, 16>;

/// Column of e_ij in R (i, j from 1 to 4, as in the thesis).
constexpr int column(int i, int j) {
  return 4 * (i - 1) + (j - 1);
}

/// Node of the element corner (0: p1 = 0, 1: p1 = a) x (0: p2 = 0, 1: p2 = b) that
/// column c belongs to, and the kind of nodal vector: 0 r, 1 r_p1, 2 r_p2, 3 r_p1p2.
struct ColumnRole {
  int corner1 = 0;  ///< 0 at p1 = 0, 1 at p1 = a
  int corner2 = 0;  ///< 0 at p2 = 0, 1 at p2 = b
  int kind = 0;     ///< 0 r, 1 r_p1, 2 r_p2, 3 r_p1p2
};
ColumnRole column_role(int c);
/// Column of the nodal vector `kind` of corner (corner1, corner2).
int column_of(int corner1, int corner2, int kind);

/// Values and derivatives of the 16 shape functions at a point.
struct ShapeValues {
  Vec16 N;    ///< S_ij
  Vec16 N1;   ///< dS_ij/dp1
  Vec16 N2;   ///< dS_ij/dp2
  Vec16 N11;  ///< d2S_ij/dp1^2
  Vec16 N22;  ///< d2S_ij/dp2^2
  Vec16 N12;  ///< d2S_ij/dp1dp2
};

/// Shape functions at (xi1, xi2) = (p1/a, p2/b) in [0, 1]^2 (thesis eq. 66, 68, 85).
ShapeValues shape(double xi1, double xi2, double a, double b);

/// The 48 coordinates viewed as R (a view: e must outlive it).
inline Eigen::Map<const Mat316> as_nodes(const Vec48& e) {
  return Eigen::Map<const Mat316>(e.data());
}
Eigen::Map<const Mat316> as_nodes(Vec48&& e) = delete;

/// R with r(0, 0) subtracted from the four position columns: every strain and curvature
/// depends on derivatives of r only, and the position-type functions sum to one, so
/// this is exact and avoids round-off from positions far from the origin.
Mat316 relative_nodes(const Vec48& e);

/// kron(B, I3).
Mat48 expand(const Mat16& B);

/// int_0^a int_0^b S_ij S_kl dp1 dp2 (16x16): thesis eq. (74), the product of the beam's
/// one-dimensional integrals, in closed form from eq. (10).
Mat16 mass_core(double a, double b);
/// Consistent mass matrix, mu = mass per area (kg/m^2): M = mu kron(mass_core, I3),
/// thesis eq. (70-74).
Mat48 mass_matrix(double mu, double a, double b);

/// int S_ij dp1 dp2: the 16 weights of thesis eq. (128).
Vec16 load_weights(double a, double b);
/// Generalized force of a uniform load f (N/m^2) over the element (thesis eq. 126, 128).
Vec48 uniform_load(const Vec3& f, double a, double b);

/// Coordinates of a flat unstrained element with corner r0 and unit edge directions t1,
/// t2 (perpendicular).
Vec48 flat(const Vec3& r0, const Vec3& t1, const Vec3& t2, double a, double b);

}  // namespace seaflex::ancf_plate
