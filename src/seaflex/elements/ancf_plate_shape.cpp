#include "seaflex/elements/ancf_plate_shape.hpp"

#include "seaflex/elements/ancf_cable.hpp"

namespace seaflex::ancf_plate {

ColumnRole column_role(int c) {
  const int i = c / 4, j = c % 4;  // zero-based thesis indices
  ColumnRole role;
  role.corner1 = i >= 2 ? 1 : 0;
  role.corner2 = j >= 2 ? 1 : 0;
  role.kind = (i % 2) + 2 * (j % 2);
  return role;
}

int column_of(int corner1, int corner2, int kind) {
  const int i = 2 * corner1 + (kind % 2), j = 2 * corner2 + (kind / 2);
  return 4 * i + j;
}

namespace {
// kron of two 4-vectors in the column order c = 4 i + j
Vec16 outer16(const ancf_cable::Vec4& u, const ancf_cable::Vec4& v) {
  Vec16 out;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) out[4 * i + j] = u[i] * v[j];
  return out;
}
}  // namespace

ShapeValues shape(double xi1, double xi2, double a, double b) {
  using ancf_cable::shape_dx;
  using ancf_cable::shape_dxx;
  const auto s1 = ancf_cable::shape(xi1, a), s2 = ancf_cable::shape(xi2, b);
  const auto d1 = shape_dx(xi1, a), d2 = shape_dx(xi2, b);
  const auto dd1 = shape_dxx(xi1, a), dd2 = shape_dxx(xi2, b);
  ShapeValues v;
  v.N = outer16(s1, s2);   // thesis eq. (68)
  v.N1 = outer16(d1, s2);  // thesis eq. (85)
  v.N2 = outer16(s1, d2);
  v.N11 = outer16(dd1, s2);
  v.N22 = outer16(s1, dd2);
  v.N12 = outer16(d1, d2);
  return v;
}

Mat316 relative_nodes(const Vec48& e) {
  Mat316 R = as_nodes(e);
  const Vec3 r0 = R.col(column(1, 1));
  for (int c : {column(1, 3), column(3, 1), column(3, 3)}) R.col(c) -= r0;
  R.col(column(1, 1)).setZero();
  return R;
}

Mat48 expand(const Mat16& B) {
  Mat48 K = Mat48::Zero();
  for (int j = 0; j < 16; ++j)
    for (int i = 0; i < 16; ++i) K.block<3, 3>(3 * i, 3 * j).diagonal().setConstant(B(i, j));
  return K;
}

namespace {
// int_0^l s s^T dx: the scalar core of thesis eq. (10)
ancf_cable::Mat4 beam_core(double l) {
  const ancf_cable::Mat12 M = ancf_cable::mass_matrix(1.0, l);
  ancf_cable::Mat4 B;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) B(i, j) = M(3 * i, 3 * j);
  return B;
}
}  // namespace

Mat16 mass_core(double a, double b) {
  // thesis eq. (74): M_ijkl = int s_i s_k dp1 * int s_j s_l dp2
  const ancf_cable::Mat4 A = beam_core(a), B = beam_core(b);
  Mat16 M;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 4; ++k)
        for (int l = 0; l < 4; ++l) M(4 * i + j, 4 * k + l) = A(i, k) * B(j, l);
  return M;
}

Mat48 mass_matrix(double mu, double a, double b) {
  return expand(mu * mass_core(a, b));  // thesis eq. (70-73)
}

Vec16 load_weights(double a, double b) {
  // thesis eq. (128): int s dx = [l/2, l^2/12, l/2, -l^2/12] in each direction
  const ancf_cable::Vec4 wa(a / 2.0, a * a / 12.0, a / 2.0, -a * a / 12.0);
  const ancf_cable::Vec4 wb(b / 2.0, b * b / 12.0, b / 2.0, -b * b / 12.0);
  return outer16(wa, wb);
}

Vec48 uniform_load(const Vec3& f, double a, double b) {
  const Vec16 w = load_weights(a, b);
  Vec48 Q;
  for (int c = 0; c < 16; ++c) Q.segment<3>(3 * c) = w[c] * f;  // thesis eq. (126)
  return Q;
}

Vec48 flat(const Vec3& r0, const Vec3& t1, const Vec3& t2, double a, double b) {
  Vec48 e = Vec48::Zero();
  for (int c1 = 0; c1 < 2; ++c1)
    for (int c2 = 0; c2 < 2; ++c2) {
      e.segment<3>(3 * column_of(c1, c2, 0)) = r0 + c1 * a * t1 + c2 * b * t2;
      e.segment<3>(3 * column_of(c1, c2, 1)) = t1;
      e.segment<3>(3 * column_of(c1, c2, 2)) = t2;
    }
  return e;
}

}  // namespace seaflex::ancf_plate
