// Constrained rigid-body benchmarks with known solutions, built through the C++ API, for the
// convergence tests of the time integrators (Drake's multibody/benchmarks in spirit):
// - a point-like pendulum on a revolute joint, released with the rod horizontal; its angle
//   obeys (m L^2 + I) phi'' = m g L cos(phi), integrated independently by a scalar RK4;
// - a fast symmetric heavy top on a ball joint in steady precession: the precession rate
//   Omega solves m g l = Omega (I3 w3 - I1' Omega cos(theta)) (I1' about the pivot;
//   Goldstein, Classical Mechanics, sec. 5.7), so the centre of gravity circles the vertical
//   at Omega exactly and the spin w3 stays constant;
// - the spatial double pendulum and the slider-crank of test_rigid_bodies.cpp (the slider-
//   crank here driven by a constant torque on the crank).
#pragma once

#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

#include "seaflex/constraints/joint.hpp"
#include "seaflex/elements/rigid_body.hpp"
#include "seaflex/forces/gravity.hpp"
#include "seaflex/forces/point_load.hpp"
#include "seaflex/math/rotation.hpp"
#include "seaflex/system/system.hpp"

namespace seaflex::benchmarks {

constexpr double kG = 9.81;

inline RigidBody& add_rigid(System& sys, const std::string& name, double mass, const Mat3& inertia,
                            const RigidBodyInitial& init) {
  return static_cast<RigidBody&>(
      sys.add_body(std::make_unique<RigidBody>(name, mass, inertia, init)));
}

inline void add_joint(System& sys, const std::string& name, JointType type,
                      std::unique_ptr<Marker> from, std::unique_ptr<Marker> to) {
  sys.add_constraint(std::make_unique<Joint>(name, type, std::move(from), std::move(to)));
}

inline std::unique_ptr<Marker> ground(const Vec3& p, const Mat3& frame = Mat3::Identity()) {
  return std::make_unique<GroundMarker>(p, frame);
}

inline std::unique_ptr<Marker> on(const RigidBody& b, const Vec3& u,
                                  const Mat3& frame = Mat3::Identity()) {
  return std::make_unique<RigidBodyMarker>(b, u, frame);
}

// slender rod of mass m and length l along body axis `axis`, radius rad
inline Mat3 rod_inertia(double m, double l, double rad, int axis) {
  const double t = m * (3 * rad * rad + l * l) / 12.0;
  Mat3 J = Vec3::Constant(t).asDiagonal();
  J(axis, axis) = 0.5 * m * rad * rad;
  return J;
}

struct Benchmark {
  std::unique_ptr<System> system;
  const RigidBody* body = nullptr;  // the body whose centre of gravity is compared
};

// --- point-like pendulum: L = 1 m, m = 1 kg, I = 1e-6 kg m^2, revolute joint about world y
// at the origin, released from rest at (L, 0, 0)
struct PointPendulum {
  static constexpr double L = 1.0, m = 1.0, I = 1e-6;
  static Benchmark build() {
    Benchmark b;
    b.system = std::make_unique<System>();
    RigidBodyInitial init;
    init.position = Vec3(L, 0, 0);
    const RigidBody& body =
        add_rigid(*b.system, "bob", m, Vec3::Constant(I).asDiagonal().toDenseMatrix(), init);
    Mat3 frame;  // columns x = world x, y = -world z, z = world y (the hinge axis)
    frame << 1, 0, 0, 0, 0, 1, 0, -1, 0;
    add_joint(*b.system, "hinge", JointType::kRevolute, ground(Vec3::Zero(), frame),
              on(body, Vec3(-L, 0, 0), frame));
    b.system->add_force(
        std::make_unique<Gravity>(Vec3(0, 0, -kG), std::vector<const Body*>{&body}));
    b.system->finalize();
    b.body = &body;
    return b;
  }
  /// the exact centre of gravity at t: phi below the horizontal, (m L^2 + I) phi'' =
  /// m g L cos(phi), by a scalar classical RK4 at dt = 1e-5 s (error ~ 1e-14 m over 10 s)
  static Vec3 exact(double t) {
    const double k = m * kG * L / (m * L * L + I);
    double phi = 0.0, om = 0.0;
    const long n = std::lround(t / 1e-5);
    const double dt = t / static_cast<double>(n);
    auto f = [k](double p) { return k * std::cos(p); };
    for (long i = 0; i < n; ++i) {
      const double k1p = om, k1o = f(phi);
      const double k2p = om + 0.5 * dt * k1o, k2o = f(phi + 0.5 * dt * k1p);
      const double k3p = om + 0.5 * dt * k2o, k3o = f(phi + 0.5 * dt * k2p);
      const double k4p = om + dt * k3o, k4o = f(phi + dt * k3p);
      phi += dt / 6.0 * (k1p + 2 * k2p + 2 * k3p + k4p);
      om += dt / 6.0 * (k1o + 2 * k2o + 2 * k3o + k4o);
    }
    return Vec3(L * std::cos(phi), 0.0, -L * std::sin(phi));
  }
};

// --- heavy symmetric top: m = 1 kg, centre of gravity l = 1 m from the ball joint along the
// symmetry axis (body z), inertias about the centre of gravity I1 = I2 = 0.05, I3 = 0.1
// kg m^2, axis 30 deg from the vertical, spin w3 = 150 rad/s, in steady precession
struct HeavyTop {
  static constexpr double m = 1.0, l = 1.0, I1 = 0.05, I3 = 0.1, w3 = 150.0;
  static constexpr double theta = std::numbers::pi / 6.0;
  /// the slow precession rate: I1' cos(theta) Omega^2 - I3 w3 Omega + m g l = 0
  static double precession() {
    const double a = (I1 + m * l * l) * std::cos(theta), b = I3 * w3, c = m * kG * l;
    return (b - std::sqrt(b * b - 4 * a * c)) / (2 * a);
  }
  static Benchmark build() {
    Benchmark b;
    b.system = std::make_unique<System>();
    const double Om = precession();
    const Vec3 e3(std::sin(theta), 0.0, std::cos(theta));
    RigidBodyInitial init;
    init.orientation = math::rotation_from_roll_pitch_yaw(0.0, theta, 0.0);  // z -> e3
    init.position = l * e3;
    init.angular_velocity = Om * Vec3::UnitZ() + (w3 - Om * std::cos(theta)) * e3;
    init.velocity = init.angular_velocity.cross(init.position);
    const RigidBody& body =
        add_rigid(*b.system, "top", m, Vec3(I1, I1, I3).asDiagonal().toDenseMatrix(), init);
    add_joint(*b.system, "pivot", JointType::kBall, ground(Vec3::Zero()), on(body, Vec3(0, 0, -l)));
    b.system->add_force(
        std::make_unique<Gravity>(Vec3(0, 0, -kG), std::vector<const Body*>{&body}));
    b.system->finalize();
    b.body = &body;
    return b;
  }
  static Vec3 exact(double t) {
    const double Om = precession();
    return l * Vec3(std::sin(theta) * std::cos(Om * t), std::sin(theta) * std::sin(Om * t),
                    std::cos(theta));
  }
};

// --- spatial double pendulum of test_rigid_bodies.cpp (rods 1 m, 2 kg and 0.8 m, 1.5 kg)
inline Benchmark double_pendulum() {
  const double L1 = 1.0, m1 = 2.0, L2 = 0.8, m2 = 1.5, rad = 0.02;
  const Mat3 A1 = math::rotation_from_roll_pitch_yaw(0.9, 0.4, 0.0);
  const Mat3 A2 = math::rotation_from_roll_pitch_yaw(-1.2, 0.7, 0.5);
  const Vec3 w1(0.5, -1.0, 2.0), w2(-1.5, 2.0, 0.7);
  RigidBodyInitial i1, i2;
  i1.orientation = A1;
  i1.position = -A1 * Vec3(0, 0, 0.5 * L1);
  const Vec3 P1 = i1.position + A1 * Vec3(0, 0, -0.5 * L1);
  i1.angular_velocity = w1;
  i1.velocity = w1.cross(i1.position);
  i2.orientation = A2;
  i2.position = P1 - A2 * Vec3(0, 0, 0.5 * L2);
  i2.angular_velocity = w2;
  i2.velocity = w1.cross(P1) + w2.cross(i2.position - P1);
  Benchmark b;
  b.system = std::make_unique<System>();
  System& sys = *b.system;
  const RigidBody& b1 = add_rigid(sys, "upper", m1, rod_inertia(m1, L1, rad, 2), i1);
  const RigidBody& b2 = add_rigid(sys, "lower", m2, rod_inertia(m2, L2, rad, 2), i2);
  add_joint(sys, "shoulder", JointType::kBall, ground(Vec3::Zero()), on(b1, {0, 0, 0.5 * L1}));
  add_joint(sys, "elbow", JointType::kBall, on(b1, {0, 0, -0.5 * L1}), on(b2, {0, 0, 0.5 * L2}));
  sys.add_force(std::make_unique<Gravity>(Vec3(0, 0, -kG), std::vector<const Body*>{&b1, &b2}));
  sys.finalize();
  b.body = &b2;
  return b;
}

// --- slider-crank of test_rigid_bodies.cpp (crank 0.1 m, rod 0.4 m, offset 0.03 m, gravity
// -y), from a crank rate om0, driven by a constant torque (N m) about z on the crank
inline Benchmark slider_crank(double om0, double torque) {
  const double r = 0.1, l = 0.4, e = 0.03, th0 = 0.3;
  const double mc = 1.0, mr = 2.0, ms = 3.0;
  auto slider_x = [&](double th) {
    return r * std::cos(th) + std::sqrt(l * l - std::pow(r * std::sin(th) - e, 2));
  };
  auto slider_v = [&](double th, double om) {
    const double a = r * std::sin(th) - e;
    return -r * std::sin(th) * om - a * r * std::cos(th) * om / std::sqrt(l * l - a * a);
  };
  const Vec3 z = Vec3::UnitZ();
  RigidBodyInitial ic, ir, is;
  const Vec3 dc(std::cos(th0), std::sin(th0), 0);
  ic.orientation = math::rotation_from_roll_pitch_yaw(0, 0, th0);
  ic.position = 0.5 * r * dc;
  ic.angular_velocity = om0 * z;
  ic.velocity = ic.angular_velocity.cross(ic.position);
  const Vec3 pin = r * dc, xs(slider_x(th0), e, 0);
  const Vec3 dr = (xs - pin) / l;
  const double phi = std::atan2(dr.y(), dr.x());
  const double phid = -r * std::cos(th0) * om0 / (l * std::cos(phi));
  ir.orientation = math::rotation_from_roll_pitch_yaw(0, 0, phi);
  ir.position = pin + 0.5 * l * dr;
  ir.angular_velocity = phid * z;
  ir.velocity = (om0 * z).cross(pin) + ir.angular_velocity.cross(0.5 * l * dr);
  is.position = xs;
  is.velocity = Vec3(slider_v(th0, om0), 0, 0);
  Benchmark b;
  b.system = std::make_unique<System>();
  System& sys = *b.system;
  const RigidBody& crank = add_rigid(sys, "crank", mc, rod_inertia(mc, r, 0.01, 0), ic);
  const RigidBody& rod = add_rigid(sys, "rod", mr, rod_inertia(mr, l, 0.01, 0), ir);
  const RigidBody& slider =
      add_rigid(sys, "slider", ms, Vec3(0.01, 0.012, 0.014).asDiagonal().toDenseMatrix(), is);
  Mat3 zxy;  // columns world z, x, y
  zxy << 0, 1, 0, 0, 0, 1, 1, 0, 0;
  Mat3 yzx;  // columns world y, z, x
  yzx << 0, 0, 1, 1, 0, 0, 0, 1, 0;
  add_joint(sys, "main bearing", JointType::kRevolute, ground(Vec3::Zero()),
            on(crank, {-0.5 * r, 0, 0}));
  add_joint(sys, "crank pin", JointType::kBall, on(crank, {0.5 * r, 0, 0}),
            on(rod, {-0.5 * l, 0, 0}));
  add_joint(sys, "wrist pin", JointType::kUniversal, on(slider, Vec3::Zero(), zxy),
            on(rod, {0.5 * l, 0, 0}));
  add_joint(sys, "guide", JointType::kPrismatic, ground(Vec3(0, e, 0), yzx),
            on(slider, Vec3::Zero(), yzx));
  sys.add_force(
      std::make_unique<Gravity>(Vec3(0, -kG, 0), std::vector<const Body*>{&crank, &rod, &slider}));
  if (torque != 0.0)
    sys.add_force(std::make_unique<PointLoad>(
        "drive", on(crank, Vec3::Zero()), VectorSignal(Vec3::Zero(), TimeSignal::constant(1.0)),
        VectorSignal(Vec3(0, 0, torque), TimeSignal::constant(1.0))));
  sys.finalize();
  b.body = &slider;
  return b;
}

}  // namespace seaflex::benchmarks
