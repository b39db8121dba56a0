// Rotations for rigid bodies and markers.
// - Euler parameters p = (e0, e1, e2, e3), |p| = 1 (Nikravesh 1988, ch. 6; Haug 1989,
//   ch. 9): A(p), G(p), Gbar(p) with omega = 2 G p', omega' = 2 Gbar p' (body axes).
//   Every entry of A(p) is a quadratic form p^T Q_ij p, so a body-fixed vector
//   A(p) u has exact first and second derivatives (rotation_quadratic_forms).
// - Roll, pitch, yaw (offshore convention): A = Rz(yaw) Ry(pitch) Rx(roll), i.e. yaw
//   about the global z, then pitch about the new y, then roll about the new x.
// - Thesis eq. (136): Z-X-Z Euler angles, A = Rz(phi) Rx(theta) Rz(psi).
#pragma once

#include <array>

#include "seaflex/core/types.hpp"

namespace seaflex::math {

using Vec4 = Eigen::Vector4d;
using Mat4 = Eigen::Matrix4d;
using Mat34 = Eigen::Matrix<double, 3, 4>;

/// Cross-product matrix: skew(a) b = a x b.
Mat3 skew(const Vec3& a);

/// A(p) = (2 e0^2 - 1) I + 2 (e e^T + e0 e~) for unit p, written as the homogeneous
/// quadratic form that equals |p|^2 times a rotation for any p.
Mat3 rotation_from_euler_parameters(const Vec4& p);
/// Unit Euler parameters of a rotation matrix (Shepperd's method), e0 >= 0.
Vec4 euler_parameters_from_rotation(const Mat3& A);
/// G(p) = [-e, e~ + e0 I]: omega (world axes) = 2 G p' (Haug's G; Nikravesh writes its
/// columns in another order of signs).
Mat34 euler_g(const Vec4& p);
/// Gbar(p) = [-e, -e~ + e0 I]: omega' (body axes) = 2 Gbar p'.
Mat34 euler_gbar(const Vec4& p);

/// S_i(u) with (A(p) u)_i = p^T S_i p for every p (i = 0, 1, 2).
std::array<Mat4, 3> rotation_quadratic_forms(const Vec3& u);

/// A = Rz(yaw) Ry(pitch) Rx(roll), angles in radians.
Mat3 rotation_from_roll_pitch_yaw(double roll, double pitch, double yaw);
/// (roll, pitch, yaw) in radians, pitch in [-pi/2, pi/2]. At pitch = +-90 deg roll and
/// yaw are not unique: yaw is reported as 0 and roll takes the whole rotation.
Vec3 roll_pitch_yaw_from_rotation(const Mat3& A);
/// Thesis eq. (136): A = Rz(phi) Rx(theta) Rz(psi), angles in radians.
Mat3 rotation_from_euler_zxz(double phi, double theta, double psi);

/// A right-handed orthonormal frame whose third column is the unit vector along axis
/// (the first column is the most nearly perpendicular global axis, orthogonalized).
Mat3 frame_from_axis(const Vec3& axis);

}  // namespace seaflex::math
