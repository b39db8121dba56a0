#include "seaflex/elements/ancf_plate_elastic.hpp"

#include <cmath>
#include <stdexcept>

#include "seaflex/math/gauss_legendre.hpp"

namespace seaflex::ancf_plate {

std::string_view to_string(MidplaneModel m) {
  switch (m) {
    case MidplaneModel::kExact:
      return "exact";
    case MidplaneModel::kL1:
      return "L1";
    case MidplaneModel::kL3:
      return "L3";
  }
  return "?";
}

std::string_view to_string(TransverseModel m) {
  switch (m) {
    case TransverseModel::kExact:
      return "exact";
    case TransverseModel::kT2:
      return "T2";
    case TransverseModel::kT3:
      return "T3";
  }
  return "?";
}

namespace {

using Mat5 = Eigen::Matrix<double, 5, 5>;
using Mat15 = Eigen::Matrix<double, 15, 15>;
using Mat35 = Eigen::Matrix<double, 3, 5>;
using Mat6 = Eigen::Matrix<double, 6, 6>;
using Mat36 = Eigen::Matrix<double, 3, 6>;

Mat3 skew(const Vec3& v) {
  Mat3 S;
  S << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return S;
}

void add_to(Vec48& Q, const Mat316& F, double scale) {
  Eigen::Map<Mat316>(Q.data()) += scale * F;
}

// K(3i + al, 3j + be) += w sum_kl G(i, k) H(3k + al, 3l + be) G(j, l) over the first nv
// point variables: the chain rule from the 3-vectors r_1, r_2, r_11, r_22, r_12 of one
// quadrature point to the 48 element coordinates (each is R times a column of G)
void add_point_hessian(const Eigen::Matrix<double, 16, 5>& G, const Mat15& H, int nv, double w,
                       Mat48& K) {
  for (int al = 0; al < 3; ++al)
    for (int be = 0; be < 3; ++be) {
      Mat5 Hs = Mat5::Zero();
      for (int k = 0; k < nv; ++k)
        for (int l = 0; l < nv; ++l) Hs(k, l) = H(3 * k + al, 3 * l + be);
      const Mat16 T = G.leftCols(nv) * Hs.topLeftCorner(nv, nv) * G.leftCols(nv).transpose();
      for (int j = 0; j < 16; ++j)
        for (int i = 0; i < 16; ++i) K(3 * i + al, 3 * j + be) += w * T(i, j);
    }
}

}  // namespace

PlateElasticity::PlateElasticity(double a, double b, const PlateMaterial& material,
                                 MidplaneModel midplane, TransverseModel transverse,
                                 int gauss_points)
    : a_(a), b_(b), material_(material), midplane_(midplane), transverse_(transverse) {
  if (!(a > 0.0) || !(b > 0.0))
    throw std::invalid_argument("PlateElasticity: edge lengths must be positive");
  const double nu = material.poisson_ratio;
  if (!(material.thickness > 0.0) || !(material.youngs_modulus > 0.0) || !(nu > -1.0) ||
      !(nu < 0.5))
    throw std::invalid_argument("PlateElasticity: invalid thickness, modulus or Poisson ratio");
  C_ = material.membrane_rigidity();
  D_ = material.flexural_rigidity();
  nu_ = nu;
  rule_ = make_rule(gauss_points);
  rule_exact_ = make_rule(7);
  // constant matrices: polynomials of degree <= 6 per direction, exact with 4 points
  S11_.setZero();
  S22_.setZero();
  Sg_.setZero();
  W_.setZero();
  Mat16 A12 = Mat16::Zero();
  for (const Point& p : make_rule(4)) {
    const auto N1 = p.G.col(0), N2 = p.G.col(1), N11 = p.G.col(2), N22 = p.G.col(3),
               N12 = p.G.col(4);
    S11_ += p.w * N1 * N1.transpose();  // thesis eq. (93)
    S22_ += p.w * N2 * N2.transpose();
    Sg_ += p.w * (N1 * N2.transpose() + N2 * N1.transpose());
    A12 += p.w * N1 * N2.transpose();
    // thesis eq. (109-110)
    W_ += p.w * (D_ * (N11 * N11.transpose() + N22 * N22.transpose() +
                       nu_ * (N11 * N22.transpose() + N22 * N11.transpose())) +
                 2.0 * D_ * (1.0 - nu_) * N12 * N12.transpose());
  }
  // mean normals as sum C_mn r_m x r_n, C antisymmetric
  Mat16 C2 = Mat16::Zero();
  for (int c1 = 0; c1 < 2; ++c1)
    for (int c2 = 0; c2 < 2; ++c2)
      C2(column_of(c1, c2, 1), column_of(c1, c2, 2)) += 0.25;  // thesis eq. (102)
  C2_ = 0.5 * (C2 - C2.transpose());
  const Mat16 C3 = A12 / (a_ * b_);  // thesis eq. (112-113)
  C3_ = 0.5 * (C3 - C3.transpose());
}

std::vector<PlateElasticity::Point> PlateElasticity::make_rule(int n) const {
  const math::QuadratureRule q = math::gauss_legendre_unit(n);
  std::vector<Point> rule;
  for (std::size_t i = 0; i < q.points.size(); ++i)
    for (std::size_t j = 0; j < q.points.size(); ++j) {
      const ShapeValues s = shape(q.points[i], q.points[j], a_, b_);
      Point p;
      p.w = q.weights[i] * q.weights[j] * a_ * b_;
      p.G << s.N1, s.N2, s.N11, s.N22, s.N12;
      rule.push_back(p);
    }
  return rule;
}

double PlateElasticity::add_forces(const Vec48& e, Vec48& Q, Mat48* K) const {
  double U = 0.0;
  switch (midplane_) {
    case MidplaneModel::kExact:
      U += add_midplane_exact(e, Q, K);
      break;
    case MidplaneModel::kL1:
      U += add_midplane_l1(e, Q, K);
      break;
    case MidplaneModel::kL3:
      U += add_midplane_l3(e, Q, K);
      break;
  }
  switch (transverse_) {
    case TransverseModel::kExact:
      U += add_transverse_exact(e, Q, K);
      break;
    case TransverseModel::kT2:
      U += add_transverse_t2(e, Q, K);
      break;
    case TransverseModel::kT3:
      U += add_transverse_t3(e, Q, K);
      break;
  }
  return U;
}

double PlateElasticity::add_midplane_exact(const Vec48& e, Vec48& Q, Mat48* K) const {
  return add_midplane_quadrature(rule_, e, Q, K);
}

double PlateElasticity::add_midplane_l3(const Vec48& e, Vec48& Q, Mat48* K) const {
  // thesis eq. (94-97): the same energy integrated exactly (degree 12 per direction)
  return add_midplane_quadrature(rule_exact_, e, Q, K);
}

double PlateElasticity::add_midplane_quadrature(const std::vector<Point>& rule, const Vec48& e,
                                                Vec48& Q, Mat48* K) const {
  const Mat316 R = relative_nodes(e);
  Mat316 F = Mat316::Zero();
  double U = 0.0;
  const double nu = nu_;
  for (const Point& p : rule) {
    const Vec3 r1 = R * p.G.col(0), r2 = R * p.G.col(1);
    // thesis eq. (80)
    const double e11 = 0.5 * (r1.dot(r1) - 1.0), e22 = 0.5 * (r2.dot(r2) - 1.0);
    const double gam = r1.dot(r2);
    const double n11 = C_ * (e11 + nu * e22), n22 = C_ * (e22 + nu * e11);
    const double n12 = 0.5 * C_ * (1.0 - nu) * gam;
    U += 0.5 * p.w * (n11 * e11 + n22 * e22 + n12 * gam);  // thesis eq. (76)
    // dU/dr1 = n11 r1 + n12 r2, dU/dr2 = n22 r2 + n12 r1 (thesis eq. 86-88)
    Mat35 g = Mat35::Zero();
    g.col(0) = n11 * r1 + n12 * r2;
    g.col(1) = n22 * r2 + n12 * r1;
    F.noalias() += p.w * g * p.G.transpose();
    if (K) {
      // H = J^T Cm J + sum n_a d2(eps_a), J rows: d eps11, d eps22, d gam over (r1, r2)
      Eigen::Matrix<double, 6, 1> j11, j22, jg;
      j11 << r1, Vec3::Zero();
      j22 << Vec3::Zero(), r2;
      jg << r2, r1;
      Mat15 H = Mat15::Zero();
      Mat6 H6 = C_ * (j11 * j11.transpose() + j22 * j22.transpose() +
                      nu * (j11 * j22.transpose() + j22 * j11.transpose()) +
                      0.5 * (1.0 - nu) * jg * jg.transpose());
      H6.topLeftCorner<3, 3>().diagonal().array() += n11;
      H6.bottomRightCorner<3, 3>().diagonal().array() += n22;
      H6.topRightCorner<3, 3>().diagonal().array() += n12;
      H6.bottomLeftCorner<3, 3>().diagonal().array() += n12;
      H.topLeftCorner<6, 6>() = H6;
      add_point_hessian(p.G, H, 2, p.w, *K);
    }
  }
  add_to(Q, F, -1.0);
  return U;
}

double PlateElasticity::add_midplane_l1(const Vec48& e, Vec48& Q, Mat48* K) const {
  const Mat316 R = relative_nodes(e);
  const int c00 = column_of(0, 0, 0), ca0 = column_of(1, 0, 0), c0b = column_of(0, 1, 0),
            cab = column_of(1, 1, 0);
  // thesis eq. (90), see the file header: the mean engineering strain of the two chords
  // along each edge direction (the beam's eq. 24 on each edge)
  const Vec3 d1a = R.col(ca0) - R.col(c00), d1b = R.col(cab) - R.col(c0b);
  const Vec3 d2a = R.col(c0b) - R.col(c00), d2b = R.col(cab) - R.col(ca0);
  const double l1a = d1a.norm(), l1b = d1b.norm(), l2a = d2a.norm(), l2b = d2b.norm();
  const double e11 = 0.5 * (l1a + l1b) / a_ - 1.0;
  const double e22 = 0.5 * (l2a + l2b) / b_ - 1.0;
  double e12 = 0.0;
  for (int c1 = 0; c1 < 2; ++c1)
    for (int c2 = 0; c2 < 2; ++c2)
      e12 += 0.125 * R.col(column_of(c1, c2, 1)).dot(R.col(column_of(c1, c2, 2)));
  const double nu = nu_;
  const double n11 = C_ * (e11 + nu * e22), n22 = C_ * (e22 + nu * e11);
  const double n12 = C_ * (1.0 - nu) * e12;  // conjugate to gam = 2 eps12
  // thesis eq. (91-92): Q = -K e, K = sum n_a int S^a dP
  const Mat16 B = n11 * S11_ + n22 * S22_ + n12 * Sg_;
  const Mat316 RB = R * B;
  add_to(Q, RB, -1.0);
  if (K) {
    *K += expand(B);
    // + sum_a vec(R S_a) (d n_a / de)^T, the derivative of the constant strains
    Mat316 de11 = Mat316::Zero(), de22 = Mat316::Zero(), de12 = Mat316::Zero();
    // d|d| = (d / |d|) . dd
    const Vec3 u1a = d1a / (2.0 * a_ * l1a), u1b = d1b / (2.0 * a_ * l1b);
    const Vec3 u2a = d2a / (2.0 * b_ * l2a), u2b = d2b / (2.0 * b_ * l2b);
    de11.col(ca0) += u1a;
    de11.col(c00) -= u1a;
    de11.col(cab) += u1b;
    de11.col(c0b) -= u1b;
    de22.col(c0b) += u2a;
    de22.col(c00) -= u2a;
    de22.col(cab) += u2b;
    de22.col(ca0) -= u2b;
    for (int c1 = 0; c1 < 2; ++c1)
      for (int c2 = 0; c2 < 2; ++c2) {
        const int p1 = column_of(c1, c2, 1), p2 = column_of(c1, c2, 2);
        de12.col(p1) += 0.125 * R.col(p2);
        de12.col(p2) += 0.125 * R.col(p1);
      }
    const Mat316 dn11 = C_ * (de11 + nu * de22), dn22 = C_ * (de22 + nu * de11);
    const Mat316 dn12 = C_ * (1.0 - nu) * de12;
    const Mat316 RS11 = R * S11_, RS22 = R * S22_, RSg = R * Sg_;
    auto vec = [](const Mat316& M) { return Eigen::Map<const Vec48>(M.data()); };
    K->noalias() += vec(RS11) * vec(dn11).transpose();
    K->noalias() += vec(RS22) * vec(dn22).transpose();
    K->noalias() += vec(RSg) * vec(dn12).transpose();
  }
  return 0.5 * a_ * b_ * (n11 * e11 + n22 * e22 + 2.0 * n12 * e12);
}

double PlateElasticity::add_transverse_exact(const Vec48& e, Vec48& Q, Mat48* K) const {
  const Mat316 R = relative_nodes(e);
  Mat316 F = Mat316::Zero();
  double U = 0.0;
  const double D = D_, nu = nu_;
  Mat3 Db;
  Db << D, nu * D, 0.0, nu * D, D, 0.0, 0.0, 0.0, 2.0 * D * (1.0 - nu);
  for (const Point& p : rule_) {
    const Mat35 X = R * p.G;  // r1, r2, r11, r22, r12
    const Vec3 r1 = X.col(0), r2 = X.col(1);
    const Vec3 n = r1.cross(r2);  // thesis eq. (83)
    const double g = n.dot(n);
    const double s = 1.0 / (g * std::sqrt(g));  // 1 / |n|^3
    Vec3 c, kappa;
    for (int ab = 0; ab < 3; ++ab) {
      c[ab] = X.col(2 + ab).dot(n);
      kappa[ab] = c[ab] * s;  // thesis eq. (82)
    }
    const Vec3 M = Db * kappa;
    U += 0.5 * p.w * kappa.dot(M);  // thesis eq. (77)
    // d kappa_ab = s n . dr_ab + m_ab . dn,  m_ab = s r_ab - 3 kappa_ab n / g
    Mat3 m;
    for (int ab = 0; ab < 3; ++ab) m.col(ab) = s * X.col(2 + ab) - (3.0 * kappa[ab] / g) * n;
    const Vec3 mu = m * M;
    Mat35 grad;
    grad.col(0) = r2.cross(mu);  // dn = dr1 x r2 + r1 x dr2
    grad.col(1) = mu.cross(r1);
    for (int ab = 0; ab < 3; ++ab) grad.col(2 + ab) = (M[ab] * s) * n;
    F.noalias() += p.w * grad * p.G.transpose();
    if (!K) continue;
    // Gauss-Newton part: sum_ab,cd d kappa_ab^T Db d kappa_cd
    Eigen::Matrix<double, 3, 15> Gk;
    const Mat3 S1 = skew(r1), S2 = skew(r2);
    for (int ab = 0; ab < 3; ++ab) {
      Gk.block<1, 3>(ab, 0) = r2.cross(m.col(ab)).transpose();
      Gk.block<1, 3>(ab, 3) = m.col(ab).cross(r1).transpose();
      Gk.block<1, 9>(ab, 6).setZero();
      Gk.block<1, 3>(ab, 6 + 3 * ab) = (s * n).transpose();
    }
    Mat15 H = Gk.transpose() * Db * Gk;
    // second derivatives of kappa weighted by the moments
    const double g52 = s / g, g72 = s / (g * g);
    const Vec3 rho = X.rightCols<3>() * M;
    const double sigma = c.dot(M);
    Mat3 Bnn = -3.0 * g52 * (rho * n.transpose() + n * rho.transpose()) +
               15.0 * sigma * g72 * n * n.transpose();
    Bnn.diagonal().array() -= 3.0 * sigma * g52;
    Mat36 Jn;  // dn / d(r1, r2)
    Jn << -S2, S1;
    H.topLeftCorner<6, 6>() += Jn.transpose() * Bnn * Jn;
    const Mat3 Smu = skew(mu);
    H.block<3, 3>(0, 3) -= Smu;
    H.block<3, 3>(3, 0) += Smu;
    Mat3 A = -3.0 * g52 * n * n.transpose();  // d2 kappa / dr_ab dn
    A.diagonal().array() += s;
    const Mat36 AJ = A * Jn;
    for (int ab = 0; ab < 3; ++ab) {
      H.block<3, 6>(6 + 3 * ab, 0) += M[ab] * AJ;
      H.block<6, 3>(0, 6 + 3 * ab) += M[ab] * AJ.transpose();
    }
    add_point_hessian(p.G, H, 5, p.w, *K);
  }
  add_to(Q, F, -1.0);
  return U;
}

double PlateElasticity::add_transverse_t2(const Vec48& e, Vec48& Q, Mat48* K) const {
  return add_transverse_averaged(C2_, e, Q, K);
}

double PlateElasticity::add_transverse_t3(const Vec48& e, Vec48& Q, Mat48* K) const {
  return add_transverse_averaged(C3_, e, Q, K);
}

double PlateElasticity::add_transverse_averaged(const Mat16& Cn, const Vec48& e, Vec48& Q,
                                                Mat48* K) const {
  // U = phi / (2 g^3), phi = n^T R W R^T n, g = n.n, n = sum C_mn r_m x r_n
  // (derivation: docs/theory/ancf_plate.md)
  const Mat316 R = relative_nodes(e);
  const Mat316 V = R * Cn.transpose();  // V_m = sum_n C_mn r_n; dn = sum_k dr_k x 2 V_k
  Vec3 n = Vec3::Zero();
  for (int m = 0; m < 16; ++m) n += R.col(m).cross(V.col(m));  // thesis eq. (102, 112)
  const double g = n.dot(n);
  const Mat316 RW = R * W_;  // rho_k
  const Mat3 P = RW * R.transpose();
  const Vec16 z = RW.transpose() * n;
  const Vec3 Pn = P * n;
  const double phi = n.dot(Pn);
  const double g3 = 1.0 / (g * g * g), g4 = g3 / g, g5 = g4 / g;
  const Vec3 lambda = g3 * Pn - 3.0 * phi * g4 * n;
  // dU/dr_k = g^-3 z_k n + w_k x lambda, w_k = 2 V_k  (thesis eq. 108, 117)
  Mat316 F;
  for (int k = 0; k < 16; ++k) F.col(k) = g3 * z[k] * n + (2.0 * V.col(k)).cross(lambda);
  add_to(Q, F, -1.0);
  if (K) {
    Mat3 Fnn = g3 * P - 6.0 * g4 * (Pn * n.transpose() + n * Pn.transpose()) +
               24.0 * phi * g5 * n * n.transpose();
    Fnn.diagonal().array() -= 3.0 * phi * g4;
    std::array<Mat3, 16> Nk, FRn, A;
    const Mat3 nn = n * n.transpose();
    for (int k = 0; k < 16; ++k) {
      Nk[k] = -skew(2.0 * V.col(k));  // dn / dr_k
      FRn[k] = g3 * n * RW.col(k).transpose() - 6.0 * g4 * z[k] * nn;
      FRn[k].diagonal().array() += g3 * z[k];
      A[k] = FRn[k] + Nk[k].transpose() * Fnn;
    }
    const Mat3 Sl = skew(lambda);
    for (int l = 0; l < 16; ++l)
      for (int k = 0; k < 16; ++k)
        K->block<3, 3>(3 * k, 3 * l) += g3 * W_(k, l) * nn + A[k] * Nk[l] +
                                        Nk[k].transpose() * FRn[l].transpose() -
                                        2.0 * Cn(k, l) * Sl;
  }
  return 0.5 * phi * g3;
}

Vec3 PlateElasticity::midplane_strain(const Vec48& e, double xi1, double xi2) const {
  const ShapeValues s = shape(xi1, xi2, a_, b_);
  const Mat316 R = relative_nodes(e);
  const Vec3 r1 = R * s.N1, r2 = R * s.N2;
  return Vec3(0.5 * (r1.dot(r1) - 1.0), 0.5 * (r2.dot(r2) - 1.0), 0.5 * r1.dot(r2));
}

Vec3 PlateElasticity::curvature(const Vec48& e, double xi1, double xi2) const {
  const ShapeValues s = shape(xi1, xi2, a_, b_);
  const Mat316 R = relative_nodes(e);
  const Vec3 n = (R * s.N1).cross(R * s.N2);
  const double f3 = std::pow(n.norm(), 3);
  return Vec3((R * s.N11).dot(n) / f3, (R * s.N22).dot(n) / f3, (R * s.N12).dot(n) / f3);
}

}  // namespace seaflex::ancf_plate
