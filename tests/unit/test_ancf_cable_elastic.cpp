// Elastic force models of the ANCF cable (thesis 2.2.3): forces against -dU/de, tangents
// against central differences of the forces, rigid motion gives zero force, the L2 closed
// form equals the quadrature of the exact Green-Lagrange model, the constant matrices
// equal eq. (27) and (42), and the two exact curvatures (per reference length, the
// default, and per deformed length, thesis eq. 14) behave as they must under a stretch.
#include "seaflex/elements/ancf_cable_elastic.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "seaflex/math/gauss_legendre.hpp"

using namespace seaflex;
using namespace seaflex::ancf_cable;

namespace {

constexpr double kL = 1.3;      // element length (m)
constexpr double kEA = 2.1e9;   // N, steel 0.01 m^2
constexpr double kEI = 1.75e6;  // N m^2

// a deformed element: straight along a skew direction, stretched 1 %, bent and twisted
Vec12 deformed(double amplitude = 0.05) {
  const Vec3 t = Vec3(1.0, 0.4, -0.3).normalized();
  Vec12 e = straight(Vec3(0.2, -0.1, 0.5), 1.01 * t, kL);
  Vec12 d;
  d << 0.01, -0.02, 0.03, 0.3, -0.2, 0.1, -0.02, 0.04, 0.01, -0.1, 0.25, 0.2;
  return e + amplitude / 0.05 * d * 0.2;
}

using ForceFn = std::function<double(const Vec12&, Vec12&, Mat12*)>;

// central-difference tangent of the force; returns max relative deviation from K
double tangent_error(const ForceFn& f, const Vec12& e) {
  Vec12 Q = Vec12::Zero();
  Mat12 K = Mat12::Zero();
  f(e, Q, &K);
  Mat12 K_fd;
  for (int j = 0; j < 12; ++j) {
    const double h = 1e-6 * std::max(1.0, std::abs(e[j]));
    Vec12 ep = e, em = e, Qp = Vec12::Zero(), Qm = Vec12::Zero();
    ep[j] += h;
    em[j] -= h;
    f(ep, Qp, nullptr);
    f(em, Qm, nullptr);
    K_fd.col(j) = -(Qp - Qm) / (2 * h);
  }
  return (K - K_fd).norm() / K.norm();
}

// central-difference gradient of the energy; returns relative deviation of Q from -dU/de
double gradient_error(const ForceFn& f, const Vec12& e) {
  Vec12 Q = Vec12::Zero();
  f(e, Q, nullptr);
  Vec12 g;
  for (int j = 0; j < 12; ++j) {
    const double h = 1e-6 * std::max(1.0, std::abs(e[j]));
    Vec12 ep = e, em = e, scratch = Vec12::Zero();
    ep[j] += h;
    em[j] -= h;
    g[j] = -(f(ep, scratch, nullptr) - f(em, scratch, nullptr)) / (2 * h);
  }
  return (Q - g).norm() / Q.norm();
}

struct ModelCase {
  const char* name;
  double (CableElasticity::*fn)(const Vec12&, Vec12&, Mat12*) const;
  bool conservative;
};

const ModelCase kModels[] = {
    {"axial exact", &CableElasticity::add_axial_exact, true},
    {"axial L1", &CableElasticity::add_axial_l1, false},
    {"axial L2", &CableElasticity::add_axial_l2, true},
    {"bending exact", &CableElasticity::add_bending_exact, true},
    {"bending exact_deformed", &CableElasticity::add_bending_exact_deformed, true},
    {"bending T1", &CableElasticity::add_bending_t1, true},
    {"bending T2", &CableElasticity::add_bending_t2, true},
};

}  // namespace

// every tangent equals the central difference of its force to 1e-6 relative
// (FD truncation ~h^2 = 1e-12, round-off ~eps/h = 1e-10: 1e-6 leaves a wide margin)
TEST(CableElastic, TangentsMatchFiniteDifferences) {
  const CableElasticity el(kL, kEA, kEI, AxialModel::kExact, BendingModel::kExact, 5);
  for (double amplitude : {0.05, 0.5}) {
    const Vec12 e = deformed(amplitude);
    for (const auto& m : kModels) {
      const ForceFn f = [&](const Vec12& x, Vec12& Q, Mat12* K) { return (el.*m.fn)(x, Q, K); };
      EXPECT_LT(tangent_error(f, e), 1e-6) << m.name << " amplitude " << amplitude;
    }
  }
}

// conservative models: Q = -dU/de
TEST(CableElastic, ForcesAreEnergyGradients) {
  const CableElasticity el(kL, kEA, kEI, AxialModel::kExact, BendingModel::kExact, 5);
  const Vec12 e = deformed(0.3);
  for (const auto& m : kModels) {
    if (!m.conservative) continue;
    const ForceFn f = [&](const Vec12& x, Vec12& Q, Mat12* K) { return (el.*m.fn)(x, Q, K); };
    EXPECT_LT(gradient_error(f, e), 1e-6) << m.name;
  }
}

// a straight, unstretched element moved and rotated rigidly carries no elastic force
TEST(CableElastic, RigidMotionGivesZeroForce) {
  for (auto axial : {AxialModel::kExact, AxialModel::kL1, AxialModel::kL2})
    for (auto bending : {BendingModel::kExact, BendingModel::kExactDeformed, BendingModel::kT1,
                         BendingModel::kT2}) {
      const CableElasticity el(kL, kEA, kEI, axial, bending, 5);
      for (const Vec3& dir : {Vec3(1, 0, 0), Vec3(0.3, -0.5, 0.8).normalized(), Vec3(0, 0, -1)}) {
        Vec12 Q = Vec12::Zero();
        const double U = el.add_forces(straight(Vec3(3, -7, 11), dir, kL), Q, nullptr);
        // round-off floor: forces ~ EA * 1e-16 = 2e-7 N (a 1e-9 strain gives 2 N);
        // energies of the closed forms (L2, T1, T2 subtract terms of size l) ~ EA l 1e-16
        // = 3e-7 J, while a real strain of 1e-7 stores 1.4e-5 J
        EXPECT_LT(Q.norm(), 1e-5) << to_string(axial) << "/" << to_string(bending);
        EXPECT_LT(std::abs(U), 1e-15 * kEA * kL) << to_string(axial) << "/" << to_string(bending);
      }
    }
}

// add_forces without a tangent takes the fused path for the exact axial model with either
// exact bending model and 2 to 8 points (ancf_cable_elastic.hpp): the same forces and energy
// as the separate functions, to round-off (1e-13 of the force's norm), at small and large
// deformation; 9 points take the separate functions themselves (identical)
TEST(CableElastic, FusedForcesEqualTheSeparateModels) {
  for (const BendingModel bending : {BendingModel::kExact, BendingModel::kExactDeformed})
    for (int points = 2; points <= 9; ++points) {
      const CableElasticity el(kL, kEA, kEI, AxialModel::kExact, bending, points);
      for (double amplitude : {0.01, 0.5, 2.0}) {
        const Vec12 e = deformed(amplitude);
        Vec12 fused = Vec12::Zero(), separate = Vec12::Zero();
        const double U = el.add_forces(e, fused, nullptr);
        double U_ref = el.add_axial_exact(e, separate, nullptr);
        U_ref += bending == BendingModel::kExact
                     ? el.add_bending_exact(e, separate, nullptr)
                     : el.add_bending_exact_deformed(e, separate, nullptr);
        EXPECT_GT(separate.norm(), 1.0);
        EXPECT_LT((fused - separate).norm(), 1e-13 * separate.norm())
            << to_string(bending) << " points " << points << " amplitude " << amplitude;
        EXPECT_NEAR(U, U_ref, 1e-13 * std::abs(U_ref));
        // with a tangent: the separate functions, the same forces
        Vec12 with_k = Vec12::Zero();
        Mat12 K = Mat12::Zero();
        el.add_forces(e, with_k, &K);
        EXPECT_LT((with_k - separate).norm(), 1e-13 * separate.norm());
      }
    }
}

// Reduced integration (the storm files' elastic gauss_points: 3). At the straight, unstrained
// element the linearized axial strain t.dr' is quadratic and the linearized curvature linear
// along the element, so the stiffness integrands are of degree 4 and 2: 3 Gauss points
// (exact to degree 5) give the same tangent as 5 (to round-off, 1e-12 of its norm), and a
// 12 x 12 tangent with exactly 5 zero eigenvalues (3 translations, 2 rotations about axes
// across the element: no spurious zero-energy mode). 2 points leave a sixth (a quadratic
// axial strain that vanishes at both points). Deformed, 3 and 5 points differ (the energy's
// degree-8 terms), by more than 1e-6 of the tangent here.
TEST(CableElastic, ThreePointsIntegrateTheLinearizedStiffnessExactly) {
  const Vec12 e0 = straight(Vec3(0.2, -0.1, 0.5), Vec3(1.0, 0.4, -0.3).normalized(), kL);
  auto tangent = [](int points, const Vec12& e) {
    const CableElasticity el(kL, kEA, kEI, AxialModel::kExact, BendingModel::kExact, points);
    Vec12 Q = Vec12::Zero();
    Mat12 K = Mat12::Zero();
    el.add_forces(e, Q, &K);
    return K;
  };
  auto zero_eigenvalues = [](const Mat12& K) {
    const Eigen::SelfAdjointEigenSolver<Mat12> eig(0.5 * (K + K.transpose()));
    const double largest = eig.eigenvalues().cwiseAbs().maxCoeff();
    int zeros = 0;
    for (int i = 0; i < 12; ++i) zeros += std::abs(eig.eigenvalues()[i]) < 1e-10 * largest;
    return zeros;
  };
  const Mat12 K5 = tangent(5, e0), K3 = tangent(3, e0), K2 = tangent(2, e0);
  EXPECT_LT((K3 - K5).norm(), 1e-12 * K5.norm());
  EXPECT_EQ(zero_eigenvalues(K5), 5);
  EXPECT_EQ(zero_eigenvalues(K3), 5);
  EXPECT_EQ(zero_eigenvalues(K2), 6);
  const Vec12 e = deformed(0.5);
  EXPECT_GT((tangent(3, e) - tangent(5, e)).norm(), 1e-6 * tangent(5, e).norm());
}

// L2 (closed form, exact tensor) and the exact axial model (Gauss quadrature of the
// same degree-8 polynomial) agree to round-off
TEST(CableElastic, L2ClosedFormEqualsQuadrature) {
  const CableElasticity el(kL, kEA, kEI, AxialModel::kExact, BendingModel::kExact, 5);
  for (double amplitude : {0.01, 0.5, 2.0}) {
    const Vec12 e = deformed(amplitude);
    Vec12 Q1 = Vec12::Zero(), Q2 = Vec12::Zero();
    Mat12 K1 = Mat12::Zero(), K2 = Mat12::Zero();
    const double U1 = el.add_axial_exact(e, Q1, &K1);
    const double U2 = el.add_axial_l2(e, Q2, &K2);
    EXPECT_LT((Q1 - Q2).norm(), 1e-12 * Q1.norm());
    EXPECT_LT((K1 - K2).norm(), 1e-12 * K1.norm());
    EXPECT_NEAR(U1, U2, 1e-12 * U1);
  }
}

// the constant matrices of eq. (27) (without EA eps) and eq. (42) (without EI)
// against quadrature of int S'^T S' dx and int S''^T S'' dx
TEST(CableElastic, ConstantMatricesMatchThesis) {
  const auto rule = math::gauss_legendre_unit(4);
  Mat4 B1 = Mat4::Zero(), B2 = Mat4::Zero();
  for (std::size_t k = 0; k < rule.points.size(); ++k) {
    const Vec4 a = shape_dx(rule.points[k], kL), b = shape_dxx(rule.points[k], kL);
    B1 += rule.weights[k] * kL * a * a.transpose();
    B2 += rule.weights[k] * kL * b * b.transpose();
  }
  EXPECT_LT((B1 - axial_matrix(kL)).norm(), 1e-13 * B1.norm());
  EXPECT_LT((B2 - bending_matrix(kL)).norm(), 1e-13 * B2.norm());
}

// exact curvature of a circular arc: nodes on a circle of radius Rc with unit tangents;
// the cubic interpolates the arc to O(theta^4), so kappa = 1/Rc within 1e-4 for a
// 0.1 rad arc, and U = 1/2 EI kappa^2 l
TEST(CableElastic, CircularArcCurvature) {
  const double Rc = 10.0, theta = 0.1, l = Rc * theta;
  Vec12 e;
  e << Rc, 0, 0, 0, 1, 0, Rc * std::cos(theta), Rc * std::sin(theta), 0, -std::sin(theta),
      std::cos(theta), 0;
  const CableElasticity el(l, kEA, kEI, AxialModel::kExact, BendingModel::kExact, 5);
  for (double xi : {0.0, 0.3, 0.5, 1.0}) EXPECT_NEAR(el.curvature(e, xi) * Rc, 1.0, 1e-3);
  Vec12 Q = Vec12::Zero();
  const double U = el.add_bending_exact(e, Q, nullptr);
  EXPECT_NEAR(U / (0.5 * kEI * l / (Rc * Rc)), 1.0, 1e-3);
  // T1 and T2 see the same arc the same way to first order
  Vec12 Q1 = Vec12::Zero(), Q2 = Vec12::Zero();
  EXPECT_NEAR(el.add_bending_t1(e, Q1, nullptr) / U, 1.0, 1e-2);
  EXPECT_NEAR(el.add_bending_t2(e, Q2, nullptr) / U, 1.0, 1e-2);
}

// The two exact curvatures under a uniform scaling r(x) -> s r(x) of a bent element (all
// nodal positions and slopes times s, which stretches the axis by s without bending it
// further): the curvature per reference length kappa_0 = |r' x r''| / |r'|^2 is
// unchanged, so its energy is too and its force does no work on the scaling (Q.e = 0);
// thesis eq. (14), kappa = kappa_0 / |r'|, scales as 1/s and its energy as 1/s^2.
// Tolerances: 1e-13 relative is round-off on sums of 5 terms of size U.
TEST(CableElastic, ExactCurvatureIsInvariantUnderStretch) {
  const CableElasticity ref(kL, kEA, kEI, AxialModel::kExact, BendingModel::kExact, 5);
  const CableElasticity def(kL, kEA, kEI, AxialModel::kExact, BendingModel::kExactDeformed, 5);
  const Vec12 e = deformed(0.5);
  Vec12 Q = Vec12::Zero(), Qd = Vec12::Zero(), scratch = Vec12::Zero();
  const double U = ref.add_bending_exact(e, Q, nullptr);
  const double Ud = def.add_bending_exact_deformed(e, Qd, nullptr);
  ASSERT_GT(U, 0.0);
  for (double s : {0.9, 1.01, 1.5}) {
    EXPECT_NEAR(ref.add_bending_exact(s * e, scratch, nullptr) / U, 1.0, 1e-13) << s;
    EXPECT_NEAR(def.add_bending_exact_deformed(s * e, scratch, nullptr) / Ud, 1.0 / (s * s), 1e-13)
        << s;
    for (double xi : {0.0, 0.37, 1.0}) {
      EXPECT_NEAR(ref.curvature(s * e, xi) / ref.curvature(e, xi), 1.0, 1e-13);
      EXPECT_NEAR(def.curvature(s * e, xi) / def.curvature(e, xi), 1.0 / s, 1e-13);
    }
  }
  // d U(s e)/ds at s = 1 is -Q.e: zero for kappa_0 (the scale of Q.e is |Q||e|),
  // -2 U for eq. (14)
  EXPECT_LT(std::abs(Q.dot(e)), 1e-13 * Q.norm() * e.norm());
  EXPECT_NEAR(-Qd.dot(e) / (-2.0 * Ud), 1.0, 1e-12);
  // the two curvatures differ by the stretch |r'| at every point
  for (double xi : {0.0, 0.37, 1.0}) {
    const Vec3 a = relative_nodes(e) * shape_dx(xi, kL);
    EXPECT_NEAR(ref.curvature(e, xi) / (def.curvature(e, xi) * a.norm()), 1.0, 1e-13);
    EXPECT_NEAR((ref.curvature_vector(e, xi) - a.norm() * def.curvature_vector(e, xi)).norm(), 0.0,
                1e-13 * ref.curvature(e, xi));
  }
}

// L1's constant strain: a uniformly stretched element has eps = (d - l)/l and the
// exact model's Green-Lagrange strain 1/2((1+s)^2 - 1)
TEST(CableElastic, UniformStretch) {
  const double s = 0.002;
  const Vec12 e = straight(Vec3::Zero(), (1.0 + s) * Vec3::UnitX(), kL);
  const CableElasticity el(kL, kEA, kEI, AxialModel::kExact, BendingModel::kExact, 5);
  EXPECT_NEAR(el.axial_strain(e, 0.4), 0.5 * ((1 + s) * (1 + s) - 1), 1e-15);
  Vec12 Q = Vec12::Zero();
  // L1's end force: -EA eps r' with eps = s and r' = (1 + s) e_x (eq. 23, 27)
  el.add_axial_l1(e, Q, nullptr);
  EXPECT_NEAR(Q[6], -kEA * s * (1 + s), 1e-9 * kEA * s);
  EXPECT_NEAR(Q[0], kEA * s * (1 + s), 1e-9 * kEA * s);
}
