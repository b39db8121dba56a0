#include "seaflex/elements/ancf_cable_elastic.hpp"

#include <cmath>
#include <iterator>
#include <stdexcept>

#include "seaflex/math/gauss_legendre.hpp"

namespace seaflex::ancf_cable {

std::string_view to_string(AxialModel m) {
  switch (m) {
    case AxialModel::kExact:
      return "exact";
    case AxialModel::kL1:
      return "L1";
    case AxialModel::kL2:
      return "L2";
  }
  return "?";
}

std::string_view to_string(BendingModel m) {
  switch (m) {
    case BendingModel::kExact:
      return "exact";
    case BendingModel::kExactDeformed:
      return "exact_deformed";
    case BendingModel::kT1:
      return "T1";
    case BendingModel::kT2:
      return "T2";
  }
  return "?";
}

Mat4 axial_matrix(double l) {
  // the 4x4 core of thesis eq. (27): [6/5, l/10, -6/5, l/10; ...] / l
  const double l2 = l * l;
  Mat4 B;
  B << 6.0 / 5.0, l / 10.0, -6.0 / 5.0, l / 10.0,        //
      l / 10.0, 2.0 * l2 / 15.0, -l / 10.0, -l2 / 30.0,  //
      -6.0 / 5.0, -l / 10.0, 6.0 / 5.0, -l / 10.0,       //
      l / 10.0, -l2 / 30.0, -l / 10.0, 2.0 * l2 / 15.0;
  return B / l;
}

Mat4 bending_matrix(double l) {
  // thesis eq. (42) without EI
  const double l2 = l * l, l3 = l2 * l;
  Mat4 B;
  B << 12.0, 6.0 * l, -12.0, 6.0 * l,         //
      6.0 * l, 4.0 * l2, -6.0 * l, 2.0 * l2,  //
      -12.0, -6.0 * l, 12.0, -6.0 * l,        //
      6.0 * l, 2.0 * l2, -6.0 * l, 4.0 * l2;
  return B / l3;
}

namespace {

Mat3 outer(const Vec3& a, const Vec3& b) {
  return a * b.transpose();
}

// adds the 3x4 force matrix F (column i acts on node vector i) into the 12-vector Q
void add_to(Vec12& Q, const Mat34& F, double scale) {
  Eigen::Map<Mat34>(Q.data()) += scale * F;
}

}  // namespace

CableElasticity::CableElasticity(double l, double EA, double EI, AxialModel axial,
                                 BendingModel bending, int gauss_points)
    : l_(l), EA_(EA), EI_(EI), axial_(axial), bending_(bending) {
  if (!(l > 0.0)) throw std::invalid_argument("CableElasticity: length must be positive");
  const math::QuadratureRule rule = math::gauss_legendre_unit(gauss_points);
  for (std::size_t k = 0; k < rule.points.size(); ++k) {
    w_.push_back(rule.weights[k] * l);
    ds_.push_back(shape_dx(rule.points[k], l));
    dds_.push_back(shape_dxx(rule.points[k], l));
  }
  B1_ = axial_matrix(l);
  B2_ = bending_matrix(l);
  // D_ijkm = int s_i' s_j' s_k' s_m' dx: a degree-8 polynomial, integrated exactly by
  // 5 Gauss points (evaluating at points avoids the cancellation of monomial coefficients)
  D_.setZero();
  const math::QuadratureRule exact = math::gauss_legendre_unit(5);
  for (std::size_t q = 0; q < exact.points.size(); ++q) {
    const Vec4 d = shape_dx(exact.points[q], l);
    const Eigen::Matrix<double, 16, 1> dd =
        Eigen::Map<const Eigen::Matrix<double, 16, 1>>(Mat4(d * d.transpose()).data());
    D_ += (exact.weights[q] * l) * dd * dd.transpose();
  }
}

template <int G>
double CableElasticity::add_exact_forces(const Vec12& e, Vec12& Q, int power) const {
  // thesis eq. (11)-(14), (20) at G points at once; the same expressions as add_axial_exact
  // and add_bending_power with f = N u, N = g h - p^2, u = g^-n
  using M3G = Eigen::Matrix<double, 3, G>;
  using RowG = Eigen::Array<double, 1, G>;
  // ds_ and dds_ hold the points' Vec4 contiguously: 4 x G matrices, column k = point k
  const Eigen::Map<const Eigen::Matrix<double, 4, G>> ds(ds_.front().data()),
      dds(dds_.front().data());
  const Eigen::Map<const RowG> w(w_.data());
  const Mat34 R = relative_nodes(e);
  const M3G a = R * ds;   // r' at the points
  const M3G b = R * dds;  // r''
  const RowG g = a.colwise().squaredNorm().array();
  const RowG h = b.colwise().squaredNorm().array();
  const RowG p = a.cwiseProduct(b).colwise().sum().array();
  const RowG eps = 0.5 * (g - 1.0);  // thesis eq. (12)
  const RowG gi = g.inverse();
  const RowG u = power == 3 ? RowG(gi * gi * gi) : RowG(gi * gi);
  const RowG N = g * h - p * p;
  const RowG wb = 0.5 * EI_ * w;
  const double U = 0.5 * EA_ * (w * eps * eps).sum() + (wb * N * u).sum();
  // the coefficients of r' and r'' in the 3 x G matrices that multiply s'^T (Fa) and s''^T
  // (Fb): the axial -EA w eps r' (eq. 20), and add_bending_power's
  // f_a = r' (2 h u - 2 n N u / g) - r'' (2 p u), f_b = r'' (2 g u) - r' (2 p u) times -wb
  const RowG fa_a = -EA_ * w * eps - wb * (2.0 * h * u - (2.0 * power) * N * u * gi);
  const RowG cross = 2.0 * wb * p * u;  // of r'' in Fa and of r' in Fb
  const RowG fb_b = -2.0 * wb * g * u;
  const M3G Fa = a * fa_a.matrix().asDiagonal() + b * cross.matrix().asDiagonal();
  const M3G Fb = b * fb_b.matrix().asDiagonal() + a * cross.matrix().asDiagonal();
  Eigen::Map<Mat34>(Q.data()) += Fa * ds.transpose() + Fb * dds.transpose();
  return U;
}

double CableElasticity::add_forces(const Vec12& e, Vec12& Q, Mat12* K) const {
  if (!K && axial_ == AxialModel::kExact &&
      (bending_ == BendingModel::kExact || bending_ == BendingModel::kExactDeformed)) {
    const int power = bending_ == BendingModel::kExact ? 2 : 3;
    // the fused path for 2 to 8 points, each size compiled on its own
    using Fused = double (CableElasticity::*)(const Vec12&, Vec12&, int) const;
    static constexpr Fused kFused[] = {nullptr,
                                       nullptr,
                                       &CableElasticity::add_exact_forces<2>,
                                       &CableElasticity::add_exact_forces<3>,
                                       &CableElasticity::add_exact_forces<4>,
                                       &CableElasticity::add_exact_forces<5>,
                                       &CableElasticity::add_exact_forces<6>,
                                       &CableElasticity::add_exact_forces<7>,
                                       &CableElasticity::add_exact_forces<8>};
    if (w_.size() < std::size(kFused) && kFused[w_.size()])
      return (this->*kFused[w_.size()])(e, Q, power);
  }
  double U = 0.0;
  switch (axial_) {
    case AxialModel::kExact:
      U += add_axial_exact(e, Q, K);
      break;
    case AxialModel::kL1:
      U += add_axial_l1(e, Q, K);
      break;
    case AxialModel::kL2:
      U += add_axial_l2(e, Q, K);
      break;
  }
  switch (bending_) {
    case BendingModel::kExact:
      U += add_bending_exact(e, Q, K);
      break;
    case BendingModel::kExactDeformed:
      U += add_bending_exact_deformed(e, Q, K);
      break;
    case BendingModel::kT1:
      U += add_bending_t1(e, Q, K);
      break;
    case BendingModel::kT2:
      U += add_bending_t2(e, Q, K);
      break;
  }
  return U;
}

double CableElasticity::add_axial_exact(const Vec12& e, Vec12& Q, Mat12* K) const {
  const Mat34 R = relative_nodes(e);
  double U = 0.0;
  for (std::size_t k = 0; k < w_.size(); ++k) {
    const Vec4& ds = ds_[k];
    const Vec3 a = R * ds;                      // r'
    const double eps = 0.5 * (a.dot(a) - 1.0);  // thesis eq. (12)
    const double w = w_[k] * EA_;
    U += 0.5 * w * eps * eps;  // thesis eq. (11)
    // Q = -EA int eps S'^T r' dx   (thesis eq. 20)
    add_to(Q, a * ds.transpose(), -w * eps);
    if (K) {
      // K = EA int (S'^T r' r'^T S' + eps S'^T S') dx
      const Mat3 block = outer(a, a) + eps * Mat3::Identity();
      for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) K->block<3, 3>(3 * i, 3 * j) += (w * ds[i] * ds[j]) * block;
    }
  }
  return U;
}

double CableElasticity::add_axial_l1(const Vec12& e, Vec12& Q, Mat12* K) const {
  const Mat34 R = relative_nodes(e);
  const Vec3 chord = R.col(2) - R.col(0);
  const double d = chord.norm();     // thesis eq. (25)
  const double eps = (d - l_) / l_;  // thesis eq. (24)
  // Q = -K_l e with K_l = EA eps int S'^T S' dx   (thesis eq. 23, 27)
  const Mat34 RB = R * B1_;
  add_to(Q, RB, -EA_ * eps);
  if (K) {
    *K += EA_ * eps * expand(B1_);
    // d eps / de = (1/l) [-u; 0; u; 0], u = chord / d
    const Vec3 u = chord / d;
    for (int i = 0; i < 4; ++i) {
      K->block<3, 3>(3 * i, 0) -= (EA_ / l_) * outer(RB.col(i), u);
      K->block<3, 3>(3 * i, 6) += (EA_ / l_) * outer(RB.col(i), u);
    }
  }
  return 0.5 * EA_ * eps * eps * l_;
}

double CableElasticity::add_axial_l2(const Vec12& e, Vec12& Q, Mat12* K) const {
  // With G = R^T R (Gram matrix of the node vectors), eps(x) = 1/2 (s'^T G s' - 1) and
  //   Q_k = -EA sum_j P_kj r_j,  P_kj = 1/2 sum_il G_il D_ilkj - 1/2 B1_kj
  // the closed form of thesis eq. (32-35).
  const Mat34 R = relative_nodes(e);
  const Mat4 G = R.transpose() * R;
  const Eigen::Map<const Eigen::Matrix<double, 16, 1>> g(
      G.data());  // G symmetric: order irrelevant
  const Eigen::Matrix<double, 16, 1> DG = D_.transpose() * g;
  const Mat4 P = 0.5 * Eigen::Map<const Mat4>(DG.data()) - 0.5 * B1_;
  add_to(Q, R * P, -EA_);
  if (K) {
    // K_(k,m) = EA [P_km I + sum_jl D_kmjl r_j r_l^T]
    for (int m = 0; m < 4; ++m)
      for (int k = 0; k < 4; ++k) {
        Mat4 E;
        for (int j = 0; j < 4; ++j)
          for (int l = 0; l < 4; ++l) E(j, l) = D_(4 * k + m, 4 * j + l);
        Mat3 block = R * E * R.transpose();
        block.diagonal().array() += P(k, m);
        K->block<3, 3>(3 * k, 3 * m) += EA_ * block;
      }
  }
  // U = EA/8 int (s'^T G s' - 1)^2 dx = EA/8 (G:D:G - 2 G:B1 + l)
  return 0.125 * EA_ * (g.dot(DG) - 2.0 * (G.cwiseProduct(B1_)).sum() + l_);
}

double CableElasticity::add_bending_exact(const Vec12& e, Vec12& Q, Mat12* K) const {
  return add_bending_power(e, Q, K, 2);  // kappa_0 = d theta / dx (Reissner 1972)
}

double CableElasticity::add_bending_exact_deformed(const Vec12& e, Vec12& Q, Mat12* K) const {
  return add_bending_power(e, Q, K, 3);  // thesis eq. (14)
}

double CableElasticity::add_bending_power(const Vec12& e, Vec12& Q, Mat12* K, int power) const {
  // f = kappa^2 = N u with N = |r' x r''|^2 = g h - p^2 and u = g^-n, n = power:
  //   du/da = -2n u/g a,   d2u/da2 = -2n u/g I + 4n(n+1) u/g^2 a a^T
  const Mat34 R = relative_nodes(e);
  const Mat3 I = Mat3::Identity();
  const double n = power;
  double U = 0.0;
  for (std::size_t k = 0; k < w_.size(); ++k) {
    const Vec4& ds = ds_[k];
    const Vec4& dds = dds_[k];
    const Vec3 a = R * ds;   // r'
    const Vec3 b = R * dds;  // r''
    const double g = a.dot(a), h = b.dot(b), p = a.dot(b);
    const double N = g * h - p * p;  // |r' x r''|^2
    double gn = g;
    for (int i = 1; i < power; ++i) gn *= g;
    const double u = 1.0 / gn;
    const double f = N * u;  // kappa^2: eq. (14) squared for n = 3
    const double w = 0.5 * EI_ * w_[k];
    U += w * f;  // thesis eq. (13), over the reference length
    const Vec3 Na = 2.0 * h * a - 2.0 * p * b;
    const Vec3 Nb = 2.0 * g * b - 2.0 * p * a;
    const Vec3 ua = (-2.0 * n * u / g) * a;
    const Vec3 fa = Na * u + N * ua;
    const Vec3 fb = Nb * u;
    add_to(Q, fa * ds.transpose() + fb * dds.transpose(), -w);
    if (K) {
      const Mat3 Naa = 2.0 * h * I - 2.0 * outer(b, b);
      const Mat3 Nab = 4.0 * outer(a, b) - 2.0 * outer(b, a) - 2.0 * p * I;
      const Mat3 Nbb = 2.0 * g * I - 2.0 * outer(a, a);
      const Mat3 uaa = (-2.0 * n * u / g) * I + (4.0 * n * (n + 1.0) * u / (g * g)) * outer(a, a);
      const Mat3 faa = Naa * u + outer(Na, ua) + outer(ua, Na) + N * uaa;
      const Mat3 fab = Nab * u + outer(ua, Nb);
      const Mat3 fbb = Nbb * u;
      for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i)
          K->block<3, 3>(3 * i, 3 * j) +=
              w * (ds[i] * ds[j] * faa + ds[i] * dds[j] * fab + dds[i] * ds[j] * fab.transpose() +
                   dds[i] * dds[j] * fbb);
    }
  }
  return U;
}

double CableElasticity::add_bending_t1(const Vec12& e, Vec12& Q, Mat12* K) const {
  // Q = -K_t e, K_t = EI int S''^T S'' dx   (thesis eq. 41-42)
  const Mat34 R = relative_nodes(e);
  const Mat34 RB = R * B2_;
  add_to(Q, RB, -EI_);
  if (K) *K += EI_ * expand(B2_);
  return 0.5 * EI_ * (R.transpose() * RB).trace();
}

double CableElasticity::add_bending_t2(const Vec12& e, Vec12& Q, Mat12* K) const {
  // U = 1/2 EI X / phi^2 with X = e^T (B2 (x) I) e = l kbar^2 and
  // phi = fbar^2 = (1/l) e^T (B1 (x) I) e   (thesis eq. 53-56)
  const Mat34 R = relative_nodes(e);
  const Mat34 RB2 = R * B2_;
  const Mat34 RB1 = R * B1_ / l_;
  const double X = (R.transpose() * RB2).trace();
  const double phi = (R.transpose() * RB1).trace();
  const double phi2 = phi * phi, phi3 = phi2 * phi, phi4 = phi3 * phi;
  // dU/de = EI [g1 / phi^2 - 2 X g2 / phi^3], g1 = (B2 (x) I) e, g2 = (B1/l (x) I) e
  // the first term is K_t1 e (eq. 58), the second the K_t2 e term (eq. 59)
  add_to(Q, RB2 / phi2 - (2.0 * X / phi3) * RB1, -EI_);
  if (K) {
    const Eigen::Map<const Vec12> g1(RB2.data());
    const Eigen::Map<const Vec12> g2(RB1.data());
    *K += EI_ * (expand(B2_) / phi2 - (4.0 / phi3) * (g1 * g2.transpose() + g2 * g1.transpose()) +
                 (12.0 * X / phi4) * g2 * g2.transpose() - (2.0 * X / phi3) * expand(B1_ / l_));
  }
  return 0.5 * EI_ * X / phi2;
}

double CableElasticity::axial_strain(const Vec12& e, double xi) const {
  const Vec3 a = as_nodes(e) * shape_dx(xi, l_);
  return 0.5 * (a.dot(a) - 1.0);
}

Vec3 CableElasticity::curvature_vector(const Vec12& e, double xi) const {
  const Mat34 R = relative_nodes(e);
  return curvature_vector(Vec3(R * shape_dx(xi, l_)), Vec3(R * shape_dxx(xi, l_)));
}

Vec3 CableElasticity::curvature_vector(const Vec3& rp, const Vec3& rpp) const {
  const double g = rp.dot(rp);
  if (bending_ == BendingModel::kExact) return rp.cross(rpp) / g;  // d theta / dx
  return rp.cross(rpp) / (g * std::sqrt(g));                       // thesis eq. (14)
}

double CableElasticity::curvature(const Vec12& e, double xi) const {
  return curvature_vector(e, xi).norm();
}

}  // namespace seaflex::ancf_cable
