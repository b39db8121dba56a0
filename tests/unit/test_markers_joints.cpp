// Rotations, markers, joints and the rigid body (the force elements written against markers:
// test_marker_forces.cpp). Every derivative that the Newton and RK4 paths rely on (marker
// Jacobians, acceleration biases, rate Jacobians and Hessian contractions; joint C_q, gamma
// and multiplier Hessians; the tangents of the rigid body) is compared with central
// differences, and the rotation utilities and the rigid body's equations of motion with
// their closed forms.
//
// Tolerances. Central differences with h = 1e-6 carry a truncation error h^2 f'''/6
// (below 1e-11 relative for these smooth, mostly polynomial functions of size O(1-10))
// and a round-off error of about eps |f| / h = 2e-10 |f|. The checks ask
//   |exact - difference| <= 1e-7 (|exact| + |f|),
// three orders of magnitude above both, while a wrong or missing term (of relative size
// O(1)) fails by six. Identities that involve no differencing are held to 1e-12 or
// tighter, a few hundred round-offs of the numbers involved.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "marker_test_support.hpp"

using namespace seaflex;
using namespace seaflex::marker_test;

// ---------------------------------------------------------------------------------------
// 1. rotation utilities

// A(p) is a proper rotation for unit p, with A = G Gbar^T, G p = Gbar p = 0 and
// G G^T = Gbar Gbar^T = I; Shepperd's method returns p (up to sign, e0 >= 0) for random
// rotations and for rotations at and near 180 degrees (e0 -> 0). Round-off: every
// quantity is a few products of numbers of size 1, so 1e-14 (about 50 eps) bounds it;
// Shepperd divides by the largest of 4 e_i^2 >= 1, so its error stays as small.
TEST(Rotation, EulerParametersGiveRotationsAndRoundTrip) {
  Rng rng(1);
  std::vector<Vec4> ps;
  for (int i = 0; i < 200; ++i) ps.push_back(rng.unit4());
  for (double e0 : {0.0, 1e-12, 1e-8, -1e-8, 1e-4}) {  // half-turns and near them
    for (int i = 0; i < 5; ++i) {
      const Vec3 axis = rng.vec3().normalized();
      Vec4 p;
      p << e0, std::sqrt(1.0 - e0 * e0) * axis;
      ps.push_back(p);
    }
    for (int k = 0; k < 3; ++k) {  // about the coordinate axes, where Shepperd switches
      Vec4 p;
      p << e0, std::sqrt(1.0 - e0 * e0) * Vec3::Unit(k);
      ps.push_back(p);
    }
  }
  ps.push_back(Vec4(1, 0, 0, 0));
  for (const Vec4& p : ps) {
    const Mat3 A = math::rotation_from_euler_parameters(p);
    EXPECT_LT((A.transpose() * A - Mat3::Identity()).norm(), 1e-14);
    EXPECT_NEAR(A.determinant(), 1.0, 1e-14);
    const Mat34 G = math::euler_g(p), Gb = math::euler_gbar(p);
    EXPECT_LT((G * Gb.transpose() - A).norm(), 1e-14);
    EXPECT_LT((G * p).norm(), 1e-15);
    EXPECT_LT((Gb * p).norm(), 1e-15);
    EXPECT_LT((G * G.transpose() - Mat3::Identity()).norm(), 1e-14);
    EXPECT_LT((Gb * Gb.transpose() - Mat3::Identity()).norm(), 1e-14);
    const Vec4 back = math::euler_parameters_from_rotation(A);
    EXPECT_GE(back[0], 0.0);
    EXPECT_NEAR(back.norm(), 1.0, 1e-15);
    EXPECT_LT(std::min((back - p).norm(), (back + p).norm()), 1e-14) << p.transpose();
    EXPECT_LT((math::rotation_from_euler_parameters(back) - A).norm(), 1e-14);
  }
}

// A = Rz(yaw) Ry(pitch) Rx(roll) with the elementary rotations written out; round trip
// for pitch up to 0.01 rad from +-90 deg, where roll and yaw come from entries of size
// cos(pitch) and their round-off grows by 1/cos(pitch) = 100 (so 1e-12); at exactly
// +-90 deg yaw reads 0, pitch is exact and the rotation is reproduced.
TEST(Rotation, RollPitchYawConventionAndRoundTrip) {
  const Mat3 yaw90 = math::rotation_from_roll_pitch_yaw(0, 0, kPi / 2);
  EXPECT_LT((yaw90 * Vec3::UnitX() - Vec3::UnitY()).norm(), 1e-15);  // yaw turns x to y
  const Mat3 pitch90 = math::rotation_from_roll_pitch_yaw(0, kPi / 2, 0);
  EXPECT_LT((pitch90 * Vec3::UnitX() + Vec3::UnitZ()).norm(), 1e-15);  // bow down
  const Mat3 roll90 = math::rotation_from_roll_pitch_yaw(kPi / 2, 0, 0);
  EXPECT_LT((roll90 * Vec3::UnitY() - Vec3::UnitZ()).norm(), 1e-15);  // starboard up
  // yaw about the global z, then pitch about the new y, then roll about the new x
  const Mat3 A = math::rotation_from_roll_pitch_yaw(0.3, -0.4, 1.2);
  EXPECT_LT((A - rot_z(1.2) * rot_y(-0.4) * rot_x(0.3)).norm(), 1e-15);
  EXPECT_LT((A.col(0) - rot_z(1.2) * rot_y(-0.4) * Vec3::UnitX()).norm(), 1e-15);

  Rng rng(2);
  for (int i = 0; i < 200; ++i) {
    const Vec3 rpy(rng(-kPi, kPi), rng(-kPi / 2 + 0.01, kPi / 2 - 0.01), rng(-kPi, kPi));
    const Mat3 R = math::rotation_from_roll_pitch_yaw(rpy[0], rpy[1], rpy[2]);
    const Vec3 back = math::roll_pitch_yaw_from_rotation(R);
    EXPECT_LT((back - rpy).norm(), 1e-12) << rpy.transpose();
  }
  for (double pitch : {kPi / 2, -kPi / 2}) {
    const Mat3 R = math::rotation_from_roll_pitch_yaw(0.7, pitch, -0.4);
    const Vec3 back = math::roll_pitch_yaw_from_rotation(R);
    EXPECT_EQ(back[2], 0.0);
    EXPECT_NEAR(back[1], pitch, 1e-15);
    EXPECT_LT((math::rotation_from_roll_pitch_yaw(back[0], back[1], back[2]) - R).norm(), 1e-12);
  }
}

// thesis eq. (136): A = Rz(phi) Rx(theta) Rz(psi)
TEST(Rotation, ZxzEulerAngles) {
  EXPECT_LT((math::rotation_from_euler_zxz(0.4, -1.1, 2.3) - rot_z(0.4) * rot_x(-1.1) * rot_z(2.3))
                .norm(),
            1e-15);
  // theta = 0: one turn about z by phi + psi
  EXPECT_LT((math::rotation_from_euler_zxz(0.4, 0.0, 0.9) - rot_z(1.3)).norm(), 1e-15);
  // the nutation tilts y towards z
  EXPECT_LT((math::rotation_from_euler_zxz(0, 0.5, 0) * Vec3::UnitY() -
             Vec3(0, std::cos(0.5), std::sin(0.5)))
                .norm(),
            1e-15);
}

// (A(p) u)_i = p^T S_i p for any p (the homogeneous form, |p|^2 times a rotation);
// exact polynomial identity, 1e-14 relative.
TEST(Rotation, QuadraticFormsReproduceTheRotatedVector) {
  Rng rng(3);
  for (int i = 0; i < 50; ++i) {
    const Vec4 p = rng(0.3, 2.0) * rng.unit4();  // not unit
    const Vec3 u = 3.0 * rng.vec3();
    const auto S = math::rotation_quadratic_forms(u);
    const Vec3 Au = math::rotation_from_euler_parameters(p) * u;
    const double scale = p.squaredNorm() * u.norm();
    EXPECT_LT(
        (Au - p.squaredNorm() * math::rotation_from_euler_parameters(p.normalized()) * u).norm(),
        1e-14 * scale);
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(p.dot(S[k] * p), Au[k], 1e-14 * scale);
      EXPECT_LT((S[k] - S[k].transpose()).norm(), 1e-15 * u.norm());
    }
  }
}

// omega = 2 G p' is the axial vector of A' A^T (world axes) and omega' = 2 Gbar p' = A^T
// omega (body axes), with A' by central differences along the unit-norm path
// p(t) = cos(s t) p0 + sin(s t) p1, p0 . p1 = 0.
TEST(Rotation, AngularVelocityFromEulerParameterRates) {
  Rng rng(4);
  for (int i = 0; i < 20; ++i) {
    const Vec4 p0 = rng.unit4();
    Vec4 p1 = rng.unit4();
    p1 = (p1 - p1.dot(p0) * p0).normalized();
    const double rate = 1.7;
    auto p_at = [&](double t) { return Vec4(std::cos(rate * t) * p0 + std::sin(rate * t) * p1); };
    const Vec4 pd = rate * p1;
    const Mat3 A = math::rotation_from_euler_parameters(p0);
    const Mat3 Ad = (math::rotation_from_euler_parameters(p_at(kH)) -
                     math::rotation_from_euler_parameters(p_at(-kH))) /
                    (2.0 * kH);
    const Mat3 W = Ad * A.transpose();
    EXPECT_LT((W + W.transpose()).norm(), kFdTol);  // skew, to the difference's accuracy
    const Vec3 omega(W(2, 1), W(0, 2), W(1, 0));
    EXPECT_TRUE(near(2.0 * math::euler_g(p0) * pd, omega, kFdTol, 1.0));
    EXPECT_TRUE(near(2.0 * math::euler_gbar(p0) * pd, A.transpose() * omega, kFdTol, 1.0));
  }
}

TEST(Rotation, FrameFromAxisIsRightHanded) {
  Rng rng(5);
  for (int i = 0; i < 50; ++i) {
    const Vec3 axis = 5.0 * rng.vec3();
    const Mat3 F = math::frame_from_axis(axis);
    EXPECT_LT((F.transpose() * F - Mat3::Identity()).norm(), 1e-14);
    EXPECT_NEAR(F.determinant(), 1.0, 1e-14);
    EXPECT_LT((F.col(2) - axis.normalized()).norm(), 1e-15);
  }
}

// ---------------------------------------------------------------------------------------
// 2. markers

namespace {

// every vector the marker has: J = dx/dq, rate = J v, bias = J' v = d/dt (J v) along
// q + t v with v held, Jv = d(J v)/dq and add_hessian(F) = d(J^T F)/dq
void check_marker(const Marker& m, const State& s, Rng& rng) {
  const std::vector<Index> dofs = m.coordinates();
  const Index n = static_cast<Index>(dofs.size());
  const VecX v = gather(s.v, dofs);
  for (int k = 0; k < 4; ++k) {
    const auto which = static_cast<MarkerVector>(k);
    if (!m.has(which)) continue;
    SCOPED_TRACE(m.describe() + ", vector " + std::to_string(k));
    auto eval = [&m, which](const State& t) {
      MarkerVectorEval e;
      m.evaluate(which, t, e);
      return e;
    };
    const MarkerVectorEval e = eval(s);
    ASSERT_EQ(e.J.cols(), n);
    ASSERT_EQ(e.Jv.cols(), n);
    const StateFn value = [&](const State& t) -> VecX { return eval(t).value; };
    const StateFn rate = [&](const State& t) -> VecX { return eval(t).rate; };
    EXPECT_TRUE(near(e.J, fd_dq(s, dofs, value), kFdTol, e.value.norm()));
    EXPECT_TRUE(near(e.rate, e.J * v, 1e-14, 1.0));
    EXPECT_TRUE(near(e.bias, fd_along_v(s, rate), kFdTol, e.rate.norm()));
    EXPECT_TRUE(near(e.Jv, fd_dq(s, dofs, rate), kFdTol, e.rate.norm()));
    const Vec3 F = 100.0 * rng.vec3();
    MatX H = MatX::Zero(n, n);
    m.add_hessian(which, s, F, H);
    const StateFn JtF = [&](const State& t) -> VecX { return eval(t).J.transpose() * F; };
    EXPECT_TRUE(near(H, fd_dq(s, dofs, JtF), kFdTol, F.norm() * (e.J.norm() + 1.0)));
    if (m.linear()) {  // what MarkerPair relies on to skip the Hessian of beams and ground
      EXPECT_EQ(H.norm(), 0.0);
      EXPECT_EQ(e.bias.norm(), 0.0);
      EXPECT_EQ(e.Jv.norm(), 0.0);
    }
  }
}

}  // namespace

TEST(Markers, DerivativesMatchFiniteDifferences) {
  World w(6);
  Rng rng(7);
  for (const auto& m : {w.R1(), w.R2(), w.B1e(), w.B1n(), w.B2e(), w.B2n(), w.G()})
    check_marker(*m, w.s, rng);
  // a marker at the centre of gravity with the body axes: the point is r itself
  check_marker(RigidBodyMarker(w.rb2, Vec3::Zero()), w.s, rng);
  // the identities hold at non-unit Euler parameters too (Newton iterates leave |p| = 1)
  State s = w.s;
  s.q.segment<4>(3) *= 1.3;
  check_marker(*w.R1(), s, rng);
}

// values: r + A u and the rotated local axes on a rigid body (unit p, round-off only);
// r_k and r'_k at a beam node; the straight line r0 + s t and the unit slope t inside an
// element of an undeformed straight beam (cubic Hermite interpolation is exact there);
// the fixed point and frame of ground.
TEST(Markers, ValuesAreThePointsAndAxesTheyDescribe) {
  World w(8);
  const State& s = w.s;
  const Vec3 u(0.5, -0.3, 1.2);
  const RigidBodyMarker m(w.rb1, u, frame_1());
  const Mat3 A = math::rotation_from_euler_parameters(s.q.segment<4>(3));
  EXPECT_LT((m.position(s) - (s.q.head<3>() + A * u)).norm(), 1e-14);
  for (int k = 1; k <= 3; ++k) {
    MarkerVectorEval e;
    m.evaluate(static_cast<MarkerVector>(k), s, e);
    EXPECT_LT((e.value - A * frame_1().col(k - 1)).norm(), 1e-14);
  }
  EXPECT_EQ(m.coordinates(), all_dofs(7));
  EXPECT_FALSE(m.linear());

  const auto node = BeamMarker::at_node(w.beam1, 2);
  const Index n2 = w.beam1.node_index(2);
  EXPECT_EQ(node->describe(), "beam1.n2");
  EXPECT_EQ(node->coordinates().size(), 6u);
  EXPECT_EQ(node->coordinates().front(), n2);
  EXPECT_EQ(node->position(s), Vec3(s.q.segment<3>(n2)));
  MarkerVectorEval e;
  node->evaluate(MarkerVector::kAxisZ, s, e);
  EXPECT_EQ(e.value, Vec3(s.q.segment<3>(n2 + 3)));
  EXPECT_TRUE(node->has(MarkerVector::kAxisZ));
  EXPECT_FALSE(node->has(MarkerVector::kAxisX));
  EXPECT_FALSE(node->has(MarkerVector::kAxisY));
  EXPECT_THROW(node->evaluate(MarkerVector::kAxisX, s, e), std::logic_error);

  State straight = s;
  VecX v0 = s.v;
  w.beam1.write_initial_state(straight.q, v0);
  const Vec3 start(0, 0, 0), end(6, 1, -2);
  const Vec3 t = (end - start).normalized();
  for (double arc : {0.4, 2.9, 5.5}) {
    const BeamMarker inside(w.beam1, arc);
    EXPECT_EQ(inside.coordinates().size(), 12u);
    EXPECT_LT((inside.position(straight) - (start + arc * t)).norm(), 1e-13);
    inside.evaluate(MarkerVector::kAxisZ, straight, e);
    EXPECT_LT((e.value - t).norm(), 1e-13);
  }

  const GroundMarker g(Vec3(1, 2, -3), frame_ground());
  EXPECT_EQ(g.position(s), Vec3(1, 2, -3));
  for (int k = 1; k <= 3; ++k) {
    g.evaluate(static_cast<MarkerVector>(k), s, e);
    EXPECT_EQ(e.value, Vec3(frame_ground().col(k - 1)));
    EXPECT_EQ(e.J.cols(), 0);
  }
  EXPECT_TRUE(g.coordinates().empty());
  EXPECT_EQ(g.body(), nullptr);
}

// ---------------------------------------------------------------------------------------
// 3. joints (and 4. the normalization constraint: same identities)

namespace {

ConstraintEval eval_constraint(const Constraint& c, Index cols, const State& s) {
  const Index rows = c.num_rows();
  ConstraintEval e{VecX::Zero(rows), MatX::Zero(rows, cols), VecX::Zero(rows), VecX::Zero(rows)};
  c.evaluate(s, e);
  return e;
}

// C_q = dC/dq, gamma = -d/dt (C_q v) along q + t v (= -(C_q v)_q v, no time dependence),
// add_multiplier_hessian(mu) = d(C_q^T mu)/dq; a linear constraint has a constant C_q
// (checked at a second, unrelated state) and no Hessian
void check_constraint(const Constraint& c, const State& s, Rng& rng, const State* other = nullptr) {
  const std::vector<Index> dofs = c.coordinates();
  const Index n = static_cast<Index>(dofs.size()), rows = c.num_rows();
  const VecX v = gather(s.v, dofs);
  const ConstraintEval e = eval_constraint(c, n, s);
  const double scale = 1.0 + e.C.norm();
  const StateFn C = [&](const State& t) -> VecX { return eval_constraint(c, n, t).C; };
  EXPECT_TRUE(near(e.Cq, fd_dq(s, dofs, C), kFdTol, scale));
  EXPECT_EQ(e.Ct.norm(), 0.0);
  const StateFn Cdot = [&](const State& t) -> VecX { return eval_constraint(c, n, t).Cq * v; };
  EXPECT_TRUE(near(e.gamma, -fd_along_v(s, Cdot), kFdTol, 1.0 + (e.Cq * v).norm()));
  const VecX mu = 10.0 * rng.vec(rows);
  MatX H = MatX::Zero(n, n);
  c.add_multiplier_hessian(s, mu, H);
  const StateFn CqTmu = [&](const State& t) -> VecX {
    return eval_constraint(c, n, t).Cq.transpose() * mu;
  };
  EXPECT_TRUE(near(H, fd_dq(s, dofs, CqTmu), kFdTol, mu.norm() * (1.0 + e.Cq.norm())));
  EXPECT_LT((H - H.transpose()).norm(), 1e-12 * (1.0 + H.norm()));
  if (c.is_linear()) {
    EXPECT_EQ(H.norm(), 0.0);
    if (other) {
      EXPECT_LT((eval_constraint(c, n, *other).Cq - e.Cq).norm(), 1e-14 * (1.0 + e.Cq.norm()));
    }
  }
}

struct JointCase {
  std::string label;
  JointType type;
  MarkerFactory from, to;
  Index rows;
  bool linear;
};

Index rows_of(JointType type, Index fixed_rows) {
  switch (type) {
    case JointType::kBall:
      return 3;
    case JointType::kUniversal:
      return 4;
    case JointType::kRevolute:
      return 5;
    case JointType::kCylindrical:
      return 4;
    case JointType::kPrismatic:
      return 5;
    case JointType::kFixed:
      return fixed_rows;
  }
  return -1;
}

constexpr JointType kAllTypes[] = {JointType::kBall,      JointType::kUniversal,
                                   JointType::kRevolute,  JointType::kCylindrical,
                                   JointType::kPrismatic, JointType::kFixed};
constexpr JointType kBeamRigidTypes[] = {JointType::kBall, JointType::kRevolute,
                                         JointType::kCylindrical, JointType::kFixed};

std::vector<JointCase> joint_cases() {
  std::vector<JointCase> cases;
  auto add = [&](const std::string& pairing, JointType t, MarkerFactory from, MarkerFactory to,
                 Index fixed_rows, bool linear) {
    cases.push_back({pairing + " " + std::string(joint_type_name(t)), t, from, to,
                     rows_of(t, fixed_rows), linear});
  };
  for (JointType t : kAllTypes) {
    add("rigid-rigid", t, &World::R1, &World::R2, 6, false);
    add("rigid-ground", t, &World::R1, &World::G, 6, false);
    add("ground-rigid", t, &World::G, &World::R2, 6, false);
  }
  for (JointType t : kBeamRigidTypes) {
    add("rigid-beam(element)", t, &World::R1, &World::B1e, 5, false);
    add("beam(node)-rigid", t, &World::B1n, &World::R2, 5, false);  // swapped inside
    add("beam(element)-rigid", t, &World::B2e, &World::R1, 5, false);
    add("ground-beam(element)", t, &World::G, &World::B1e, 5, true);
    add("beam(node)-ground", t, &World::B1n, &World::G, 5, true);  // swapped inside
  }
  for (JointType t : {JointType::kBall, JointType::kFixed}) {
    add("beam-beam(elements)", t, &World::B1e, &World::B2e, 6, true);
    add("beam-beam(nodes)", t, &World::B1n, &World::B2n, 6, true);
    add("beam-beam(node, element)", t, &World::B2n, &World::B1e, 6, true);
  }
  return cases;
}

}  // namespace

TEST(Joints, RowCountsLinearityAndDerivatives) {
  World w(9);
  World other(10);  // another state of the same numbering, for the linearity check
  Rng rng(11);
  for (const JointCase& jc : joint_cases()) {
    SCOPED_TRACE(jc.label);
    auto from = (w.*jc.from)(), to = (w.*jc.to)();
    const std::string from_name = from->describe(), to_name = to->describe();
    const Joint joint("j", jc.type, std::move(from), std::move(to));
    EXPECT_EQ(joint.num_rows(), jc.rows);
    EXPECT_EQ(joint.is_linear(), jc.linear);
    // the markers as the user named them, whatever the internal order
    EXPECT_EQ(joint.from().describe(), from_name);
    EXPECT_EQ(joint.to().describe(), to_name);
    check_constraint(joint, w.s, rng, &other.s);
  }
}

// Joints whose markers cannot carry the type are refused with std::invalid_argument.
TEST(Joints, RefusesTypesTheMarkersCannotCarry) {
  World w(12);
  auto make = [&](JointType t, MarkerFactory a, MarkerFactory b) {
    return Joint("j", t, (w.*a)(), (w.*b)());
  };
  for (JointType t : {JointType::kUniversal, JointType::kPrismatic}) {
    EXPECT_THROW(make(t, &World::R1, &World::B1e), std::invalid_argument);
    EXPECT_THROW(make(t, &World::B1n, &World::R2), std::invalid_argument);
    EXPECT_THROW(make(t, &World::G, &World::B1n), std::invalid_argument);
    EXPECT_THROW(make(t, &World::B1e, &World::G), std::invalid_argument);
  }
  for (JointType t : {JointType::kRevolute, JointType::kCylindrical, JointType::kUniversal,
                      JointType::kPrismatic}) {
    EXPECT_THROW(make(t, &World::B1e, &World::B2e), std::invalid_argument);
    EXPECT_THROW(make(t, &World::B1n, &World::B2n), std::invalid_argument);
  }
  EXPECT_NO_THROW(make(JointType::kBall, &World::B1e, &World::B2e));
  EXPECT_NO_THROW(make(JointType::kFixed, &World::B1e, &World::B2e));
  EXPECT_NO_THROW(make(JointType::kRevolute, &World::B1n, &World::R2));
}

// Meaning of the rows: a rigid body joined to ground at a configuration where the
// marker frames coincide satisfies every type; each type keeps C = 0 exactly under
// the relative motions it allows (rotation about any axis for ball, about the common
// z for revolute, sliding along z for prismatic, both for cylindrical, rotations about
// from-x and to-y for universal) and is violated (|C| > 1e-3) by the others. C is
// evaluated to round-off (1e-12 on positions of size 10).
TEST(Joints, RowsVanishExactlyOnTheMotionsEachTypeAllows) {
  World w(13);
  const Vec3 u(0.5, -0.3, 1.2);
  const Mat3 A0 = math::rotation_from_roll_pitch_yaw(0.4, -0.2, 0.9);
  const Vec3 r0(3, -1, 2);
  const Vec3 P = r0 + A0 * u;      // the joint point
  const Mat3 Fg = A0 * frame_1();  // ground frame = the body marker's frame
  auto place = [&](const Mat3& R, const Vec3& shift) {
    // rotate the body by R about P, then translate it by shift
    State s = w.s;
    s.q.segment<3>(0) = P + R * (r0 - P) + shift;
    s.q.segment<4>(3) = math::euler_parameters_from_rotation(R * A0);
    return s;
  };
  const Vec3 x = Fg.col(0), y = Fg.col(1), z = Fg.col(2);
  struct Motion {
    std::string name;
    State s;
    std::vector<JointType> satisfied;
  };
  const Mat3 Rx = Eigen::AngleAxisd(0.5, x).toRotationMatrix();
  const Mat3 universal = Eigen::AngleAxisd(0.3, Rx * y).toRotationMatrix() * Rx;
  using enum JointType;
  const std::vector<Motion> motions = {
      {"none",
       place(Mat3::Identity(), Vec3::Zero()),
       {kBall, kUniversal, kRevolute, kCylindrical, kPrismatic, kFixed}},
      {"rotation about a skew axis",
       place(Eigen::AngleAxisd(0.8, Vec3(1, 2, 3).normalized()).toRotationMatrix(), Vec3::Zero()),
       {kBall}},
      {"rotation about z",
       place(Eigen::AngleAxisd(0.7, z).toRotationMatrix(), Vec3::Zero()),
       {kBall, kRevolute, kCylindrical}},
      {"sliding along z", place(Mat3::Identity(), 0.4 * z), {kCylindrical, kPrismatic}},
      {"screw along z",
       place(Eigen::AngleAxisd(-0.6, z).toRotationMatrix(), 0.3 * z),
       {kCylindrical}},
      {"rotation about from-x, then to-y", place(universal, Vec3::Zero()), {kBall, kUniversal}},
  };
  for (const Motion& mo : motions) {
    for (JointType t : kAllTypes) {
      SCOPED_TRACE(mo.name + ", " + std::string(joint_type_name(t)));
      const Joint j("j", t, std::make_unique<GroundMarker>(P, Fg),
                    std::make_unique<RigidBodyMarker>(w.rb1, u, frame_1()));
      const Index n = static_cast<Index>(j.coordinates().size());
      const VecX C = eval_constraint(j, n, mo.s).C;
      const bool allowed =
          std::find(mo.satisfied.begin(), mo.satisfied.end(), t) != mo.satisfied.end();
      if (allowed)
        EXPECT_LT(C.norm(), 1e-12);
      else
        EXPECT_GT(C.norm(), 1e-3);
    }
  }
}

// The same for joints on beams, whose marker axis is the slope r' (no torsion, any
// stretch): beam-beam ball and fixed at a node shared in position (and, for fixed, in
// slope r'); a beam node joined to a rigid body whose marker z axis lies along the
// slope (beam named first, so swapped inside), which may spin about the slope but not
// tilt; a beam point on a ground line, which may slide along it (cylindrical).
TEST(Joints, BeamRowsVanishExactlyOnTheMotionsEachTypeAllows) {
  World w(25);
  using enum JointType;
  auto C_of = [](const Joint& j, const State& s) {
    return eval_constraint(j, static_cast<Index>(j.coordinates().size()), s).C;
  };
  const Index n3 = w.beam1.node_index(3), m0 = w.beam2.node_index(0);
  const Vec3 P = w.s.q.segment<3>(n3), t = w.s.q.segment<3>(n3 + 3), th = t.normalized();

  // beam-beam at nodes
  State s = w.s;
  s.q.segment<6>(m0) = s.q.segment<6>(n3);
  const Joint ball("b", kBall, w.B1n(), w.B2n()), fixed("f", kFixed, w.B1n(), w.B2n());
  EXPECT_LT(C_of(ball, s).norm(), 1e-12);
  EXPECT_LT(C_of(fixed, s).norm(), 1e-12);
  State bent = s;
  bent.q.segment<3>(m0 + 3) = Eigen::AngleAxisd(0.3, th.unitOrthogonal()) * t;
  EXPECT_LT(C_of(ball, bent).norm(), 1e-12);
  EXPECT_GT(C_of(fixed, bent).norm(), 1e-3);
  State stretched = s;
  stretched.q.segment<3>(m0 + 3) *= 1.1;
  EXPECT_GT(C_of(fixed, stretched).norm(), 1e-3);  // eq. (154-155): r' itself is continuous

  // beam node - rigid body, the body's marker z along the slope through the node
  const Vec3 u2(-0.8, 0.4, 0.1);
  const Mat3 A2 = math::frame_from_axis(th) * frame_2().transpose();
  const Vec3 r2 = P - A2 * u2;
  auto place = [&](const Mat3& R, const Vec3& shift) {  // turn rb2 by R about P, shift
    State st = w.s;
    st.q.segment<3>(7) = P + R * (r2 - P) + shift;
    st.q.segment<4>(10) = math::euler_parameters_from_rotation(R * A2);
    return st;
  };
  struct Motion {
    std::string name;
    State s;
    std::vector<JointType> satisfied;
  };
  const Vec3 tilt_axis = (A2 * frame_2()).col(0);
  const std::vector<Motion> motions = {
      {"none", place(Mat3::Identity(), Vec3::Zero()), {kBall, kRevolute, kCylindrical, kFixed}},
      {"spin about the slope",
       place(Mat3(Eigen::AngleAxisd(0.9, th)), Vec3::Zero()),
       {kBall, kRevolute, kCylindrical, kFixed}},
      {"slide along the slope", place(Mat3::Identity(), 0.3 * th), {kCylindrical}},
      {"tilt", place(Mat3(Eigen::AngleAxisd(0.2, tilt_axis)), Vec3::Zero()), {kBall}},
  };
  for (const Motion& mo : motions) {
    for (JointType type : kBeamRigidTypes) {
      SCOPED_TRACE(mo.name + ", " + std::string(joint_type_name(type)));
      const Joint j("j", type, w.B1n(), w.R2());
      const bool allowed =
          std::find(mo.satisfied.begin(), mo.satisfied.end(), type) != mo.satisfied.end();
      if (allowed)
        EXPECT_LT(C_of(j, mo.s).norm(), 1e-12);
      else
        EXPECT_GT(C_of(j, mo.s).norm(), 1e-3);
    }
  }

  // a point inside a beam element on a ground line along its slope
  const auto inside = w.B1e();
  MarkerVectorEval e;
  inside->evaluate(MarkerVector::kAxisZ, w.s, e);
  const Vec3 Pe = inside->position(w.s), te = e.value;
  const Joint cyl("c", kCylindrical, std::make_unique<GroundMarker>(Pe, math::frame_from_axis(te)),
                  w.B1e());
  const Joint fix("f", kFixed, std::make_unique<GroundMarker>(Pe, math::frame_from_axis(te)),
                  w.B1e());
  EXPECT_LT(C_of(cyl, w.s).norm(), 1e-12);
  EXPECT_LT(C_of(fix, w.s).norm(), 1e-12);
  State slid = w.s;
  for (int k = 0; k < w.beam1.num_nodes(); ++k)
    slid.q.segment<3>(w.beam1.node_index(k)) += 0.3 * te.normalized();
  EXPECT_LT(C_of(cyl, slid).norm(), 1e-12);
  EXPECT_GT(C_of(fix, slid).norm(), 1e-3);
}

// reaction(mu) is the constraint force -C_q^T mu on the body named "to", read as a force
// F at the "to" marker point and a moment M: on a rigid "to" body its generalized force
// is F on r and, for a virtual rotation dtheta (dp = 1/2 G^T dtheta), (M + (P - r) x F)
// . dtheta. Covers the internal swap (beam named first). Algebraic identity: 1e-11.
TEST(Joints, ReactionIsTheConstraintForceOnTheToBody) {
  World w(14);
  Rng rng(15);
  std::vector<JointCase> cases;
  for (JointType t : kAllTypes) {
    cases.push_back({"rigid-rigid", t, &World::R1, &World::R2, 0, false});
    cases.push_back({"ground-rigid", t, &World::G, &World::R2, 0, false});
  }
  for (JointType t : kBeamRigidTypes) {
    cases.push_back({"beam(node)-rigid", t, &World::B1n, &World::R2, 0, false});
    cases.push_back({"beam(element)-rigid", t, &World::B2e, &World::R2, 0, false});
  }
  const Index o = w.rb2.offset();
  const Vec4 p = w.s.q.segment<4>(o + 3);
  for (const JointCase& jc : cases) {
    SCOPED_TRACE(jc.label + " " + std::string(joint_type_name(jc.type)));
    const Joint j("j", jc.type, (w.*jc.from)(), (w.*jc.to)());
    const std::vector<Index> dofs = j.coordinates();
    const VecX mu = 1e3 * rng.vec(j.num_rows());
    const ConstraintEval e = eval_constraint(j, static_cast<Index>(dofs.size()), w.s);
    VecX Qc = VecX::Zero(w.n);
    const VecX local = -e.Cq.transpose() * mu;
    for (std::size_t i = 0; i < dofs.size(); ++i) Qc[dofs[i]] += local[static_cast<Index>(i)];
    const auto [F, M] = j.reaction(w.s, mu);
    const double scale = Qc.norm() + F.norm() + M.norm();
    EXPECT_TRUE(near(Qc.segment<3>(o), F, 1e-11, scale));
    const Vec3 arm = j.to().position(w.s) - w.s.q.segment<3>(o);
    const Vec3 rotation_work = 0.5 * math::euler_g(p) * Qc.segment<4>(o + 3);
    EXPECT_TRUE(near(rotation_work, M + arm.cross(F), 1e-11, scale));
  }
}

// |p|^2 - 1: C, C_q, gamma and the Hessian by differences, at unit and non-unit p
TEST(EulerParameterNormalization, DerivativesMatchFiniteDifferences) {
  World w(16);
  Rng rng(17);
  const EulerParameterNormalization c(w.rb2);
  EXPECT_EQ(c.num_rows(), 1);
  EXPECT_FALSE(c.is_linear());
  const std::vector<Index> dofs = c.coordinates();
  EXPECT_EQ(dofs, (std::vector<Index>{10, 11, 12, 13}));
  check_constraint(c, w.s, rng);
  State s = w.s;
  s.q.segment<4>(10) *= 1.2;
  EXPECT_NEAR(eval_constraint(c, 4, s).C[0], 0.44, 1e-14);
  check_constraint(c, s, rng);
}

// ---------------------------------------------------------------------------------------
// 5. rigid body

// M = diag(m I, 4 Gbar^T J' Gbar) (exact, 1e-12 relative); the quadratic-velocity force
// does no work (Q . v = 0, since Gbar(p') p' = 0) and its tangents dQ/dq, dQ/dv match
// differences; the matrix is linear in (km, kq, kv); T = 1/2 v^T M v.
TEST(RigidBody, MassBlockAndQuadraticVelocityForce) {
  World w(18);
  const RigidBody& b = w.rb1;
  const Probe probe = Probe::of(w.n, w.rb1);
  const State& s = w.s;
  const Vec4 p = s.q.segment<4>(3);
  const Mat34 Gb = math::euler_gbar(p);
  MatX Mexp = MatX::Zero(w.n, w.n);
  Mexp.topLeftCorner<3, 3>() = b.mass() * Mat3::Identity();
  Mexp.block<4, 4>(3, 3) = 4.0 * Gb.transpose() * b.inertia() * Gb;
  const MatX M = probe.matrix(s, kMass);
  EXPECT_TRUE(near(M, Mexp, 1e-12, 0.0));
  EXPECT_NEAR(b.kinetic_energy(s), 0.5 * s.v.dot(M * s.v), 1e-12 * s.v.dot(M * s.v));

  const VecX Q = probe.forces(s);
  EXPECT_EQ(Q.head<3>().norm(), 0.0);
  EXPECT_GT(Q.segment<4>(3).norm(), 1.0);
  EXPECT_LT(std::abs(Q.dot(s.v)), 1e-12 * Q.norm() * s.v.norm());
  const std::vector<Index> dofs = all_dofs(w.n);
  const StateFn forces = [&](const State& t) -> VecX { return probe.forces(t); };
  const MatX Kq = probe.matrix(s, kStiffness), Kv = probe.matrix(s, kDamping);
  EXPECT_TRUE(near(-Kq, fd_dq(s, dofs, forces), kFdTol, Q.norm()));
  EXPECT_TRUE(near(-Kv, fd_dv(s, dofs, forces), kFdTol, Q.norm()));
  EXPECT_TRUE(near(probe.matrix(s, MatrixScales{2.0, -3.0, 5.0}), 2.0 * M - 3.0 * Kq + 5.0 * Kv,
                   1e-13, 0.0));
}

// the initial state carries the orientation and the world angular velocity:
// p from A, p' = 1/2 G^T omega with p . p' = 0; the accessors read them back
TEST(RigidBody, InitialStateAndKinematics) {
  RigidBodyInitial init;
  init.position = Vec3(1, -2, 3);
  init.orientation = math::rotation_from_roll_pitch_yaw(0.2, -0.7, 2.5);
  init.velocity = Vec3(0.3, 0.1, -0.2);
  init.angular_velocity = Vec3(0.5, -1.5, 0.8);
  RigidBody b("b", 100.0, inertia_1(), init);
  b.set_offset(0);
  State s;
  s.q = VecX::Zero(7);
  s.v = VecX::Zero(7);
  b.write_initial_state(s.q, s.v);
  EXPECT_LT((b.orientation(s) - init.orientation).norm(), 1e-14);
  EXPECT_LT((b.position(s) - init.position).norm(), 1e-15);
  EXPECT_LT((b.velocity(s) - init.velocity).norm(), 1e-15);
  EXPECT_LT((b.angular_velocity(s) - init.angular_velocity).norm(), 1e-14);
  EXPECT_LT(std::abs(s.q.segment<4>(3).dot(s.v.segment<4>(3))), 1e-15);
  const Mat3 A = init.orientation;
  const Vec3 w = init.angular_velocity;
  EXPECT_NEAR(
      b.kinetic_energy(s),
      0.5 * 100.0 * init.velocity.squaredNorm() + 0.5 * w.dot(A * inertia_1() * A.transpose() * w),
      1e-12 * 2000.0);
  EXPECT_LT((b.angular_momentum(s) - A * inertia_1() * A.transpose() * w).norm(), 1e-11);
}

// A free body: [M C_q^T; C_q 0] [a; lambda] = [Q; gamma] with the normalization row
// gives the body-axis angular acceleration w'_dot = 2 Gbar p'' (Gbar(p') p' = 0) that
// satisfies Euler's equations J' w'_dot + w' x J' w' = 0 (round-off of a well-conditioned
// 8x8 solve: 1e-10 of |J'| |w'|^2), no acceleration of the centre of gravity, and a
// constant angular momentum (central difference along q + t v + t^2/2 a with h = 1e-5:
// truncation ~ h^2 |w'|^2 ~ 1e-9 and round-off eps/h ~ 1e-11 relative; 1e-7 of
// |J'| |w'|^2).
TEST(RigidBody, FreeMotionFollowsEulersEquations) {
  Rng rng(19);
  for (int trial = 0; trial < 10; ++trial) {
    RigidBody b("b", 1200.0, trial % 2 ? inertia_1() : inertia_2(), {});
    b.set_offset(0);
    const EulerParameterNormalization norm(b);
    State s;
    s.q = VecX::Zero(7);
    s.v = VecX::Zero(7);
    s.q.head<3>() = rng.vec3();
    const Vec4 p = rng.unit4();
    s.q.segment<4>(3) = p;
    const Vec3 wb = 2.0 * rng.vec3();  // body axes
    s.v.head<3>() = rng.vec3();
    s.v.segment<4>(3) = 0.5 * math::euler_gbar(p).transpose() * wb;
    const Probe probe = Probe::of(7, b);
    const MatX M = probe.matrix(s, kMass);
    const VecX Q = probe.forces(s);
    const ConstraintEval c = eval_constraint(norm, 4, s);
    Eigen::Matrix<double, 8, 8> K = Eigen::Matrix<double, 8, 8>::Zero();
    K.topLeftCorner<7, 7>() = M;
    K.block<1, 4>(7, 3) = c.Cq;
    K.block<4, 1>(3, 7) = c.Cq.transpose();
    Eigen::Matrix<double, 8, 1> rhs;
    rhs << Q, c.gamma;
    const Eigen::Matrix<double, 8, 1> x = K.fullPivLu().solve(rhs);
    const Vec3 wb_check = 2.0 * math::euler_gbar(p) * s.v.segment<4>(3);
    EXPECT_LT((wb_check - wb).norm(), 1e-14);
    const Mat3 J = b.inertia();
    const Vec3 wdot = 2.0 * math::euler_gbar(p) * x.segment<4>(3);
    const double scale = J.norm() * wb.squaredNorm();
    EXPECT_LT((J * wdot + wb.cross(J * wb)).norm(), 1e-10 * scale);
    EXPECT_LT(x.head<3>().norm(), 1e-12);
    // p'' keeps |p| = 1 to second order: p . p'' = -|p'|^2
    EXPECT_NEAR(p.dot(x.segment<4>(3)), -s.v.segment<4>(3).squaredNorm(), 1e-12);

    const double h = 1e-5;
    auto momentum = [&](double t) {
      State st = s;
      st.q += t * s.v + 0.5 * t * t * x.head<7>();
      st.v += t * x.head<7>();
      return b.angular_momentum(st);
    };
    EXPECT_LT(((momentum(h) - momentum(-h)) / (2 * h)).norm(), 1e-7 * scale);
  }
}
