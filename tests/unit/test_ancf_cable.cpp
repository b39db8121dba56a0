// Kernel identities of the ANCF cable: shape functions, mass matrix (thesis eq. 10) and
// uniform load (eq. 127) against independent Gauss quadrature of their definitions.
#include "seaflex/elements/ancf_cable.hpp"

#include <gtest/gtest.h>

#include "seaflex/math/gauss_legendre.hpp"

using namespace seaflex;
using namespace seaflex::ancf_cable;

namespace {
Eigen::Matrix<double, 3, 12> S_matrix(double xi, double l) {
  const Vec4 s = shape(xi, l);
  Eigen::Matrix<double, 3, 12> S = Eigen::Matrix<double, 3, 12>::Zero();
  for (int i = 0; i < 4; ++i) S.block<3, 3>(0, 3 * i).diagonal().setConstant(s[i]);
  return S;
}
}  // namespace

TEST(AncfCable, ShapeFunctionsInterpolateNodes) {
  const double l = 2.5;
  const Vec3 r0(1, 2, 3), t0(0.6, 0.8, 0), rl(4, 5, 6), tl(0, 0, 1);
  Vec12 e;
  e << r0, t0, rl, tl;
  const auto R = as_nodes(e);
  EXPECT_LT((R * shape(0.0, l) - r0).norm(), 1e-15);
  EXPECT_LT((R * shape(1.0, l) - rl).norm(), 1e-15);
  EXPECT_LT((R * shape_dx(0.0, l) - t0).norm(), 1e-14);
  EXPECT_LT((R * shape_dx(1.0, l) - tl).norm(), 1e-14);
  // derivatives against central differences in x = xi l
  const double xi = 0.37, h = 1e-6;
  const Vec4 fd = (shape(xi + h / l, l) - shape(xi - h / l, l)) / (2 * h);
  EXPECT_LT((fd - shape_dx(xi, l)).norm(), 1e-8);
  const Vec4 fd2 = (shape_dx(xi + h / l, l) - shape_dx(xi - h / l, l)) / (2 * h);
  EXPECT_LT((fd2 - shape_dxx(xi, l)).norm(), 1e-7);
}

// M = int rho A S^T S dx (thesis eq. 9), integrated with 4 Gauss points (degree 6 exact)
TEST(AncfCable, MassMatrixMatchesQuadrature) {
  const double l = 1.7, rhoA = 78.5;
  const auto rule = math::gauss_legendre_unit(4);
  Mat12 M = Mat12::Zero();
  for (std::size_t k = 0; k < rule.points.size(); ++k) {
    const auto S = S_matrix(rule.points[k], l);
    M += rule.weights[k] * l * rhoA * S.transpose() * S;
  }
  EXPECT_LT((M - mass_matrix(rhoA, l)).norm(), 1e-12 * M.norm());
  // total mass: a uniform translation u has kinetic mass rho A l
  Vec12 u;
  u << Vec3::UnitX(), Vec3::Zero(), Vec3::UnitX(), Vec3::Zero();
  EXPECT_NEAR(u.dot(mass_matrix(rhoA, l) * u), rhoA * l, 1e-12);
}

TEST(AncfCable, UniformLoadMatchesQuadrature) {
  const double l = 3.0;
  const Vec3 f(1.0, -2.0, 5.0);
  const auto rule = math::gauss_legendre_unit(3);
  Vec12 Q = Vec12::Zero();
  for (std::size_t k = 0; k < rule.points.size(); ++k)
    Q += rule.weights[k] * l * S_matrix(rule.points[k], l).transpose() * f;
  EXPECT_LT((Q - uniform_load(f, l)).norm(), 1e-13);
}
