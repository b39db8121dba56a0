// Seabed contact of rigid-body points (forces/rigid_body_seabed_contact.hpp): the exact
// tangents dQ/dq and dQ/dv of a tilted, turning and sliding box whose corners are partly
// below a flat, a sloped and a grid seabed, against central differences of Q; the force at
// one point against the law written out by hand; the loader of environment.seabed.points.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "seaflex/elements/rigid_body.hpp"
#include "seaflex/forces/rigid_body_seabed_contact.hpp"
#include "seaflex/hydro/seabed.hpp"
#include "seaflex/io/model_loader.hpp"
#include "seaflex/math/rotation.hpp"
#include "seaflex/system/system.hpp"

using namespace seaflex;

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

struct PointCase {
  std::unique_ptr<System> sys;
  std::unique_ptr<RigidBodySeabedContact> contact;
  State s;
};

// a 4 m x 2 m x 1 m box (12 t) tilted by 5 deg roll and -7 deg pitch about a CG 0.45 m
// above a seabed at 100 m (beneath its origin): two or three of its lower corners are below
// the seabed, the others above; it moves at about the slip velocity and turns
PointCase make_case(std::shared_ptr<const hydro::Seabed> seabed, double mu) {
  PointCase c;
  c.sys = std::make_unique<System>();
  RigidBodyInitial init;
  init.position = Vec3(0.3, -0.2, seabed->at(0.3, -0.2).height + 0.45);
  init.orientation = math::rotation_from_roll_pitch_yaw(5 * kDeg, -7 * kDeg, 20 * kDeg);
  auto& body = static_cast<RigidBody&>(c.sys->add_body(
      std::make_unique<RigidBody>("box", 12e3, Mat3(Vec3(5e3, 17e3, 20e3).asDiagonal()), init)));
  c.sys->finalize();
  std::vector<SeabedContactPoint> points;
  for (double x : {-2.0, 2.0})
    for (double y : {-1.0, 1.0}) points.push_back({Vec3(x, y, -0.5), 1e6 * (1.5 + 0.1 * x + y)});
  points.push_back({Vec3(0, 0, 0.5), 2e6});  // an upper point, far above the seabed
  PointContactProperties p;
  p.damping = 0.4;
  p.friction = mu;
  p.slip_velocity = 0.05;
  c.contact = std::make_unique<RigidBodySeabedContact>("box.seabed", body, std::move(seabed),
                                                       std::move(points), p);
  c.s = c.sys->initial_state();
  // moving: translating at about the slip velocity, sinking, turning
  c.s.v.segment<3>(0) = Vec3(0.04, -0.03, -0.02);
  const math::Vec4 pe = c.s.q.segment<4>(3);
  const Vec3 w(0.02, -0.03, 0.05);                                // rad/s, world
  c.s.v.segment<4>(3) = 0.5 * math::euler_g(pe).transpose() * w;  // p' = G^T w / 2
  return c;
}

// the contact's Q (7) and, when matrix, its matrix at the scales
VecX assemble(const PointCase& c, const State& s, MatX* matrix, double kq, double kv) {
  VecX Q = VecX::Zero(c.sys->num_coordinates());
  math::SparseBlockAssembler A(c.sys->num_coordinates(), c.sys->num_coordinates());
  c.contact->declare_blocks(A);
  A.finalize();
  A.set_zero();
  AssemblyTarget t;
  t.forces = &Q;
  if (matrix) {
    t.matrix = &A;
    t.scales.kq = kq;
    t.scales.kv = kv;
  }
  c.contact->assemble(s, 1.0, t);
  if (matrix) *matrix = MatX(A.matrix());
  return Q;
}

// the largest difference between the matrix (kq = -1 or kv = -1: +dQ/dq, +dQ/dv) and the
// central differences of Q, relative to the matrix's norm
double tangent_error(const PointCase& c, bool velocity) {
  MatX A;
  assemble(c, c.s, &A, velocity ? 0.0 : -1.0, velocity ? -1.0 : 0.0);
  const Index n = c.sys->num_coordinates();
  MatX fd(n, n);
  for (Index j = 0; j < n; ++j) {
    const double h = 1e-6;
    State sp = c.s, sm = c.s;
    (velocity ? sp.v : sp.q)[j] += h;
    (velocity ? sm.v : sm.q)[j] -= h;
    fd.col(j) = (assemble(c, sp, nullptr, 0, 0) - assemble(c, sm, nullptr, 0, 0)) / (2 * h);
  }
  EXPECT_GT(A.norm(), 0.0);
  return (A - fd).norm() / A.norm();
}

int points_in_contact(const PointCase& c) {
  int n = 0;
  for (int i = 0; i < c.contact->num_points(); ++i)
    if (c.contact->point_force(c.s, i).normal.norm() > 0.0) ++n;
  return n;
}

}  // namespace

// The matrix equals the central differences of Q to 1e-6 of its norm. h = 1e-6: the
// truncation error, ~h^2 times the third derivative (the friction law curves over the slip
// velocity 0.05 m/s: ~ (h/v_s)^2 = 4e-10 relative), and the round-off, ~1e-16 |x|/h with
// |x| ~ 100 m (1e-8 relative), are both well below 1e-6. No point sits at a kink of the
// law (d = 0 or F = 0): every corner is at least 1 cm from the seabed. The grid is the
// sloped plane's depths on a 3 x 3 grid (bilinear reproduces a plane), so its normal is
// constant and the tangent is exact on it too.
TEST(RigidBodySeabedContactTangent, MatchesFiniteDifferences) {
  const auto flat = std::make_shared<const hydro::Seabed>(hydro::Seabed::flat(100.0));
  const auto sloped =
      std::make_shared<const hydro::Seabed>(hydro::Seabed::plane(100.0, 12 * kDeg, 200 * kDeg));
  std::vector<double> xs{-50, 0, 50}, ys{-50, 0, 50}, depths;
  for (double y : ys)
    for (double x : xs) depths.push_back(-sloped->at(x, y).height);
  const auto grid = std::make_shared<const hydro::Seabed>(hydro::Seabed::grid(xs, ys, depths));
  for (const auto& seabed : {flat, sloped, grid})
    for (double mu : {0.0, 0.7}) {
      const PointCase c = make_case(seabed, mu);
      const int touching = points_in_contact(c);
      EXPECT_GE(touching, 1);
      EXPECT_LE(touching, 3);
      for (int i = 0; i < c.contact->num_points(); ++i)
        EXPECT_GT(std::abs(c.contact->point_force(c.s, i).penetration), 0.01) << i;
      const double eq = tangent_error(c, false), ev = tangent_error(c, true);
      std::printf("%d points in contact, mu %.1f: dQ/dq %.2e, dQ/dv %.2e\n", touching, mu, eq, ev);
      EXPECT_LT(eq, 1e-6) << "dQ/dq, mu " << mu;
      EXPECT_LT(ev, 1e-6) << "dQ/dv, mu " << mu;
    }
}

// One point, written out: on a seabed sloping 10 deg, the normal force k d + c d' along
// the normal and the friction mu F v_t / sqrt(|v_t|^2 + v_s^2) against the velocity along
// the seabed, with c = 2 zeta sqrt(k m) for a single point (to 1e-12 relative: the same
// arithmetic in another order).
TEST(RigidBodySeabedContact, OnePointFollowsTheLaw) {
  const double slope = 10 * kDeg, k = 3e5, zeta = 0.2, m = 5e3, mu = 0.6, vs = 0.02;
  auto seabed = std::make_shared<const hydro::Seabed>(hydro::Seabed::plane(50.0, slope, 0.0));
  System sys;
  RigidBodyInitial init;
  init.position = Vec3(10.0, 3.0, -50.0 - 10.0 * std::tan(slope) + 1.0);  // 1 m above
  init.velocity = Vec3(0.03, 0.01, -0.2);
  auto& body = static_cast<RigidBody&>(
      sys.add_body(std::make_unique<RigidBody>("clump", m, Mat3::Identity() * 1e3, init)));
  sys.finalize();
  PointContactProperties p;
  p.damping = zeta;
  p.friction = mu;
  p.slip_velocity = vs;
  RigidBodySeabedContact contact("clump.seabed", body, seabed, {{Vec3(0, 0, -1.05), k}}, p);
  const State s = sys.initial_state();
  const auto f = contact.point_force(s, 0);
  // the point 1.05 m below the CG is 0.05 m below the seabed vertically: d = 0.05 cos(slope)
  const Vec3 n(std::sin(slope), 0.0, std::cos(slope));
  const double d = 0.05 * std::cos(slope);
  const double c = 2 * zeta * std::sqrt(k * m);
  const double F = k * d - c * n.dot(init.velocity);
  const Vec3 vt = init.velocity - n * n.dot(init.velocity);
  EXPECT_NEAR(f.penetration, d, 1e-12 * d);
  EXPECT_NEAR(contact.damping_coefficient(0), c, 1e-12 * c);
  EXPECT_LT((f.normal - F * n).norm(), 1e-12 * F);
  EXPECT_LT((f.friction + mu * F * vt / std::sqrt(vt.squaredNorm() + vs * vs)).norm(), 1e-12 * F);
  // its Q: the force on r, and on p 2 G^T (u x f) (Nikravesh eq. 6.98) plus 2 p (A u . f),
  // the radial part of x = r + p^T S p (A u) off |p| = 1, along the normalization's
  // gradient (its multiplier takes it)
  VecX Q = VecX::Zero(7);
  math::SparseBlockAssembler A(7, 7);
  contact.declare_blocks(A);
  A.finalize();
  AssemblyTarget t;
  t.forces = &Q;
  contact.assemble(s, 1.0, t);
  const Vec3 ft = f.normal + f.friction;
  EXPECT_LT((Q.head<3>() - ft).norm(), 1e-12 * F);
  const Vec3 moment = Vec3(0, 0, -1.05).cross(ft);
  const math::Vec4 pe = s.q.segment<4>(3);
  const math::Vec4 Qp =
      2.0 * math::euler_g(pe).transpose() * moment + 2.0 * pe * (Vec3(0, 0, -1.05).dot(ft));
  EXPECT_LT((Q.tail<4>() - Qp).norm(), 1e-12 * F);
  // lifted 0.1 m the point leaves the seabed: no force
  State up = s;
  up.q[2] += 0.1;
  EXPECT_EQ(contact.point_force(up, 0).normal, Vec3::Zero());
  EXPECT_EQ(contact.potential_energy(up), 0.0);
  EXPECT_NEAR(contact.potential_energy(s), 0.5 * k * d * d, 1e-12 * k * d * d);
}

namespace {

const RigidBodySeabedContact* contact_of(const io::Model& m, const std::string& name) {
  for (const auto& f : m.system->forces())
    if (const auto* c = dynamic_cast<const RigidBodySeabedContact*>(f.get());
        c && c->name() == name)
      return c;
  ADD_FAILURE() << "no force " << name;
  return nullptr;
}

}  // namespace

// environment.seabed.points as documented (docs/model-format.md 4.5): k = normal_stiffness x
// area or the stiffness given, the points in the order given, the entry's friction or else
// the seabed's, the seabed's damping and slip velocity, c_i = 2 zeta k_i sqrt(m/K) (exact
// arithmetic: 1e-12 relative); the channels' names.
TEST(RigidBodySeabedContact, LoaderReadsThePoints) {
  const io::Model m = io::load_model_text(R"(
environment:
  water: {density: 1025, depth: 100}
  seabed:
    normal_stiffness: 2.0e5
    damping: 0.25
    friction: 0.4
    slip_velocity: 0.02
    points:
      - {body: clump, points: [[1, 0, -0.5], [-1, 0, -0.5], [0, 1, -0.5]], area: 1.5}
      - {body: anchor, points: [[0, 0, -1]], stiffness: 7.0e6, friction: 1.2}
bodies:
  clump: {type: rigid_body, mass: 8000, inertia: [1000, 1000, 1500], position: [0, 0, -99]}
  anchor: {type: rigid_body, mass: 3000, inertia: [500, 500, 500], position: [20, 0, -98]}
)",
                                          "points.yaml");
  const auto* clump = contact_of(m, "clump.seabed");
  const auto* anchor = contact_of(m, "anchor.seabed");
  ASSERT_TRUE(clump && anchor);
  ASSERT_EQ(clump->num_points(), 3);
  EXPECT_EQ(clump->points()[1].position, Vec3(-1, 0, -0.5));
  for (const auto& p : clump->points()) EXPECT_NEAR(p.stiffness, 3e5, 1e-12 * 3e5);
  EXPECT_EQ(clump->properties().friction, 0.4);
  EXPECT_EQ(clump->properties().damping, 0.25);
  EXPECT_EQ(clump->properties().slip_velocity, 0.02);
  const double c = 2 * 0.25 * 3e5 * std::sqrt(8000 / 9e5);
  EXPECT_NEAR(clump->damping_coefficient(2), c, 1e-12 * c);
  ASSERT_EQ(anchor->num_points(), 1);
  EXPECT_EQ(anchor->points()[0].stiffness, 7e6);
  EXPECT_EQ(anchor->properties().friction, 1.2);
  const double ca = 2 * 0.25 * std::sqrt(7e6 * 3000);
  EXPECT_NEAR(anchor->damping_coefficient(0), ca, 1e-12 * ca);
  std::vector<std::string> names;
  for (const auto& ch : io::model_channels(m)) names.push_back(ch.name);
  for (const char* n : {"clump.seabed.force", "clump.seabed.friction", "clump.seabed.p0.force",
                        "clump.seabed.p2.force", "anchor.seabed.p0.force"})
    EXPECT_NE(std::find(names.begin(), names.end(), n), names.end()) << n;
  EXPECT_EQ(std::find(names.begin(), names.end(), "clump.seabed.p3.force"), names.end());
}

// environment.seabed.lines: absent, every beam touches the seabed; a list, only those listed;
// an empty list, none (a seabed for rigid-body points alone)
TEST(RigidBodySeabedContact, LinesListSelectsTheBeams) {
  const auto model = [](const std::string& lines) {
    return io::load_model_text(R"(
environment:
  water: {density: 1025, depth: 100}
  seabed:
    normal_stiffness: 2.0e5
)" + lines + R"(
    points:
      - {body: clump, points: [[0, 0, -0.5]], area: 1.5}
bodies:
  clump: {type: rigid_body, mass: 8000, inertia: [1000, 1000, 1500], position: [0, 0, -99]}
  a: {type: ancf_beam, start: [0, 0, -99], end: [50, 0, -99], elements: 4,
      outer_diameter: 0.1, youngs_modulus: 2e11, density: 7850}
  b: {type: ancf_beam, start: [0, 5, -99], end: [50, 5, -99], elements: 4,
      outer_diameter: 0.1, youngs_modulus: 2e11, density: 7850}
)",
                               "lines.yaml");
  };
  const auto touching = [](const io::Model& m) {
    std::vector<std::string> names;
    for (const auto& f : m.system->forces())
      if (f->name() == "a.seabed" || f->name() == "b.seabed") names.push_back(f->name());
    return names;
  };
  EXPECT_EQ(touching(model("")), (std::vector<std::string>{"a.seabed", "b.seabed"}));
  EXPECT_EQ(touching(model("    lines: [b]")), (std::vector<std::string>{"b.seabed"}));
  const io::Model none = model("    lines: []");
  EXPECT_TRUE(touching(none).empty());
  EXPECT_NE(contact_of(none, "clump.seabed"), nullptr);  // the points still touch it
}
