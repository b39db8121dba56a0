#include "seaflex/elements/ancf_cable.hpp"

namespace seaflex::ancf_cable {

Vec4 shape(double xi, double l) {
  const double x2 = xi * xi, x3 = x2 * xi;
  // thesis eq. (4)
  return Vec4(1.0 - 3.0 * x2 + 2.0 * x3, l * (xi - 2.0 * x2 + x3), 3.0 * x2 - 2.0 * x3,
              l * (x3 - x2));
}

Vec4 shape_dx(double xi, double l) {
  const double x2 = xi * xi;
  // d/dx = (1/l) d/dxi of eq. (4)
  return Vec4((-6.0 * xi + 6.0 * x2) / l, 1.0 - 4.0 * xi + 3.0 * x2, (6.0 * xi - 6.0 * x2) / l,
              3.0 * x2 - 2.0 * xi);
}

void add_shape_product(Mat12& K, const Vec4& a, const Vec4& b, const Mat3& B, double scale) {
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) K.block<3, 3>(3 * i, 3 * j) += (scale * a[i] * b[j]) * B;
}

Vec4 shape_dxx(double xi, double l) {
  return Vec4((-6.0 + 12.0 * xi) / (l * l), (-4.0 + 6.0 * xi) / l, (6.0 - 12.0 * xi) / (l * l),
              (6.0 * xi - 2.0) / l);
}

Mat34 relative_nodes(const Vec12& e) {
  Mat34 R = as_nodes(e);
  R.col(2) -= R.col(0);
  R.col(0).setZero();
  return R;
}

Mat12 expand(const Mat4& B) {
  Mat12 K = Mat12::Zero();
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) K.block<3, 3>(3 * i, 3 * j).diagonal().setConstant(B(i, j));
  return K;
}

Mat12 mass_matrix(double rho_A, double l) {
  // thesis eq. (10)
  const double l2 = l * l;
  Mat4 B;
  B << 13.0 / 35.0, 11.0 * l / 210.0, 9.0 / 70.0, -13.0 * l / 420.0,  //
      11.0 * l / 210.0, l2 / 105.0, 13.0 * l / 420.0, -l2 / 140.0,    //
      9.0 / 70.0, 13.0 * l / 420.0, 13.0 / 35.0, -11.0 * l / 210.0,   //
      -13.0 * l / 420.0, -l2 / 140.0, -11.0 * l / 210.0, l2 / 105.0;
  return expand(rho_A * l * B);
}

Vec12 uniform_load(const Vec3& f, double l) {
  // thesis eq. (127): int_0^l S dx = [l/2 I, l^2/12 I, l/2 I, -l^2/12 I]
  Vec12 Q;
  Q << 0.5 * l * f, l * l / 12.0 * f, 0.5 * l * f, -l * l / 12.0 * f;
  return Q;
}

Vec12 straight(const Vec3& r0, const Vec3& t, double l) {
  Vec12 e;
  e << r0, t, r0 + l * t, t;
  return e;
}

}  // namespace seaflex::ancf_cable
