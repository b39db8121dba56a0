// Shared by test_markers_joints.cpp and test_marker_forces.cpp: central differences
// (the tolerances of test_markers_joints.cpp's header), random states, the two rigid
// bodies and two beams the tests are written against (World), and a probe that assembles
// one body or force alone (Probe).
#pragma once

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

namespace seaflex::marker_test {

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

// d f / d x[dofs[j]] by central differences, x the state's positions q or velocities v
inline MatX fd_central(const State& s, const std::vector<Index>& dofs, const StateFn& f,
                       VecX State::*x) {
  const VecX f0 = f(s);
  MatX D(f0.size(), static_cast<Index>(dofs.size()));
  for (std::size_t j = 0; j < dofs.size(); ++j) {
    State sp = s, sm = s;
    (sp.*x)[dofs[j]] += kH;
    (sm.*x)[dofs[j]] -= kH;
    D.col(static_cast<Index>(j)) = (f(sp) - f(sm)) / (2.0 * kH);
  }
  return D;
}

// d f / d q[dofs[j]] by central differences
inline MatX fd_dq(const State& s, const std::vector<Index>& dofs, const StateFn& f) {
  return fd_central(s, dofs, f, &State::q);
}

// d f / d q[dofs[j]] by the fourth-order central difference, for energies: near a
// minimum (a spring at rest) the gradient is zero and the h^2 V''' / 6 truncation of
// the plain difference, about 1e-12 times the stiffness, would be all that is left;
// here it is h^4 V^(5) / 30
inline MatX fd4_dq(const State& s, const std::vector<Index>& dofs, const StateFn& f) {
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
inline MatX fd_dv(const State& s, const std::vector<Index>& dofs, const StateFn& f) {
  return fd_central(s, dofs, f, &State::v);
}

// d/dt f(q + t v, v) at t = 0, v held
inline VecX fd_along_v(const State& s, const StateFn& f) {
  State sp = s, sm = s;
  sp.q += kH * s.v;
  sm.q -= kH * s.v;
  return (f(sp) - f(sm)) / (2.0 * kH);
}

inline std::vector<Index> all_dofs(Index n) {
  std::vector<Index> d(static_cast<std::size_t>(n));
  for (Index i = 0; i < n; ++i) d[static_cast<std::size_t>(i)] = i;
  return d;
}

inline VecX gather(const VecX& x, const std::vector<Index>& dofs) {
  VecX y(static_cast<Index>(dofs.size()));
  for (std::size_t i = 0; i < dofs.size(); ++i) y[static_cast<Index>(i)] = x[dofs[i]];
  return y;
}

// |a - b| <= tol (|b| + scale), scale standing for the size of the differenced function
inline ::testing::AssertionResult near(const MatX& a, const MatX& b, double tol, double scale) {
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

inline Mat3 rot_x(double a) {
  Mat3 R;
  R << 1, 0, 0, 0, std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a);
  return R;
}
inline Mat3 rot_y(double a) {
  Mat3 R;
  R << std::cos(a), 0, std::sin(a), 0, 1, 0, -std::sin(a), 0, std::cos(a);
  return R;
}
inline Mat3 rot_z(double a) {
  Mat3 R;
  R << std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a), 0, 0, 0, 1;
  return R;
}

inline Mat3 inertia_1() {
  Mat3 J;
  J << 2000, 150, -80, 150, 3000, 120, -80, 120, 4000;
  return J;
}
inline Mat3 inertia_2() {
  Mat3 J;
  J << 900, -40, 60, -40, 700, 30, 60, 30, 1100;
  return J;
}

// local frames of the rigid-body markers: rotated, so that no axis is a body axis
inline Mat3 frame_1() {
  return math::rotation_from_roll_pitch_yaw(0.3, -0.5, 1.1);
}
inline Mat3 frame_2() {
  return math::rotation_from_roll_pitch_yaw(-1.2, 0.4, -0.7);
}
inline Mat3 frame_ground() {
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

// a World's marker, chosen by the member function that makes it
using MarkerFactory = std::unique_ptr<Marker> (World::*)() const;

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

}  // namespace seaflex::marker_test
