// Kernel identities of the ANCF plate (thesis section 2.3): shape functions, mass matrix
// (eq. 70-74) and uniform load (eq. 128) against quadrature of their definitions; for
// every elastic model: zero force under rigid motion, force = -dU/de and tangent = the
// finite difference of the force; the plate marker against finite differences.
#include <gtest/gtest.h>

#include <random>

#include "seaflex/elements/ancf_plate.hpp"
#include "seaflex/math/gauss_legendre.hpp"
#include "seaflex/math/rotation.hpp"

using namespace seaflex;
using namespace seaflex::ancf_plate;

namespace {

constexpr double kA = 1.3, kB = 0.9;

PlateMaterial steel() {
  PlateMaterial m;
  m.thickness = 0.02;
  m.youngs_modulus = 210e9;
  m.poisson_ratio = 0.3;
  m.density = 7850;
  return m;
}

Eigen::Matrix<double, 3, 48> S_matrix(const Vec16& N) {
  Eigen::Matrix<double, 3, 48> S = Eigen::Matrix<double, 3, 48>::Zero();
  for (int c = 0; c < 16; ++c) S.block<3, 3>(0, 3 * c).diagonal().setConstant(N[c]);
  return S;
}

// a flat element, rotated and moved, then bent and stretched by a random perturbation
Vec48 deformed(double amplitude, unsigned seed) {
  const Mat3 Rot = math::rotation_from_roll_pitch_yaw(0.3, -0.5, 1.1);
  Vec48 e = flat(Vec3(2.0, -1.0, 0.5), Rot.col(0), Rot.col(1), kA, kB);
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int c = 0; c < 16; ++c) {
    const double scale = column_role(c).kind == 0 ? kA : 1.0;  // positions in m, slopes in 1
    for (int k = 0; k < 3; ++k) e[3 * c + k] += amplitude * scale * u(gen);
  }
  return e;
}

struct Models {
  MidplaneModel m;
  TransverseModel t;
};
const Models kAll[] = {
    {MidplaneModel::kExact, TransverseModel::kExact}, {MidplaneModel::kL3, TransverseModel::kT2},
    {MidplaneModel::kL3, TransverseModel::kT3},       {MidplaneModel::kL1, TransverseModel::kT2},
    {MidplaneModel::kL1, TransverseModel::kT3},       {MidplaneModel::kExact, TransverseModel::kT3},
    {MidplaneModel::kL1, TransverseModel::kExact},
};

std::string label(const Models& m) {
  return std::string(to_string(m.m)) + "/" + std::string(to_string(m.t));
}

}  // namespace

TEST(AncfPlate, ShapeFunctionsInterpolateNodes) {
  Vec48 e;
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int k = 0; k < 48; ++k) e[k] = u(gen);
  const auto R = as_nodes(e);
  // at each corner: r, r_p1, r_p2, r_p1p2 are the nodal vectors (thesis eq. 61)
  for (int c1 = 0; c1 < 2; ++c1)
    for (int c2 = 0; c2 < 2; ++c2) {
      const ShapeValues s = shape(c1, c2, kA, kB);
      EXPECT_LT((R * s.N - R.col(column_of(c1, c2, 0))).norm(), 1e-14);
      EXPECT_LT((R * s.N1 - R.col(column_of(c1, c2, 1))).norm(), 1e-13);
      EXPECT_LT((R * s.N2 - R.col(column_of(c1, c2, 2))).norm(), 1e-13);
      EXPECT_LT((R * s.N12 - R.col(column_of(c1, c2, 3))).norm(), 1e-12);
    }
  // thesis eq. (67): e_21 = r_p1(0, 0), e_12 = r_p2(0, 0), e_33 = r(a, b)
  EXPECT_EQ(column(2, 1), column_of(0, 0, 1));
  EXPECT_EQ(column(1, 2), column_of(0, 0, 2));
  EXPECT_EQ(column(3, 3), column_of(1, 1, 0));
  EXPECT_EQ(column(4, 4), column_of(1, 1, 3));
  // derivatives against central differences
  const double x1 = 0.31, x2 = 0.77, h = 1e-6;
  const ShapeValues s = shape(x1, x2, kA, kB);
  const ShapeValues p1 = shape(x1 + h / kA, x2, kA, kB), m1 = shape(x1 - h / kA, x2, kA, kB);
  const ShapeValues p2 = shape(x1, x2 + h / kB, kA, kB), m2 = shape(x1, x2 - h / kB, kA, kB);
  EXPECT_LT(((p1.N - m1.N) / (2 * h) - s.N1).norm(), 1e-8);
  EXPECT_LT(((p2.N - m2.N) / (2 * h) - s.N2).norm(), 1e-8);
  EXPECT_LT(((p1.N1 - m1.N1) / (2 * h) - s.N11).norm(), 1e-7);
  EXPECT_LT(((p2.N2 - m2.N2) / (2 * h) - s.N22).norm(), 1e-7);
  EXPECT_LT(((p2.N1 - m2.N1) / (2 * h) - s.N12).norm(), 1e-7);
}

// M = mu int S^T S dP (thesis eq. 70), 4 x 4 Gauss points (degree 6 per direction, exact)
TEST(AncfPlate, MassMatrixMatchesQuadratureAndPlateMass) {
  const double mu = 157.0;
  const auto rule = math::gauss_legendre_unit(4);
  Mat48 M = Mat48::Zero();
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t j = 0; j < 4; ++j) {
      const auto S = S_matrix(shape(rule.points[i], rule.points[j], kA, kB).N);
      M += rule.weights[i] * rule.weights[j] * kA * kB * mu * S.transpose() * S;
    }
  const Mat48 Me = mass_matrix(mu, kA, kB);
  EXPECT_LT((M - Me).norm(), 1e-12 * M.norm());
  EXPECT_LT((Me - Me.transpose()).norm(), 1e-14 * Me.norm());
  // a uniform translation along each axis carries the plate's mass mu a b
  for (int d = 0; d < 3; ++d) {
    Vec48 u = Vec48::Zero();
    for (int c1 = 0; c1 < 2; ++c1)
      for (int c2 = 0; c2 < 2; ++c2) u[3 * column_of(c1, c2, 0) + d] = 1.0;
    EXPECT_NEAR(u.dot(Me * u), mu * kA * kB, 1e-12 * mu * kA * kB) << "axis " << d;
  }
}

TEST(AncfPlate, UniformLoadMatchesQuadrature) {
  const Vec3 f(1.0, -2.0, 5.0);
  const auto rule = math::gauss_legendre_unit(3);
  Vec48 Q = Vec48::Zero();
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j)
      Q += rule.weights[i] * rule.weights[j] * kA * kB *
           S_matrix(shape(rule.points[i], rule.points[j], kA, kB).N).transpose() * f;
  EXPECT_LT((Q - uniform_load(f, kA, kB)).norm(), 1e-13);
  // the total force is f a b
  Vec3 total = Vec3::Zero();
  for (int c1 = 0; c1 < 2; ++c1)
    for (int c2 = 0; c2 < 2; ++c2) total += Q.segment<3>(3 * column_of(c1, c2, 0));
  EXPECT_LT((total - f * kA * kB).norm(), 1e-13);
}

// a rigid rotation and translation of the flat element strains nothing: U = 0 and Q = 0
// (relative to the force scale C a of a unit strain)
TEST(AncfPlate, RigidMotionGivesZeroElasticForce) {
  const Mat3 Rot = math::rotation_from_euler_zxz(0.7, 1.2, -0.4);
  const Vec48 e = flat(Vec3(5.0, -3.0, 100.0), Rot.col(0), Rot.col(1), kA, kB);
  const double scale = steel().membrane_rigidity() * kA;
  for (const Models& m : kAll) {
    const PlateElasticity el(kA, kB, steel(), m.m, m.t);
    Vec48 Q = Vec48::Zero();
    Mat48 K = Mat48::Zero();
    const double U = el.add_forces(e, Q, &K);
    EXPECT_LT(std::abs(U), 1e-12 * scale * kA) << label(m);
    EXPECT_LT(Q.lpNorm<Eigen::Infinity>(), 1e-12 * scale) << label(m);
    // the tangent has the rigid translations in its null space
    Vec48 t = Vec48::Zero();
    for (int c1 = 0; c1 < 2; ++c1)
      for (int c2 = 0; c2 < 2; ++c2) t.segment<3>(3 * column_of(c1, c2, 0)) = Vec3(1, 2, 3);
    EXPECT_LT((K * t).lpNorm<Eigen::Infinity>(), 1e-9 * K.lpNorm<Eigen::Infinity>()) << label(m);
  }
}

// Q = -dU/de by central differences for the models derived from a potential (all but L1);
// relative tolerance 1e-6: the difference step 1e-7 of a slope-sized coordinate leaves a
// truncation error ~1e-10 and round-off ~1e-9 of the force scale
TEST(AncfPlate, ForceIsMinusEnergyGradient) {
  const Vec48 e = deformed(0.05, 3);
  for (const Models& m : kAll) {
    if (m.m == MidplaneModel::kL1) continue;
    const PlateElasticity el(kA, kB, steel(), m.m, m.t);
    Vec48 Q = Vec48::Zero();
    el.add_forces(e, Q, nullptr);
    Vec48 fd;
    const double h = 1e-7;
    for (int k = 0; k < 48; ++k) {
      Vec48 ep = e, em = e, dummy = Vec48::Zero();
      ep[k] += h;
      em[k] -= h;
      fd[k] = -(el.add_forces(ep, dummy, nullptr) - el.add_forces(em, dummy, nullptr)) / (2 * h);
    }
    EXPECT_LT((fd - Q).norm(), 1e-6 * Q.norm()) << label(m);
  }
}

// K = -dQ/de by central differences, every model (L1 included: its tangent is not
// symmetric, but it is the exact derivative of its force); tolerance as above
TEST(AncfPlate, TangentIsForceDerivative) {
  for (unsigned seed : {3u, 11u}) {
    const Vec48 e = deformed(0.05, seed);
    for (const Models& m : kAll) {
      const PlateElasticity el(kA, kB, steel(), m.m, m.t);
      Vec48 Q = Vec48::Zero();
      Mat48 K = Mat48::Zero();
      el.add_forces(e, Q, &K);
      Mat48 fd;
      const double h = 1e-7;
      for (int k = 0; k < 48; ++k) {
        Vec48 ep = e, em = e, Qp = Vec48::Zero(), Qm = Vec48::Zero();
        ep[k] += h;
        em[k] -= h;
        el.add_forces(ep, Qp, nullptr);
        el.add_forces(em, Qm, nullptr);
        fd.col(k) = -(Qp - Qm) / (2 * h);
      }
      EXPECT_LT((fd - K).norm(), 1e-6 * K.norm()) << label(m) << " seed " << seed;
      if (m.m != MidplaneModel::kL1) {
        EXPECT_LT((K - K.transpose()).norm(), 1e-10 * K.norm()) << label(m);
      }
    }
  }
}

// L1, thesis eq. (90): the constant strains are the chord strains (d - l) / l of the edges
// (docs/theory/ancf_plate.md). A uniform stretch by l1, l2 (shear g) gives eps11 = l1 - 1,
// eps22 = l2 - 1, eps12 = g / 2 exactly, so U = a b / 2 (N11 eps11 + N22 eps22 + 2 N12 eps12)
TEST(AncfPlate, L1ConstantStrainsAreChordStrains) {
  const double l1 = 1.03, l2 = 0.98;
  const Vec48 e = flat(Vec3(0.2, 0.1, 0.0), Vec3(l1, 0, 0), Vec3(0, l2, 0), kA, kB);
  const PlateElasticity el(kA, kB, steel(), MidplaneModel::kL1, TransverseModel::kT3);
  Vec48 Q = Vec48::Zero();
  const double U = el.add_midplane_l1(e, Q, nullptr);
  const double C = steel().membrane_rigidity(), nu = steel().poisson_ratio;
  const double e11 = l1 - 1.0, e22 = l2 - 1.0;
  const double ref = 0.5 * kA * kB * C * (e11 * e11 + e22 * e22 + 2.0 * nu * e11 * e22);
  EXPECT_NEAR(U, ref, 1e-12 * ref);
}

// L1 is not the gradient of a potential (thesis eq. 90-92, docs/theory/ancf_plate.md):
// K = K(eps) + sum_a (S^a e) (dN_a/de)^T with K(eps) symmetric; no constant strain depends
// on r_p1p2, so K - K^T on the rows of r_p1p2 and the columns of the positions is the second
// term alone, which is not zero on a bent element
TEST(AncfPlate, L1TangentIsNotSymmetric) {
  const Vec48 e = deformed(0.05, 3);
  const PlateElasticity el(kA, kB, steel(), MidplaneModel::kL1, TransverseModel::kT3);
  Vec48 Q = Vec48::Zero();
  Mat48 K = Mat48::Zero();
  el.add_midplane_l1(e, Q, &K);
  const Mat48 A = K - K.transpose();
  double block = 0.0;
  for (int c = 0; c < 16; ++c)
    for (int d = 0; d < 16; ++d)
      if (column_role(c).kind == 3 && column_role(d).kind == 0)
        block = std::max(block, A.block<3, 3>(3 * c, 3 * d).lpNorm<Eigen::Infinity>());
  EXPECT_GT(block, 1e-3 * K.lpNorm<Eigen::Infinity>());
}

// L3 is the exact midplane energy integrated exactly: the exact model with 7 x 7 points
// gives the same numbers to round-off
TEST(AncfPlate, L3EqualsExactMidplaneIntegratedExactly) {
  const Vec48 e = deformed(0.05, 5);
  const PlateElasticity exact(kA, kB, steel(), MidplaneModel::kExact, TransverseModel::kT3, 7);
  const PlateElasticity l3(kA, kB, steel(), MidplaneModel::kL3, TransverseModel::kT3);
  const PlateElasticity coarse(kA, kB, steel(), MidplaneModel::kExact, TransverseModel::kT3, 4);
  Vec48 Qe = Vec48::Zero(), Ql = Vec48::Zero(), Qc = Vec48::Zero();
  const double Ue = exact.add_midplane_exact(e, Qe, nullptr);
  const double Ul = l3.add_midplane_l3(e, Ql, nullptr);
  const double Uc = coarse.add_midplane_exact(e, Qc, nullptr);
  EXPECT_NEAR(Ue, Ul, 1e-12 * Ue);
  EXPECT_LT((Qe - Ql).norm(), 1e-12 * Qe.norm());
  // 4 x 4 points integrate degree 7 only: visibly different on this strongly strained state
  EXPECT_GT(std::abs(Uc - Ul), 1e-8 * Ul);
}

// the curvatures of a cylindrical bend of radius rho: k11 = 1/rho, k22 = k12 = 0; the
// three transverse models agree on it (its normal is the same everywhere up to the bend)
TEST(AncfPlate, CurvatureOfCylindricalBend) {
  const double rho = 20.0;
  // nodal values of r(p1, p2) = (rho sin(p1/rho), p2, rho (1 - cos(p1/rho))), a small arc
  Vec48 e = Vec48::Zero();
  for (int c1 = 0; c1 < 2; ++c1)
    for (int c2 = 0; c2 < 2; ++c2) {
      const double p1 = c1 * kA, p2 = c2 * kB, th = p1 / rho;
      e.segment<3>(3 * column_of(c1, c2, 0)) =
          Vec3(rho * std::sin(th), p2, rho * (1 - std::cos(th)));
      e.segment<3>(3 * column_of(c1, c2, 1)) = Vec3(std::cos(th), 0, std::sin(th));
      e.segment<3>(3 * column_of(c1, c2, 2)) = Vec3(0, 1, 0);
    }
  const PlateElasticity el(kA, kB, steel(), MidplaneModel::kExact, TransverseModel::kExact);
  const Vec3 k = el.curvature(e, 0.5, 0.5);
  // the cubic Hermite arc through the nodal values has its curvature right to about
  // (a/rho)^2 / 24 = 1.8e-4 at the middle: 5e-4 relative; sign: the normal t1 x t2 = +z
  // points to the centre of the bend, so k11 > 0
  EXPECT_NEAR(k[0], 1.0 / rho, 5e-4 / rho);
  EXPECT_NEAR(k[1], 0.0, 1e-12);
  EXPECT_NEAR(k[2], 0.0, 1e-12);
  const double D = steel().flexural_rigidity();
  for (TransverseModel t : {TransverseModel::kExact, TransverseModel::kT2, TransverseModel::kT3}) {
    const PlateElasticity m(kA, kB, steel(), MidplaneModel::kExact, t);
    Vec48 Q = Vec48::Zero();
    double U = 0.0;
    if (t == TransverseModel::kExact) U = m.add_transverse_exact(e, Q, nullptr);
    if (t == TransverseModel::kT2) U = m.add_transverse_t2(e, Q, nullptr);
    if (t == TransverseModel::kT3) U = m.add_transverse_t3(e, Q, nullptr);
    // U = D/2 k^2 a b; the averaged normals differ from the local one by ~a/(2 rho) rad,
    // which changes k by its cosine, ~0.1 %
    EXPECT_NEAR(U, 0.5 * D * kA * kB / (rho * rho), 2e-3 * 0.5 * D * kA * kB / (rho * rho))
        << to_string(t);
  }
}

// the plate marker: J, the rate and the bias against finite differences of the vectors
TEST(AncfPlate, MarkerAgainstFiniteDifferences) {
  PlateGeometry g;
  g.corner = Vec3(1, 2, 3);
  g.edge1 = Vec3(2, 0, 0);
  g.edge2 = Vec3(0, 0, -1);
  g.nx = 2;
  g.ny = 1;
  AncfPlate plate("p", g, steel(), PlateOptions{});
  State s;
  s.q.setZero(plate.num_coordinates());
  s.v.setZero(plate.num_coordinates());
  plate.write_initial_state(s.q, s.v);
  std::mt19937 gen(1);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (Index k = 0; k < s.q.size(); ++k) {
    s.q[k] += 0.1 * u(gen);
    s.v[k] = u(gen);
  }
  const PlateMarker m(plate, 1, 1);
  EXPECT_EQ(m.describe(), "p.n1_1");
  const auto dofs = m.coordinates();
  ASSERT_EQ(dofs.size(), 9u);
  for (int w = 0; w < 4; ++w) {
    const auto which = static_cast<MarkerVector>(w);
    MarkerVectorEval ev;
    m.evaluate(which, s, ev);
    const double h = 1e-6;
    for (int k = 0; k < 9; ++k) {
      State sp = s, sm = s;
      sp.q[dofs[k]] += h;
      sm.q[dofs[k]] -= h;
      MarkerVectorEval ep, em;
      m.evaluate(which, sp, ep);
      m.evaluate(which, sm, em);
      EXPECT_LT(((ep.value - em.value) / (2 * h) - ev.J.col(k)).norm(), 1e-8);
      EXPECT_LT(((ep.rate - em.rate) / (2 * h) - ev.Jv.col(k)).norm(), 1e-8);
    }
    // bias = J' v: the second time derivative along q(t) = q + t v, minus J q'' (= 0)
    State sp = s, sm = s;
    sp.q += h * s.v;
    sm.q -= h * s.v;
    MarkerVectorEval ep, em;
    m.evaluate(which, sp, ep);
    m.evaluate(which, sm, em);
    EXPECT_LT(((ep.rate - em.rate) / (2 * h) - ev.bias).norm(), 1e-7);
    // d(J^T F)/dq
    const Vec3 F(0.3, -1.2, 2.0);
    MatX H = MatX::Zero(9, 9);
    m.add_hessian(which, s, F, H);
    for (int k = 0; k < 9; ++k) {
      State qp = s, qm = s;
      qp.q[dofs[k]] += h;
      qm.q[dofs[k]] -= h;
      MarkerVectorEval a, b;
      m.evaluate(which, qp, a);
      m.evaluate(which, qm, b);
      const VecX col = (a.J.transpose() * F - b.J.transpose() * F) / (2 * h);
      EXPECT_LT((col - H.col(k)).norm(), 1e-8);
    }
  }
}
