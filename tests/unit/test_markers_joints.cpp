// Rotations, markers, joints, the rigid body and the force elements written against
// markers. Every derivative that the Newton and RK4 paths rely on (marker Jacobians,
// acceleration biases, rate Jacobians and Hessian contractions; joint C_q, gamma and
// multiplier Hessians; the tangents of the rigid body and of the force elements) is
// compared with central differences, and the rotation utilities, the rigid body's
// equations of motion and the point moment with their closed forms.
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
#include <functional>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "seaflex/constraints/joint.hpp"
#include "seaflex/elements/ancf_beam.hpp"
#include "seaflex/elements/rigid_body.hpp"
#include "seaflex/forces/constant_tensioner.hpp"
#include "seaflex/forces/pneumatic_cylinder.hpp"
#include "seaflex/forces/point_load.hpp"
#include "seaflex/forces/rope.hpp"
#include "seaflex/forces/rotational_spring.hpp"
#include "seaflex/forces/spring_damper.hpp"
#include "seaflex/math/rotation.hpp"
#include "seaflex/math/sparse_block_assembler.hpp"

using namespace seaflex;

namespace {

using math::Mat34;
using math::Mat4;
using math::Vec4;

constexpr double kPi = std::numbers::pi;
constexpr double kH = 1e-6;      // central-difference step
constexpr double kFdTol = 1e-7;  // see the header

class Rng {
 public:
  explicit Rng(unsigned seed) : gen_(seed) {}
  double operator()(double lo = -1.0, double hi = 1.0) {
    return std::uniform_real_distribution<double>(lo, hi)(gen_);
  }
  VecX vec(Index n) {
    VecX x(n);
    for (Index i = 0; i < n; ++i) x[i] = (*this)();
    return x;
  }
  Vec3 vec3() { return vec(3); }
  Vec4 unit4() {
    Vec4 p;
    do p = vec(4);
    while (p.norm() < 0.2);
    return p.normalized();
  }

 private:
  std::mt19937 gen_;
};

using StateFn = std::function<VecX(const State&)>;

// d f / d q[dofs[j]] by central differences
MatX fd_dq(const State& s, const std::vector<Index>& dofs, const StateFn& f) {
  const VecX f0 = f(s);
  MatX D(f0.size(), static_cast<Index>(dofs.size()));
  for (std::size_t j = 0; j < dofs.size(); ++j) {
    State sp = s, sm = s;
    sp.q[dofs[j]] += kH;
    sm.q[dofs[j]] -= kH;
    D.col(static_cast<Index>(j)) = (f(sp) - f(sm)) / (2.0 * kH);
  }
  return D;
}

// d f / d q[dofs[j]] by the fourth-order central difference, for energies: near a
// minimum (a spring at rest) the gradient is zero and the h^2 V''' / 6 truncation of
// the plain difference, about 1e-12 times the stiffness, would be all that is left;
// here it is h^4 V^(5) / 30
MatX fd4_dq(const State& s, const std::vector<Index>& dofs, const StateFn& f) {
  const VecX f0 = f(s);
  MatX D(f0.size(), static_cast<Index>(dofs.size()));
  for (std::size_t j = 0; j < dofs.size(); ++j) {
    auto at = [&](double t) {
      State st = s;
      st.q[dofs[j]] += t;
      return f(st);
    };
    D.col(static_cast<Index>(j)) =
        (at(-2.0 * kH) - 8.0 * at(-kH) + 8.0 * at(kH) - at(2.0 * kH)) / (12.0 * kH);
  }
  return D;
}

// d f / d v[dofs[j]] by central differences
MatX fd_dv(const State& s, const std::vector<Index>& dofs, const StateFn& f) {
  const VecX f0 = f(s);
  MatX D(f0.size(), static_cast<Index>(dofs.size()));
  for (std::size_t j = 0; j < dofs.size(); ++j) {
    State sp = s, sm = s;
    sp.v[dofs[j]] += kH;
    sm.v[dofs[j]] -= kH;
    D.col(static_cast<Index>(j)) = (f(sp) - f(sm)) / (2.0 * kH);
  }
  return D;
}

// d/dt f(q + t v, v) at t = 0, v held
VecX fd_along_v(const State& s, const StateFn& f) {
  State sp = s, sm = s;
  sp.q += kH * s.v;
  sm.q -= kH * s.v;
  return (f(sp) - f(sm)) / (2.0 * kH);
}

std::vector<Index> all_dofs(Index n) {
  std::vector<Index> d(static_cast<std::size_t>(n));
  for (Index i = 0; i < n; ++i) d[static_cast<std::size_t>(i)] = i;
  return d;
}

VecX gather(const VecX& x, const std::vector<Index>& dofs) {
  VecX y(static_cast<Index>(dofs.size()));
  for (std::size_t i = 0; i < dofs.size(); ++i) y[static_cast<Index>(i)] = x[dofs[i]];
  return y;
}

// |a - b| <= tol (|b| + scale), scale standing for the size of the differenced function
testing::AssertionResult near(const MatX& a, const MatX& b, double tol, double scale) {
  if (a.rows() != b.rows() || a.cols() != b.cols())
    return testing::AssertionFailure()
           << "sizes " << a.rows() << "x" << a.cols() << " and " << b.rows() << "x" << b.cols();
  const double err = (a - b).norm(), bound = tol * (b.norm() + scale);
  if (err <= bound) return testing::AssertionSuccess();
  return testing::AssertionFailure()
         << "|a - b| = " << err << " > " << bound << " (|b| = " << b.norm() << ")\na =\n"
         << a << "\nb =\n"
         << b;
}

Mat3 rot_x(double a) {
  Mat3 R;
  R << 1, 0, 0, 0, std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a);
  return R;
}
Mat3 rot_y(double a) {
  Mat3 R;
  R << std::cos(a), 0, std::sin(a), 0, 1, 0, -std::sin(a), 0, std::cos(a);
  return R;
}
Mat3 rot_z(double a) {
  Mat3 R;
  R << std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a), 0, 0, 0, 1;
  return R;
}

Mat3 inertia_1() {
  Mat3 J;
  J << 2000, 150, -80, 150, 3000, 120, -80, 120, 4000;
  return J;
}
Mat3 inertia_2() {
  Mat3 J;
  J << 900, -40, 60, -40, 700, 30, 60, 30, 1100;
  return J;
}

// local frames of the rigid-body markers: rotated, so that no axis is a body axis
Mat3 frame_1() {
  return math::rotation_from_roll_pitch_yaw(0.3, -0.5, 1.1);
}
Mat3 frame_2() {
  return math::rotation_from_roll_pitch_yaw(-1.2, 0.4, -0.7);
}
Mat3 frame_ground() {
  return math::rotation_from_roll_pitch_yaw(0.6, 0.2, 2.0);
}

// Two rigid bodies and two beams numbered one after another (rb1 0-6, rb2 7-13, beam1
// 14-37, beam2 38-55) in a random state: unit Euler parameters with arbitrary rates p'
// (the derivative identities hold for every v), beams perturbed off their straight
// shapes, random beam velocities.
struct World {
  RigidBody rb1{"rb1", 1500.0, inertia_1(), {}};
  RigidBody rb2{"rb2", 800.0, inertia_2(), {}};
  AncfBeam beam1{"beam1", BeamGeometry::straight(Vec3(0, 0, 0), Vec3(6, 1, -2), 3),
                 BeamSection::pipe(0.3, 0.25, 2.1e11, 7850), BeamOptions{}};
  AncfBeam beam2{"beam2", BeamGeometry::straight(Vec3(1, 4, 0), Vec3(5, 3, 1), 2),
                 BeamSection::pipe(0.2, 0.15, 2.1e11, 7850), BeamOptions{}};
  State s;
  Index n = 0;

  explicit World(unsigned seed) {
    for (Body* b : bodies()) {
      b->set_offset(n);
      n += b->num_coordinates();
    }
    s.q = VecX::Zero(n);
    s.v = VecX::Zero(n);
    for (Body* b : bodies()) b->write_initial_state(s.q, s.v);
    Rng rng(seed);
    for (RigidBody* r : {&rb1, &rb2}) {
      s.q.segment<3>(r->offset()) = 2.0 * rng.vec3();
      s.q.segment<4>(r->offset() + 3) = rng.unit4();
      s.v.segment<7>(r->offset()) = rng.vec(7);
    }
    for (AncfBeam* b : {&beam1, &beam2}) {
      const Index m = b->num_coordinates();
      s.q.segment(b->offset(), m) += 0.1 * rng.vec(m);
      s.v.segment(b->offset(), m) = rng.vec(m);
    }
  }
  std::vector<Body*> bodies() { return {&rb1, &rb2, &beam1, &beam2}; }

  // the markers used throughout
  std::unique_ptr<Marker> R1() const {
    return std::make_unique<RigidBodyMarker>(rb1, Vec3(0.5, -0.3, 1.2), frame_1());
  }
  std::unique_ptr<Marker> R2() const {
    return std::make_unique<RigidBodyMarker>(rb2, Vec3(-0.8, 0.4, 0.1), frame_2());
  }
  std::unique_ptr<Marker> B1e() const {  // inside element 1 of beam1 (elements 2.14 m)
    return std::make_unique<BeamMarker>(beam1, 2.9);
  }
  std::unique_ptr<Marker> B1n() const { return BeamMarker::at_node(beam1, 3); }
  std::unique_ptr<Marker> B2e() const { return std::make_unique<BeamMarker>(beam2, 1.1); }
  std::unique_ptr<Marker> B2n() const { return BeamMarker::at_node(beam2, 0); }
  std::unique_ptr<Marker> G() const {
    return std::make_unique<GroundMarker>(Vec3(1, 2, -3), frame_ground());
  }
};

// Assembles one body or force alone into its own pattern: Q, and the dense matrix
// km M - kq dQ/dq - kv dQ/dv.
class Probe {
 public:
  using Assemble = std::function<void(const State&, AssemblyTarget&)>;
  Probe(Index n, const std::function<void(math::SparseBlockAssembler&)>& declare, Assemble assemble)
      : n_(n), assemble_(std::move(assemble)) {
    pattern_.resize(n, n);
    declare(pattern_);
    pattern_.finalize();
  }
  static Probe of(Index n, Force& f) {
    return Probe(
        n, [&f](math::SparseBlockAssembler& p) { f.declare_blocks(p); },
        [&f](const State& s, AssemblyTarget& t) { f.assemble(s, 1.0, t); });
  }
  static Probe of(Index n, Body& b) {
    return Probe(
        n, [&b](math::SparseBlockAssembler& p) { b.declare_blocks(p); },
        [&b](const State& s, AssemblyTarget& t) { b.assemble(s, t); });
  }
  VecX forces(const State& s) const {
    VecX Q = VecX::Zero(n_);
    AssemblyTarget t;
    t.forces = &Q;
    assemble_(s, t);
    return Q;
  }
  MatX matrix(const State& s, MatrixScales k) const {
    math::SparseBlockAssembler m = pattern_;
    m.set_zero();
    AssemblyTarget t;
    t.matrix = &m;
    t.scales = k;
    assemble_(s, t);
    return MatX(m.matrix());
  }

 private:
  Index n_;
  Assemble assemble_;
  math::SparseBlockAssembler pattern_;
};

constexpr MatrixScales kMass{1.0, 0.0, 0.0};
constexpr MatrixScales kStiffness{0.0, 1.0, 0.0};
constexpr MatrixScales kDamping{0.0, 0.0, 1.0};

}  // namespace

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

using MarkerFactory = std::unique_ptr<Marker> (World::*)() const;

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

// ---------------------------------------------------------------------------------------
// 6. force elements

namespace {

// Q = -dV/dq with the velocities zero (the conservative part, for conservative
// elements); the assembled matrix with kq = 1 is -dQ/dq at state s_q and with kv = 1 is
// -dQ/dv at state s_v (two states because the rotational spring's damping q-derivative
// is left out of its tangent by design, so its q-tangent is checked at rest); no mass.
void check_force(Force& f, const World& w, const State& s_q, const State& s_v,
                 bool conservative = true) {
  const Probe probe = Probe::of(w.n, f);
  const std::vector<Index> dofs = all_dofs(w.n);
  State rest = s_q;
  rest.v.setZero();
  if (conservative) {
    const VecX Q0 = probe.forces(rest);
    const StateFn V = [&](const State& t) -> VecX {
      return VecX::Constant(1, f.potential_energy(t));
    };
    EXPECT_TRUE(near(Q0, -fd4_dq(rest, dofs, V).transpose(), kFdTol, 1.0 + std::abs(V(rest)[0])));
  }
  const StateFn forces = [&](const State& t) -> VecX { return probe.forces(t); };
  EXPECT_TRUE(near(-probe.matrix(s_q, kStiffness), fd_dq(s_q, dofs, forces), kFdTol,
                   probe.forces(s_q).norm()));
  EXPECT_TRUE(near(-probe.matrix(s_v, kDamping), fd_dv(s_v, dofs, forces), kFdTol,
                   probe.forces(s_v).norm()));
  EXPECT_EQ(probe.matrix(s_q, kMass).norm(), 0.0);
}

double distance(const Marker& a, const Marker& b, const State& s) {
  return (b.position(s) - a.position(s)).norm();
}

}  // namespace

// linear and table laws, damped, between rigid-body and beam markers and ground; the
// table law both inside the table and beyond its end; a slack element in compression
// carries nothing; the damping's q-derivative is part of the tangent (tested with
// velocities)
TEST(SpringDamper, ForceIsMinusEnergyGradientAndTangentsMatchDifferences) {
  World w(20);
  const State& s = w.s;
  const SpringLaw table = SpringLaw::table({-1.0, 0.0, 0.5, 2.0}, {-2e4, 0.0, 6e4, 1e5});
  struct Case {
    std::string label;
    MarkerFactory a, b;
    SpringLaw law;
    double extension, damping;
  };
  const std::vector<Case> cases = {
      {"linear rigid-beam(element)", &World::R1, &World::B1e, SpringLaw::linear(2e5), 0.7, 3e3},
      {"linear beam(node)-ground", &World::B1n, &World::G, SpringLaw::linear(5e4), -0.2, 1e3},
      {"linear rigid-rigid", &World::R1, &World::R2, SpringLaw::linear(1e5), 0.3, 0.0},
      {"table rigid-rigid", &World::R1, &World::R2, table, 0.3, 2e3},
      {"table beyond the end, rigid-ground", &World::G, &World::R2, table, 3.0, 2e3},
      {"table below the start, beam-beam", &World::B1e, &World::B2n, table, -1.5, 500.0},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.label);
    auto a = (w.*c.a)(), b = (w.*c.b)();
    const double L = distance(*a, *b, s);
    SpringDamper spring("k", std::move(a), std::move(b), L - c.extension, c.law, c.damping, false);
    check_force(spring, w, s, s);
    // the energy is the law's and the tension includes the damping, T = T_s + c L'
    EXPECT_NEAR(spring.potential_energy(s), c.law.energy(c.extension),
                1e-9 * std::abs(c.law.energy(c.extension)));
    EXPECT_NEAR(spring.length(s), L, 1e-15 * L);
    const StateFn length = [&](const State& t) -> VecX {
      return VecX::Constant(1, spring.length(t));
    };
    const double Ld = fd_along_v(s, length)[0];
    EXPECT_NEAR(spring.tension(s), c.law.tension(c.extension) + c.damping * Ld,
                kFdTol * (std::abs(spring.tension(s)) + 1.0));
  }
  // a slack sling shorter than its free length: no force, no tangent, no energy
  auto a = w.R1(), b = w.B1e();
  const double L = distance(*a, *b, s);
  SpringDamper sling("sling", std::move(a), std::move(b), 1.2 * L, SpringLaw::linear(1e5), 1e3,
                     true);
  const Probe probe = Probe::of(w.n, sling);
  EXPECT_EQ(probe.forces(s).norm(), 0.0);
  EXPECT_EQ(probe.matrix(s, MatrixScales{0.0, 1.0, 1.0}).norm(), 0.0);
  EXPECT_EQ(sling.potential_energy(s), 0.0);
  EXPECT_EQ(sling.tension(s), 0.0);
}

// a rope through four points on two rigid bodies, a beam and ground, with 1, 4 and 2 parts:
// the force is minus the gradient of 1/2 EA/L0 (L - L0)^2 with L = sum n_i |d_i|, the
// tangents match differences (the damping's q-derivative included), and the tension is
// EA (L - L0)/L0 + c L'; slack, it carries nothing
TEST(Rope, ForceIsMinusEnergyGradientAndTangentsMatchDifferences) {
  World w(22);
  const State& s = w.s;
  auto make = [&](double slack_factor, double damping) {
    std::vector<MarkerPair> segs;
    segs.emplace_back(w.R1(), w.B1e());
    segs.emplace_back(w.B1e(), w.G());
    segs.emplace_back(w.G(), w.R2());
    const std::vector<int> parts{1, 4, 2};
    const double L = distance(*w.R1(), *w.B1e(), s) + 4 * distance(*w.B1e(), *w.G(), s) +
                     2 * distance(*w.G(), *w.R2(), s);
    return std::make_pair(
        std::make_unique<Rope>("wire", std::move(segs), parts, slack_factor * L, 3e7, damping), L);
  };
  for (double damping : {0.0, 2e4}) {
    SCOPED_TRACE("damping " + std::to_string(damping));
    auto [rope, L] = make(0.98, damping);
    check_force(*rope, w, s, s);
    EXPECT_NEAR(rope->length(s), L, 1e-14 * L);
    const StateFn length = [&](const State& t) -> VecX {
      return VecX::Constant(1, rope->length(t));
    };
    const double Ld = fd_along_v(s, length)[0];
    const double T = 3e7 * (L - 0.98 * L) / (0.98 * L) + damping * Ld;
    EXPECT_NEAR(rope->tension(s), std::max(T, 0.0), 1e-9 * std::abs(T));
    EXPECT_NEAR(rope->potential_energy(s), 0.5 * 3e7 / (0.98 * L) * std::pow(0.02 * L, 2),
                1e-9 * rope->potential_energy(s));
  }
  auto [slack, L] = make(1.05, 1e3);
  const Probe probe = Probe::of(w.n, *slack);
  EXPECT_EQ(probe.forces(s).norm(), 0.0);
  EXPECT_EQ(probe.matrix(s, MatrixScales{0.0, 1.0, 1.0}).norm(), 0.0);
  EXPECT_EQ(slack->tension(s), 0.0);
  EXPECT_EQ(slack->potential_energy(s), 0.0);
}

// gas spring (isothermal and adiabatic, compressed and extended) with Stribeck friction,
// rigid-rigid and beam-ground: the force at rest is minus the gradient of the gas energy,
// the tangents match differences (the friction's velocity tangent inside and outside the
// regularization band), and the pressure and friction are eq. (184) and (185) evaluated
// by hand
TEST(PneumaticCylinder, GasLawStribeckFrictionAndTangents) {
  World w(23);
  const State& s = w.s;
  struct Case {
    std::string label;
    MarkerFactory a, b;
    double exponent, compression, regularization;
  };
  const std::vector<Case> cases = {
      {"isothermal, compressed, rigid-rigid", &World::R1, &World::R2, 1.0, 0.4, 1e-3},
      {"adiabatic, extended, rigid-rigid", &World::R1, &World::R2, 1.4, -0.3, 1e-3},
      {"adiabatic, compressed, beam-ground, wide band", &World::B1e, &World::G, 1.4, 0.2, 5.0},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.label);
    GasSpringLaw gas{0.05, 8e6, 0.2, c.exponent};
    StribeckFriction fr;
    fr.coulomb = 2e3;
    fr.static_friction = 5e3;
    fr.stribeck_velocity = 0.05;
    fr.viscous = 1e4;
    fr.pressure_coefficient = 5e-4;
    fr.max_pressure_friction = 4.2e3;
    fr.regularization_velocity = c.regularization;
    auto a = (w.*c.a)(), b = (w.*c.b)();
    const double L = distance(*a, *b, s);
    PneumaticCylinder cyl("cyl", std::move(a), std::move(b), gas, fr);
    cyl.set_reference_length(L + c.compression);
    check_force(cyl, w, s, s);
    // eq. (184): P = P0 (V0 / (V0 - A c))^n
    const double P = 8e6 * std::pow(0.2 / (0.2 - 0.05 * c.compression), c.exponent);
    EXPECT_NEAR(cyl.pressure(s), P, 1e-12 * P);
    // eq. (185), far outside the regularization band tanh = sgn
    const StateFn length = [&](const State& t) -> VecX { return VecX::Constant(1, cyl.length(t)); };
    const double v = fd_along_v(s, length)[0];
    EXPECT_NEAR(cyl.extension_rate(s), v, 1e-7 * (1 + std::abs(v)));
    if (c.regularization < 1e-2 && std::abs(v) > 0.1) {
      const double sgn = v > 0 ? 1.0 : -1.0;
      const double expected = (2e3 + 3e3 * std::exp(-std::abs(v) / 0.05)) * sgn + 1e4 * v +
                              std::min(5e-4 * P, 4.2e3) * sgn;
      EXPECT_NEAR(cyl.friction(s), expected, 1e-9 * std::abs(expected));
    }
    EXPECT_NEAR(cyl.force(s), P * 0.05 - cyl.friction(s), 1e-12 * P * 0.05);
    EXPECT_GE(cyl.dissipation(s), 0.0);
  }
  // the friction law alone: continuous through v = 0, odd, and its derivative matches
  // differences across the kink of |v| at 0
  StribeckFriction fr{1e3, 3e3, 0.02, 500.0, 1e-4, 2e3, 1e-3};
  EXPECT_EQ(fr.force(0.0, 1e7), 0.0);
  EXPECT_NEAR(fr.force(-0.3, 1e7), -fr.force(0.3, 1e7), 1e-12);
  for (double v : {-0.05, -1e-4, 0.0, 2e-4, 0.01, 0.3}) {
    const double h = 1e-8;
    const double fd = (fr.force(v + h, 1e7) - fr.force(v - h, 1e7)) / (2 * h);
    EXPECT_NEAR(fr.dforce_dv(v, 1e7), fd, 1e-5 * std::abs(fd) + 1e-3) << v;
  }
}

// constant-tension tensioner, T = T0 + k s + c L' + the stops: inside the stroke (damped),
// beyond the upper and the lower stop, and a pure constant tension with unlimited stroke;
// rigid-rigid, rigid-beam, beam-ground and beam-beam. The strokes lie 0.1 m or more from
// the kinks at s_min and s_max, where the central differences (h = 1e-6) see one branch
// only. The force at rest is minus the gradient of V(s), the tangents match differences
// (the damping's q-derivative included), and the tension and V are the law by hand (1e-12:
// a few round-offs of the terms).
TEST(ConstantTensioner, ForceIsMinusEnergyGradientAndTangentsMatchDifferences) {
  World w(24);
  const State& s = w.s;
  const double inf = std::numeric_limits<double>::infinity();
  struct Case {
    std::string label;
    MarkerFactory a, b;
    double stroke, k, c, s_min, s_max;
  };
  const std::vector<Case> cases = {
      {"inside the stroke, damped, rigid-rigid", &World::R1, &World::R2, 0.3, 2e5, 3e3, -1.0, 1.0},
      {"beyond s_max, rigid-beam(element)", &World::R1, &World::B1e, 0.7, 1e5, 1e3, -0.4, 0.5},
      {"below s_min, beam(node)-ground", &World::B1n, &World::G, -0.6, 1e5, 2e3, -0.4, 0.5},
      {"constant tension, unlimited, beam-beam", &World::B1e, &World::B2n, 0.2, 0.0, 0.0, -inf,
       inf},
  };
  const double T0 = 4e5, k_stop = 5e7;
  for (const Case& c : cases) {
    SCOPED_TRACE(c.label);
    auto a = (w.*c.a)(), b = (w.*c.b)();
    const double L = distance(*a, *b, s);
    TensionerLaw law{T0, c.k, c.c, c.s_min, c.s_max, std::isfinite(c.s_max) ? k_stop : 0.0};
    ConstantTensioner ten("top", std::move(a), std::move(b), law);
    ten.set_reference_length(L - c.stroke);
    check_force(ten, w, s, s);
    EXPECT_NEAR(ten.stroke(s), c.stroke, 1e-12 * L);
    const double over = std::max(c.stroke - c.s_max, 0.0),
                 under = std::max(c.s_min - c.stroke, 0.0);
    const double restoring = T0 + c.k * c.stroke + k_stop * over - k_stop * under;
    const StateFn length = [&](const State& t) -> VecX { return VecX::Constant(1, ten.length(t)); };
    const double Ld = fd_along_v(s, length)[0];
    EXPECT_NEAR(ten.tension(s), restoring + c.c * Ld, 1e-12 * T0 + 1e-7 * std::abs(c.c * Ld));
    const double V = T0 * c.stroke + 0.5 * c.k * c.stroke * c.stroke +
                     0.5 * k_stop * (over * over + under * under);
    EXPECT_NEAR(ten.potential_energy(s), V, 1e-12 * (std::abs(V) + T0));
  }
  // the law's slope on both sides of each kink, and its energy continuous through them
  TensionerLaw law{T0, 1e5, 0.0, -0.4, 0.5, k_stop};
  EXPECT_EQ(law.slope(0.5), 1e5);
  EXPECT_EQ(law.slope(0.5 + 1e-9), 1e5 + k_stop);
  EXPECT_EQ(law.slope(-0.4), 1e5);
  EXPECT_EQ(law.slope(-0.4 - 1e-9), 1e5 + k_stop);
  EXPECT_NEAR(law.energy(0.5 + 1e-9), law.energy(0.5), 1e-9 * (T0 + 1e5));
  EXPECT_NEAR(law.restoring(0.5 + 1e-9), law.restoring(0.5), 1e-9 * (1e5 + k_stop) + 1e-9);
}

// V = 1/2 k theta^2 between z axes: at exactly aligned axes (theta = 0), in the series
// branch (theta = 3e-5) and on both sides of its end (1e-4), near 1 rad and beyond pi/2;
// rigid-rigid, rigid-beam, beam-beam and beam-ground. q-tangent at zero velocity (the damping's
// q-derivative is left out by design), v-tangent with velocities. For a rigid b, the generalized
// force on b is the moment moment_on_b: Q_b . dq = M . dtheta for dp = 1/2 G^T dtheta (algebraic,
// 1e-11).
TEST(RotationalSpring, ForceIsMinusEnergyGradientAndTangentsMatchDifferences) {
  World w(21);
  const Index o1 = w.rb1.offset(), o2 = w.rb2.offset();
  const Vec4 p1 = w.s.q.segment<4>(o1 + 3);
  const Mat3 A1 = math::rotation_from_euler_parameters(p1);
  for (double theta : {0.0, 3e-5, 0.99e-4, 1.01e-4, 1.0, 2.4}) {
    SCOPED_TRACE("rigid-rigid, theta " + std::to_string(theta));
    State s = w.s;
    // rb2 = rb1 turned by theta about its x axis: the z axes differ by theta
    s.q.segment<4>(o2 + 3) =
        theta == 0.0 ? p1 : math::euler_parameters_from_rotation(A1 * rot_x(theta));
    RotationalSpring spring("flex", std::make_unique<RigidBodyMarker>(w.rb1, Vec3(0.2, 0.1, 0)),
                            std::make_unique<RigidBodyMarker>(w.rb2, Vec3(0, -0.3, 0.5)), 4e6, 2e4);
    State rest = s;
    rest.v.setZero();
    check_force(spring, w, rest, s);
    if (theta == 0.0)
      EXPECT_EQ(spring.angle(s), 0.0);
    else
      EXPECT_NEAR(spring.angle(s), theta, 1e-14 + 1e-12 * theta);
    EXPECT_NEAR(spring.potential_energy(s), 0.5 * 4e6 * theta * theta,
                1e-9 * (1.0 + 4e6 * theta * theta));
    // the generalized force on rb2 is the moment on it, at rest and with damping
    const Probe probe = Probe::of(w.n, spring);
    const Vec4 p2 = s.q.segment<4>(o2 + 3);
    for (const State* st : {&rest, &s}) {
      const VecX Q = probe.forces(*st);
      const Vec3 M = spring.moment_on_b(*st);
      const Vec3 rotation_work = 0.5 * math::euler_g(p2) * Q.segment<4>(o2 + 3);
      EXPECT_TRUE(near(rotation_work, M, 1e-11, Q.norm()));
      EXPECT_EQ(Q.segment<3>(o2).norm(), 0.0);  // no force, a pure moment
    }
    if (theta > 0.0) {  // the spring's moment turns b back towards a
      const Vec3 za = A1.col(2), zb = math::rotation_from_euler_parameters(p2).col(2);
      EXPECT_TRUE(
          near(spring.moment_on_b(rest), -4e6 * theta * za.cross(zb).normalized(), 1e-9, 0.0));
    }
  }
  struct Case {
    std::string label;
    MarkerFactory a, b;
  };
  for (const Case& c : std::vector<Case>{{"rigid-beam(node)", &World::R1, &World::B1n},
                                         {"beam(element)-rigid", &World::B1e, &World::R2},
                                         {"beam-beam", &World::B1n, &World::B2e},
                                         {"beam(element)-ground", &World::B1e, &World::G}}) {
    SCOPED_TRACE(c.label);
    RotationalSpring spring("flex", (w.*c.a)(), (w.*c.b)(), 3e6, 1e4);
    State rest = w.s;
    rest.v.setZero();
    check_force(spring, w, rest, w.s);
  }
}

// Point load with a moment. On a rigid marker the moment's generalized force equals that
// of a couple, F at +r and -F at -r with M = 2 r x F and F, r perpendicular (both vanish
// along p and do the same virtual work), and Q . dq = M . dtheta for a virtual rotation
// dp = 1/2 G^T dtheta (exact: 1e-12). On a beam node the slope turns by dtheta x t,
// which does the work of the moment's part across the slope. Tangent dQ/dq (force and
// moment) on rigid and beam markers by differences.
TEST(PointLoad, MomentIsACoupleAndTangentsMatchDifferences) {
  World w(23);
  const State& s = w.s;
  const Vec3 M(3e3, -2e3, 5e3), F(1e3, 4e2, -7e2);
  const auto constant = [](const Vec3& x) { return VectorSignal(x, TimeSignal::constant(1.0)); };
  const Vec3 u(0.5, -0.3, 1.2);
  PointLoad moment("m", std::make_unique<RigidBodyMarker>(w.rb1, u, frame_1()),
                   constant(Vec3::Zero()), constant(M));
  const Probe pm = Probe::of(w.n, moment);
  const VecX Qm = pm.forces(s);
  const Vec4 p = s.q.segment<4>(3);
  const Mat3 A = math::rotation_from_euler_parameters(p);
  const Vec3 r = 0.8 * M.cross(Vec3(1, 0.3, -0.2)).normalized();  // r perpendicular to M
  const Vec3 Fc = M.cross(r) / (2.0 * r.squaredNorm());           // 2 r x Fc = M
  ASSERT_LT((2.0 * r.cross(Fc) - M).norm(), 1e-12 * M.norm());
  PointLoad plus("plus", std::make_unique<RigidBodyMarker>(w.rb1, u + A.transpose() * r),
                 constant(Fc));
  PointLoad minus("minus", std::make_unique<RigidBodyMarker>(w.rb1, u - A.transpose() * r),
                  constant(-Fc));
  const VecX Qc = Probe::of(w.n, plus).forces(s) + Probe::of(w.n, minus).forces(s);
  EXPECT_TRUE(near(Qm, Qc, 1e-12, 0.0));
  EXPECT_EQ(Qm.head<3>().norm(), 0.0);
  EXPECT_LT(std::abs(Qm.segment<4>(3).dot(p)), 1e-12 * Qm.norm());
  Rng rng(24);
  for (int i = 0; i < 5; ++i) {
    const Vec3 dtheta = rng.vec3();
    EXPECT_NEAR(Qm.segment<4>(3).dot(0.5 * math::euler_g(p).transpose() * dtheta), M.dot(dtheta),
                1e-12 * M.norm());
  }

  // beam node: Q . de = M . dtheta - (M . t^)(t^ . dtheta) for de = dtheta x t on r'
  const int node = 2;
  PointLoad on_node("mn", BeamMarker::at_node(w.beam1, node), constant(Vec3::Zero()), constant(M));
  const VecX Qn = Probe::of(w.n, on_node).forces(s);
  const Index k = w.beam1.node_index(node);
  const Vec3 t = s.q.segment<3>(k + 3), th = t.normalized();
  EXPECT_EQ(Qn.segment<3>(k).norm(), 0.0);
  for (int i = 0; i < 5; ++i) {
    const Vec3 dtheta = rng.vec3();
    EXPECT_NEAR(Qn.segment<3>(k + 3).dot(dtheta.cross(t)),
                M.dot(dtheta) - M.dot(th) * th.dot(dtheta), 1e-12 * M.norm());
  }

  // tangents: force and moment on a rigid marker, a beam node and inside an element
  for (MarkerFactory where : {&World::R1, &World::R2, &World::B1n, &World::B1e, &World::B2e}) {
    PointLoad load("l", (w.*where)(), constant(F), constant(M));
    SCOPED_TRACE((w.*where)()->describe());
    check_force(load, w, s, s, /*conservative=*/false);  // a world-fixed moment has no potential
  }
}

// ---------------------------------------------------------------------------------------
// 7. spring law table

// Linear interpolation between the points, extension beyond the ends with the end
// slopes, and energy = integral of T from 0 (trapezoids on 2e5 steps, exact on linear
// pieces: the error comes from the kinks only, |dk| h^2 / 8 each, below 1e-9 of the
// energy scale 1e5 max(|a|, 1); tolerance 1e-8 of it).
TEST(SpringLaw, TableInterpolatesExtendsAndIntegrates) {
  const std::vector<double> x{-0.5, 0.0, 0.4, 1.0, 2.5};
  const std::vector<double> T{-1e4, 2e3, 5e4, 8e4, 1.1e5};  // pretension 2 kN at zero
  const SpringLaw law = SpringLaw::table(x, T);
  for (std::size_t i = 0; i < x.size(); ++i) EXPECT_NEAR(law.tension(x[i]), T[i], 1e-9);
  EXPECT_NEAR(law.zero_extension_tension(), 2e3, 1e-9);
  for (std::size_t i = 0; i + 1 < x.size(); ++i) {
    const double slope = (T[i + 1] - T[i]) / (x[i + 1] - x[i]);
    const double xm = x[i] + 0.3 * (x[i + 1] - x[i]);
    EXPECT_NEAR(law.tension(xm), T[i] + 0.3 * (T[i + 1] - T[i]), 1e-9);
    EXPECT_NEAR(law.stiffness(xm), slope, 1e-9);
  }
  const double k_lo = (T[1] - T[0]) / (x[1] - x[0]), k_hi = (T[4] - T[3]) / (x[4] - x[3]);
  EXPECT_NEAR(law.tension(-2.0), T[0] + k_lo * (-2.0 - x[0]), 1e-9);
  EXPECT_NEAR(law.stiffness(-2.0), k_lo, 1e-9);
  EXPECT_NEAR(law.tension(4.0), T[4] + k_hi * (4.0 - x[4]), 1e-9);
  EXPECT_NEAR(law.stiffness(4.0), k_hi, 1e-9);
  auto integral = [&](double a) {
    const int steps = 200000;
    const double h = a / steps;
    double sum = 0.5 * (law.tension(0.0) + law.tension(a));
    for (int i = 1; i < steps; ++i) sum += law.tension(i * h);
    return sum * h;
  };
  for (double a : {-2.0, -0.5, -0.3, 0.0, 0.2, 0.4, 0.77, 1.0, 2.5, 4.0}) {
    const double scale = 1e5 * std::max(std::abs(a), 1.0);
    EXPECT_NEAR(law.energy(a), integral(a), 1e-8 * scale) << a;
  }
  // the linear law
  const SpringLaw lin = SpringLaw::linear(3e4);
  EXPECT_DOUBLE_EQ(lin.tension(0.2), 6e3);
  EXPECT_DOUBLE_EQ(lin.energy(0.2), 0.5 * 3e4 * 0.2 * 0.2);
  EXPECT_THROW(SpringLaw::table({0.0}, {1.0}), std::invalid_argument);
  EXPECT_THROW(SpringLaw::table({0.0, 0.0}, {1.0, 2.0}), std::invalid_argument);
  EXPECT_THROW(SpringLaw::table({0.0, 1.0}, {1.0}), std::invalid_argument);
}
