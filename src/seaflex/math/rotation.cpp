#include "seaflex/math/rotation.hpp"

#include <algorithm>
#include <cmath>

namespace seaflex::math {

Mat3 skew(const Vec3& a) {
  Mat3 m;
  m << 0.0, -a.z(), a.y(), a.z(), 0.0, -a.x(), -a.y(), a.x(), 0.0;
  return m;
}

Mat3 rotation_from_euler_parameters(const Vec4& p) {
  const double e0 = p[0], e1 = p[1], e2 = p[2], e3 = p[3];
  Mat3 A;
  A << e0 * e0 + e1 * e1 - e2 * e2 - e3 * e3, 2.0 * (e1 * e2 - e0 * e3),
      2.0 * (e1 * e3 + e0 * e2),  //
      2.0 * (e1 * e2 + e0 * e3), e0 * e0 - e1 * e1 + e2 * e2 - e3 * e3,
      2.0 * (e2 * e3 - e0 * e1),  //
      2.0 * (e1 * e3 - e0 * e2), 2.0 * (e2 * e3 + e0 * e1), e0 * e0 - e1 * e1 - e2 * e2 + e3 * e3;
  return A;
}

Vec4 euler_parameters_from_rotation(const Mat3& A) {
  // Shepperd: pick the largest of 4 e0^2, 4 e1^2, 4 e2^2, 4 e3^2 to divide by
  const double tr = A.trace();
  const Vec4 d(tr, A(0, 0), A(1, 1), A(2, 2));
  Index k = 0;
  d.maxCoeff(&k);
  Vec4 p;
  if (k == 0) {
    const double s = 2.0 * std::sqrt(1.0 + tr);  // 4 e0
    p << 0.25 * s, (A(2, 1) - A(1, 2)) / s, (A(0, 2) - A(2, 0)) / s, (A(1, 0) - A(0, 1)) / s;
  } else if (k == 1) {
    const double s = 2.0 * std::sqrt(1.0 + 2.0 * A(0, 0) - tr);  // 4 e1
    p << (A(2, 1) - A(1, 2)) / s, 0.25 * s, (A(0, 1) + A(1, 0)) / s, (A(0, 2) + A(2, 0)) / s;
  } else if (k == 2) {
    const double s = 2.0 * std::sqrt(1.0 + 2.0 * A(1, 1) - tr);  // 4 e2
    p << (A(0, 2) - A(2, 0)) / s, (A(0, 1) + A(1, 0)) / s, 0.25 * s, (A(1, 2) + A(2, 1)) / s;
  } else {
    const double s = 2.0 * std::sqrt(1.0 + 2.0 * A(2, 2) - tr);  // 4 e3
    p << (A(1, 0) - A(0, 1)) / s, (A(0, 2) + A(2, 0)) / s, (A(1, 2) + A(2, 1)) / s, 0.25 * s;
  }
  if (p[0] < 0.0) p = -p;
  return p.normalized();
}

Mat34 euler_g(const Vec4& p) {
  Mat34 g;
  g << -p[1], p[0], -p[3], p[2],  //
      -p[2], p[3], p[0], -p[1],   //
      -p[3], -p[2], p[1], p[0];
  return g;
}

Mat34 euler_gbar(const Vec4& p) {
  Mat34 g;
  g << -p[1], p[0], p[3], -p[2],  //
      -p[2], -p[3], p[0], p[1],   //
      -p[3], p[2], -p[1], p[0];
  return g;
}

std::array<Mat4, 3> rotation_quadratic_forms(const Vec3& u) {
  // Q_ij with A_ij(p) = p^T Q_ij p, read off rotation_from_euler_parameters
  auto sym = [](Mat4& q, int a, int b, double v) {
    q(a, b) += v;
    if (a != b) q(b, a) += v;
  };
  std::array<std::array<Mat4, 3>, 3> Q;
  for (auto& row : Q)
    for (auto& m : row) m.setZero();
  Q[0][0].diagonal() << 1, 1, -1, -1;
  sym(Q[0][1], 1, 2, 1), sym(Q[0][1], 0, 3, -1);
  sym(Q[0][2], 1, 3, 1), sym(Q[0][2], 0, 2, 1);
  sym(Q[1][0], 1, 2, 1), sym(Q[1][0], 0, 3, 1);
  Q[1][1].diagonal() << 1, -1, 1, -1;
  sym(Q[1][2], 2, 3, 1), sym(Q[1][2], 0, 1, -1);
  sym(Q[2][0], 1, 3, 1), sym(Q[2][0], 0, 2, -1);
  sym(Q[2][1], 2, 3, 1), sym(Q[2][1], 0, 1, 1);
  Q[2][2].diagonal() << 1, -1, -1, 1;
  std::array<Mat4, 3> S;
  for (int i = 0; i < 3; ++i) S[i] = u[0] * Q[i][0] + u[1] * Q[i][1] + u[2] * Q[i][2];
  return S;
}

Mat3 rotation_from_roll_pitch_yaw(double roll, double pitch, double yaw) {
  return (Eigen::AngleAxisd(yaw, Vec3::UnitZ()) * Eigen::AngleAxisd(pitch, Vec3::UnitY()) *
          Eigen::AngleAxisd(roll, Vec3::UnitX()))
      .toRotationMatrix();
}

Vec3 roll_pitch_yaw_from_rotation(const Mat3& A) {
  // atan2 rather than asin(-A(2, 0)): asin loses half the digits near +-90 deg
  const double pitch = std::atan2(-A(2, 0), std::hypot(A(2, 1), A(2, 2)));
  if (std::abs(A(2, 0)) > 1.0 - 1e-12) {
    // gimbal lock: only roll -+ yaw is defined; report it all as roll
    return {std::atan2(-A(1, 2), A(1, 1)), pitch, 0.0};
  }
  return {std::atan2(A(2, 1), A(2, 2)), pitch, std::atan2(A(1, 0), A(0, 0))};
}

Mat3 rotation_from_euler_zxz(double phi, double theta, double psi) {
  return (Eigen::AngleAxisd(phi, Vec3::UnitZ()) * Eigen::AngleAxisd(theta, Vec3::UnitX()) *
          Eigen::AngleAxisd(psi, Vec3::UnitZ()))
      .toRotationMatrix();
}

Mat3 frame_from_axis(const Vec3& axis) {
  const Vec3 z = axis.normalized();
  Index k = 0;
  z.cwiseAbs().minCoeff(&k);
  Vec3 x = Vec3::Unit(k) - z[k] * z;
  x.normalize();
  Mat3 F;
  F.col(0) = x;
  F.col(1) = z.cross(x);
  F.col(2) = z;
  return F;
}

}  // namespace seaflex::math
