// The force elements written against markers (spring-damper, rope, pneumatic cylinder,
// constant tensioner, rotational spring, point load, spring laws): their forces are minus
// the gradient of their energy and their tangents match central differences, with the
// tolerances of test_markers_joints.cpp's header (marker_test_support.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "marker_test_support.hpp"

using namespace seaflex;
using namespace seaflex::marker_test;

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
    // aligned axes: zero to round-off (the two axes come through different products, which a
    // build with fused multiply-adds rounds differently: 2.9e-17 rad with SEAFLEX_NATIVE)
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
      // aligned axes: both vanish to round-off, within the stiffness times 1e-14 rad
      const double scale = theta == 0.0 ? 4e6 * 1e-14 / 1e-11 : Q.norm();
      EXPECT_TRUE(near(rotation_work, M, 1e-11, scale));
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
