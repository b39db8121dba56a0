// Morison loads (thesis eq. 176-177) on ANCF beams and on rigid-body members, models built
// from model files, against closed forms:
//  - steady drag on a fixed horizontal pipe in a uniform current: 1/2 rho Cd D U^2 L;
//  - the inline force history on a fixed vertical cylinder from the seabed through the
//    surface in an Airy wave (drag + inertia integrated over depth; with Wheeler
//    stretching the integral over [-d, eta] is (1 + eta/d) times the integral of the
//    linear profile over [-d, 0]);
//  - buoyancy of a partially submerged element;
//  - dQ/dv and dQ/dq against central differences.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "seaflex/forces/morison_beam.hpp"
#include "seaflex/forces/rigid_morison.hpp"
#include "seaflex/hydro/dispersion.hpp"
#include "seaflex/io/model_loader.hpp"

using namespace seaflex;

namespace {

constexpr double kPi = std::numbers::pi;

Force& force_named(const io::Model& m, const std::string& name) {
  for (const auto& f : m.system->forces())
    if (f->name() == name) return *f;
  throw std::runtime_error("no force " + name);
}

// Q of one force in a state
VecX force_vector(const io::Model& m, const Force& f, const State& s) {
  VecX Q = VecX::Zero(m.system->num_coordinates());
  AssemblyTarget t;
  t.forces = &Q;
  f.assemble(s, 1.0, t);
  return Q;
}

// resultant of a beam's generalized force: the position entries of every node (the
// Hermite position functions s1 + s3 sum to one, so these add up to int f dx)
Vec3 beam_resultant(const VecX& Q, Index offset, int nodes) {
  Vec3 F = Vec3::Zero();
  for (int k = 0; k < nodes; ++k) F += Q.segment<3>(offset + 6 * k);
  return F;
}

TEST(Morison, SteadyDragOnHorizontalPipeInUniformCurrent) {
  const std::string yaml = R"(
environment:
  gravity: 9.81
  water: {density: 1025, depth: 200}
  current: {speed: 1.7, direction: 90}
bodies:
  pipe:
    type: ancf_beam
    start: [0, 0, -20]
    end: [30, 0, -20]
    elements: 6
    outer_diameter: 0.7
    inner_diameter: 0.4
    youngs_modulus: 210e9
    density: 7850
hydrodynamics:
  pipe: {cd: 0.65, cm: 1.6, buoyancy: false}
)";
  const io::Model m = io::load_model_text(yaml, "pipe.yaml");
  const State s = m.system->initial_state();
  const Vec3 F = beam_resultant(force_vector(m, force_named(m, "pipe.morison"), s), 0, 7);
  // the current flows towards +y, normal to the pipe; no acceleration, no motion:
  // drag only, exactly 1/2 rho Cd D U^2 L (quadrature of a constant: round-off; 0.1 % asked)
  const double expected = 0.5 * 1025 * 0.65 * 0.7 * 1.7 * 1.7 * 30;
  EXPECT_NEAR(F.y(), expected, 1e-10 * expected);
  EXPECT_NEAR(F.x(), 0.0, 1e-9 * expected);
  EXPECT_NEAR(F.z(), 0.0, 1e-9 * expected);
}

TEST(Morison, BuoyancyOfAPartlySubmergedPipe) {
  // a pipe from z = -12 to z = +3 in still water: buoyancy rho g A over the 12 wet metres
  // only (the crossing found inside the element); exact to the root finder's 1e-12.
  const std::string yaml = R"(
environment:
  gravity: 9.81
  water: {density: 1025, depth: 50}
bodies:
  pipe:
    type: ancf_beam
    start: [0, 0, -12]
    end: [0, 0, 3]
    elements: 2
    outer_diameter: 0.5
    inner_diameter: 0.3
    youngs_modulus: 210e9
    density: 7850
hydrodynamics:
  pipe: {cd: 1.0, cm: 2.0}
)";
  const io::Model m = io::load_model_text(yaml, "buoy.yaml");
  const State s = m.system->initial_state();
  const Vec3 F = beam_resultant(force_vector(m, force_named(m, "pipe.morison"), s), 0, 3);
  const double expected = 1025 * 9.81 * 0.25 * kPi * 0.25 * 12.0;
  EXPECT_NEAR(F.z(), expected, 1e-9 * expected);
}

// closed form of the inline force on a vertical cylinder, seabed to surface, in an Airy
// wave (amplitude a, deep enough profile given by k, d), Wheeler-stretched
double cylinder_inline_force(double t, double a, double w, double k, double d, double D, double Cd,
                             double Cm, double rho) {
  const double th = w * t;  // at x = 0
  const double eta = a * std::cos(th);
  const double A = 0.25 * kPi * D * D;
  const double sh = std::sinh(k * d);
  // int_{-d}^0 cosh(k(z+d)) dz = sinh(kd)/k ; int cosh^2 = sinh(2kd)/(4k) + d/2
  const double u0 = a * w / sh, a0 = a * w * w / sh;
  const double inertia = -rho * Cm * A * a0 * std::sin(th) * sh / k;  // du/dt ~ -sin
  const double c = std::cos(th);
  const double drag =
      0.5 * rho * Cd * D * u0 * u0 * std::abs(c) * c * (std::sinh(2 * k * d) / (4 * k) + d / 2);
  return (1.0 + eta / d) * (inertia + drag);
}

TEST(Morison, InlineForceOnVerticalCylinderInAiryWave) {
  const double d = 40, H = 4, T = 8, D = 2.0, Cd = 1.0, Cm = 2.0, rho = 1025, g = 9.81;
  const std::string yaml = R"(
environment:
  gravity: 9.81
  water: {density: 1025, depth: 40}
  waves: {type: airy, height: 4, period: 8, direction: 0}
bodies:
  pile:
    type: ancf_beam
    start: [0, 0, -40]
    end: [0, 0, 6]
    elements: 23
    outer_diameter: 2.0
    inner_diameter: 1.8
    youngs_modulus: 210e9
    density: 7850
hydrodynamics:
  pile: {cd: 1.0, cm: 2.0, buoyancy: false, gauss_points: 8}
)";
  const io::Model m = io::load_model_text(yaml, "pile.yaml");
  State s = m.system->initial_state();
  const double w = 2 * kPi / T, k = hydro::wave_number(w, d, g), a = H / 2;
  const Force& f = force_named(m, "pile.morison");
  double fmax = 0.0, err = 0.0;
  for (int i = 0; i < 32; ++i) {
    s.t = i * T / 32;
    const double F = beam_resultant(force_vector(m, f, s), 0, 24).x();
    const double ref = cylinder_inline_force(s.t, a, w, k, d, D, Cd, Cm, rho);
    fmax = std::max(fmax, std::abs(ref));
    err = std::max(err, std::abs(F - ref));
  }
  // Gauss quadrature of cosh over 2 m elements is exact to ~1e-12; the element cut at the
  // surface is found to 1e-12. The issue asks 0.5 %; 1e-6 of the peak is asserted.
  EXPECT_LT(err, 1e-6 * fmax);
  std::printf("pile inline force: peak %.6g N, max error %.3g N\n", fmax, err);
}

TEST(Morison, InlineForceOnRigidMemberInAiryWave) {
  // the same pile as a Morison member of a rigid body held by a fixed joint to ground
  const double d = 40, T = 8, D = 2.0, rho = 1025, g = 9.81;
  const std::string yaml = R"(
environment:
  gravity: 9.81
  water: {density: 1025, depth: 40}
  waves: {type: airy, height: 4, period: 8, direction: 0}
bodies:
  jacket:
    type: rigid_body
    mass: 1.0e5
    inertia: [1e7, 1e7, 1e6]
    position: [0, 0, -17]
joints:
  - name: hold
    type: fixed
    from: {body: ground, position: [0, 0, -17]}
    to: {body: jacket}
hydrodynamics:
  jacket:
    morison:
      - {end_a: [0, 0, -23], end_b: [0, 0, 23], diameter: 2.0, cd: 1.0, cm: 2.0, ca: 1.0, strips: 40}
)";
  const io::Model m = io::load_model_text(yaml, "jacket.yaml");
  State s = m.system->initial_state();
  const double w = 2 * kPi / T, k = hydro::wave_number(w, d, g), a = 2.0;
  const auto& f = static_cast<const RigidMorison&>(force_named(m, "jacket.morison"));
  double fmax = 0.0, err = 0.0;
  for (int i = 0; i < 32; ++i) {
    s.t = i * T / 32;
    const double F = f.wrench_at(s).force.x();
    const double ref = cylinder_inline_force(s.t, a, w, k, d, D, 1.0, 2.0, rho);
    fmax = std::max(fmax, std::abs(ref));
    err = std::max(err, std::abs(F - ref));
  }
  // 40 Gauss points over the 40 m wet length integrate cosh(k z) (k d = 2.6) to ~1e-12;
  // the |cos| cos drag is smooth in z. 0.5 % asked; 1e-6 asserted.
  EXPECT_LT(err, 1e-6 * fmax);
}

TEST(Morison, BeamTangentsMatchFiniteDifferences) {
  const std::string yaml = R"(
environment:
  gravity: 9.81
  water: {density: 1025, depth: 60}
  waves: {type: airy, height: 3, period: 9, direction: 30}
  current: {profile: [[-60, 0.1, 40], [-30, 0.6, 40], [0, 1.2, 10]]}
bodies:
  riser:
    type: ancf_beam
    polyline: [[0, 0, -50], [6, 3, -20], [8, 5, -2]]
    elements: [3, 2]
    outer_diameter: 0.6
    inner_diameter: 0.4
    youngs_modulus: 210e9
    density: 7850
hydrodynamics:
  riser: {cd: 1.1, cd_axial: 0.02, cm: 1.9, ca: 0.9}
)";
  const io::Model m = io::load_model_text(yaml, "riser.yaml");
  State s = m.system->initial_state();
  s.t = 2.3;
  for (Index i = 0; i < s.v.size(); ++i) s.v[i] = 0.3 * std::sin(1.7 * i);
  Force& f = force_named(m, "riser.morison");
  const Index n = s.q.size();
  // the tangent blocks: -dQ/dq (kq = 1) and -dQ/dv (kv = 1)
  auto tangent = [&](double kq, double kv) {
    math::SparseBlockAssembler A(n, n);
    f.declare_blocks(A);
    A.finalize();
    A.set_zero();
    AssemblyTarget t;
    t.matrix = &A;
    t.scales = MatrixScales{0.0, kq, kv};
    f.assemble(s, 1.0, t);
    return MatX(A.matrix());
  };
  // central differences of Q in v and q
  MatX dQdv(n, n), dQdq(n, n);
  for (Index j = 0; j < n; ++j) {
    State sp = s, sm = s;
    sp.v[j] += 1e-6;
    sm.v[j] -= 1e-6;
    dQdv.col(j) = (force_vector(m, f, sp) - force_vector(m, f, sm)) / 2e-6;
    sp = s;
    sm = s;
    sp.q[j] += 1e-6;
    sm.q[j] -= 1e-6;
    dQdq.col(j) = (force_vector(m, f, sp) - force_vector(m, f, sm)) / 2e-6;
  }
  const MatX Kv = -tangent(0.0, 1.0), Kq = -tangent(1.0, 0.0);
  // dQ/dv is exact: differences agree to the FD truncation, 1e-6 of the largest entry.
  EXPECT_LT((Kv - dQdv).lpNorm<Eigen::Infinity>(), 1e-6 * dQdv.lpNorm<Eigen::Infinity>());
  // dQ/dq leaves out the motion of the wet end (the top element crosses the surface),
  // whose entries are small: 1 % of the largest entry is asserted, and below the surface
  // element (the first four elements, coordinates 0..29) 1e-5.
  EXPECT_LT((Kq - dQdq).lpNorm<Eigen::Infinity>(), 1e-2 * dQdq.lpNorm<Eigen::Infinity>());
  EXPECT_LT((Kq - dQdq).topLeftCorner(24, 24).lpNorm<Eigen::Infinity>(),
            1e-5 * dQdq.lpNorm<Eigen::Infinity>());
}

}  // namespace

namespace {

// the rigid-translation added masses u^T M u (u = 1 on every node's x, y or z) of the
// Morison force on a horizontal pipe along x, 24 m, D = 0.7 m, with these coefficients
Vec3 pipe_added_masses(const std::string& coefficients, bool* constant_mass = nullptr) {
  const std::string yaml = R"(
environment:
  gravity: 9.81
  water: {density: 1025, depth: 200}
bodies:
  pipe:
    type: ancf_beam
    start: [0, 0, -20]
    end: [24, 0, -20]
    elements: 4
    outer_diameter: 0.7
    inner_diameter: 0.4
    youngs_modulus: 210e9
    density: 7850
hydrodynamics:
  pipe: )" + coefficients + "\n";
  const io::Model m = io::load_model_text(yaml, "pipe.yaml");
  Force& f = force_named(m, "pipe.morison");
  if (constant_mass) *constant_mass = f.constant_mass();
  const State s = m.system->initial_state();
  const Index n = s.q.size();
  math::SparseBlockAssembler A(n, n);
  f.declare_blocks(A);
  A.finalize();
  A.set_zero();
  AssemblyTarget t;
  t.matrix = &A;
  t.scales = MatrixScales{1.0, 0.0, 0.0};
  f.assemble(s, 1.0, t);
  const MatX M = A.matrix();
  Vec3 masses;
  for (int dir = 0; dir < 3; ++dir) {
    VecX u = VecX::Zero(n);
    for (int k = 0; k < 5; ++k) u[6 * k + dir] = 1.0;  // unit translation: r = 1, r' = 0
    masses[dir] = u.dot(M * u);
  }
  return masses;
}

TEST(Morison, AddedMassActsNormalToTheBeamOnly) {
  // a horizontal pipe along x: the added mass matrix int S^T rho Ca A (I - t t^T) S dx
  // gives a rigid translation along y or z the mass rho Ca A L, along x none.
  // Exact (Gauss quadrature of the Hermite products): 1e-12 relative.
  bool constant_mass = true;
  const Vec3 mass = pipe_added_masses("{cd: 0.65, cm: 1.6}", &constant_mass);
  EXPECT_FALSE(constant_mass);
  const double expected = 1025 * 0.6 * 0.25 * kPi * 0.49 * 24;  // Ca = Cm - 1 = 0.6
  for (int dir = 0; dir < 3; ++dir)
    EXPECT_NEAR(mass[dir], dir == 0 ? 0.0 : expected, 1e-12 * expected) << dir;
}

}  // namespace

namespace {

TEST(Morison, AxialFroudeKrylovOnAVerticalPipe) {
  // a vertical pipe, fully submerged (z from -35 to -10 m in 40 m of water), in an Airy
  // wave (H = 4 m, T = 8 s, no stretching): along its axis it feels the fluid inertia
  // rho A Cm_ax a_z with Cm_ax = 1 + Ca_ax (Froude-Krylov plus axial added mass), across
  // it rho A Cm a_x, where at x = 0 (DNV-RP-C205 table 3-1, seaflex's phase)
  //   a_x = -a w^2 cosh(k (z + d)) / sinh(k d) sin(w t),
  //   a_z = -a w^2 sinh(k (z + d)) / sinh(k d) cos(w t),
  // integrated over z in closed form. Without ca_axial Cm_ax = 1 (the Froude-Krylov part
  // alone); cm_axial: 0 leaves the axial term out. Gauss quadrature of the smooth
  // profiles over 5 m elements with 8 points: exact to round-off; 1e-9 of the peak.
  const double d = 40, H = 4, T = 8, D = 1.0, Cm = 2.0, rho = 1025, g = 9.81;
  const double area = 0.25 * kPi * D * D, z1 = -35, z2 = -10;
  const double w = 2 * kPi / T, k = hydro::wave_number(w, d, g), a = H / 2;
  const double int_cosh = (std::sinh(k * (z2 + d)) - std::sinh(k * (z1 + d))) / k;
  const double int_sinh = (std::cosh(k * (z2 + d)) - std::cosh(k * (z1 + d))) / k;
  for (const auto& [extra, cm_axial] : std::vector<std::pair<std::string, double>>{
           {"", 1.0}, {", ca_axial: 0.3", 1.3}, {", cm_axial: 0", 0.0}}) {
    const std::string yaml = R"(
environment:
  gravity: 9.81
  water: {density: 1025, depth: 40}
  waves: {type: airy, height: 4, period: 8, direction: 0, wheeler_stretching: false}
bodies:
  pipe:
    type: ancf_beam
    start: [0, 0, -35]
    end: [0, 0, -10]
    elements: 5
    outer_diameter: 1.0
    inner_diameter: 0.9
    youngs_modulus: 210e9
    density: 7850
hydrodynamics:
  pipe: {cm: 2.0, buoyancy: false, gauss_points: 8)" +
                             extra + "}\n";
    const io::Model m = io::load_model_text(yaml, "pipe.yaml");
    State s = m.system->initial_state();
    const Force& f = force_named(m, "pipe.morison");
    const double peak = rho * area * a * w * w / std::sinh(k * d) * std::max(int_cosh, int_sinh) *
                        std::max(Cm, 1.3);
    for (int i = 0; i < 16; ++i) {
      s.t = i * T / 16;
      const Vec3 F = beam_resultant(force_vector(m, f, s), 0, 6);
      const double fx =
          -rho * area * Cm * a * w * w / std::sinh(k * d) * int_cosh * std::sin(w * s.t);
      const double fz =
          -rho * area * cm_axial * a * w * w / std::sinh(k * d) * int_sinh * std::cos(w * s.t);
      EXPECT_NEAR(F.x(), fx, 1e-9 * peak) << extra << " t = " << s.t;
      EXPECT_NEAR(F.z(), fz, 1e-9 * peak) << extra << " t = " << s.t;
    }
  }
}

TEST(Morison, AxialAddedMass) {
  // a horizontal pipe along x with ca_axial 0.25: a rigid translation along x has the
  // added mass rho Ca_ax A L, across it rho Ca A L (exact quadrature: 1e-12 relative)
  const Vec3 mass = pipe_added_masses("{cd: 0.65, cm: 1.6, ca_axial: 0.25}");
  const double mass_a = 1025 * 0.25 * kPi * 0.49 * 24;
  for (int dir = 0; dir < 3; ++dir)
    EXPECT_NEAR(mass[dir], (dir == 0 ? 0.25 : 0.6) * mass_a, 1e-12 * mass_a) << dir;
}

TEST(Morison, AxialDragAndContentsWeight) {
  // current along the pipe's axis: only the axial (skin) drag 1/2 rho Cd_ax pi D U^2 L;
  // contents of density 1100 kg/m^3 in the bore add their weight rho_i A_i g L downward.
  // Constants integrated exactly: 1e-10 relative.
  const std::string yaml = R"(
environment:
  gravity: 9.81
  water: {density: 1025, depth: 200}
  current: {speed: 2.0, direction: 0}
bodies:
  pipe:
    type: ancf_beam
    start: [0, 0, -20]
    end: [30, 0, -20]
    elements: 5
    outer_diameter: 0.7
    inner_diameter: 0.4
    youngs_modulus: 210e9
    density: 7850
hydrodynamics:
  pipe: {cd: 0.65, cd_axial: 0.008, cm: 1.6, buoyancy: false, contents_density: 1100}
)";
  const io::Model m = io::load_model_text(yaml, "pipe.yaml");
  const State s = m.system->initial_state();
  const Vec3 F = beam_resultant(force_vector(m, force_named(m, "pipe.morison"), s), 0, 6);
  const double axial = 0.5 * 1025 * 0.008 * kPi * 0.7 * 4.0 * 30;
  const double contents = 1100 * 0.25 * kPi * 0.16 * 9.81 * 30;
  EXPECT_NEAR(F.x(), axial, 1e-10 * axial);
  EXPECT_NEAR(F.y(), 0.0, 1e-10 * axial);
  EXPECT_NEAR(F.z(), -contents, 1e-10 * contents);
}

}  // namespace

namespace {

TEST(Morison, EndPressureOnASurfacePiercingColumn) {
  // a vertical column member from z = -30 m through the surface (end effects on): the
  // vertical force is the wave pressure on its bottom face, p_d A, with the Airy pressure
  // rho g a cosh(k(z_s + d))/cosh(k d) cos(theta) at the Wheeler-stretched depth
  // z_s = d (z - eta)/(d + eta) (no normal Morison force acts vertically on a vertical
  // member). Closed form; 1e-9 relative asserted.
  const std::string yaml = R"(
environment:
  gravity: 9.81
  water: {density: 1025, depth: 60}
  waves: {type: airy, height: 6, period: 11, direction: 0}
bodies:
  spar:
    type: rigid_body
    mass: 1.0e6
    inertia: [1e8, 1e8, 1e7]
    position: [0, 0, -10]
joints:
  - {name: hold, type: fixed, from: {body: ground, position: [0, 0, -10]}, to: {body: spar}}
hydrodynamics:
  spar:
    morison:
      - {end_a: [0, 0, -20], end_b: [0, 0, 20], diameter: 12, cd: 0.7, cm: 2.0, end_effects: true}
)";
  const io::Model m = io::load_model_text(yaml, "spar.yaml");
  const auto& f = static_cast<const RigidMorison&>(force_named(m, "spar.morison"));
  State s = m.system->initial_state();
  const double d = 60, a = 3, w = 2 * kPi / 11, k = hydro::wave_number(w, d, 9.81);
  const double A = 0.25 * kPi * 144;
  double fmax = 0.0, err = 0.0;
  for (int i = 0; i < 16; ++i) {
    s.t = i * 11.0 / 16;
    const double th = w * s.t, eta = a * std::cos(th);
    const double zs = d * (-30 - eta) / (d + eta);
    const double ref =
        1025 * 9.81 * a * std::cosh(k * (zs + d)) / std::cosh(k * d) * std::cos(th) * A;
    const double Fz = f.wrench_at(s).force.z();
    fmax = std::max(fmax, std::abs(ref));
    err = std::max(err, std::abs(Fz - ref));
  }
  EXPECT_LT(err, 1e-9 * fmax);
}

}  // namespace

// fluid_reuse (forces/morison_beam.hpp): the fluid found at a Gauss point is used again
// while the time is the same and the point has moved by at most delta. A vertical pipe
// (z from -35 to -10 m, 40 m of water) in an Airy wave (H = 4 m, T = 8 s) and a 0.5 m/s
// current, delta = 1 mm. Moving every node by dr (|dr|_inf = 0.8 delta, slopes kept, so
// every point moves by dr): the load with reuse is exactly the load at the old place, and
// it differs from the load at the new place by at most its bound per unit length
//   rho Cd D/2 (2 |u_r| + |du|) |du| + rho A Cm |da|,  |du| <= |grad u|_F |dr|_2,
//   |da| <= w |du|,  |grad u|_F <= 2 k a w cosh(k (z + d)) / sinh(k d)
// (the four entries of the Airy velocity gradient), times the 25 m length. Moving by
// 2 delta or changing the time evaluates the sea again: the loads are then identical.
TEST(Morison, FluidReuseStaysWithinItsBound) {
  const double d = 40, H = 4, T = 8, D = 1.0, Cd = 1.0, Cm = 2.0, rho = 1025, g = 9.81;
  const double delta = 1e-3, L = 25, zt = -10, U = 0.5;
  const double w = 2 * kPi / T, k = hydro::wave_number(w, d, g), a = H / 2;
  auto model = [](const char* reuse) {
    return io::load_model_text(std::string(R"(
environment:
  gravity: 9.81
  water: {density: 1025, depth: 40}
  current: {speed: 0.5, direction: 0}
  waves: {type: airy, height: 4, period: 8, direction: 0}
bodies:
  pipe: {type: ancf_beam, start: [0, 0, -35], end: [0, 0, -10], elements: 5,
         outer_diameter: 1.0, inner_diameter: 0.9, youngs_modulus: 210e9, density: 7850}
hydrodynamics:
  pipe: {cd: 1.0, cm: 2.0, buoyancy: false)") +
                                   reuse + "}\n",
                               "pipe.yaml");
  };
  const io::Model with = model(", fluid_reuse: 0.001"), without = model("");
  const Force& fw = force_named(with, "pipe.morison");
  const Force& fo = force_named(without, "pipe.morison");
  auto resultant = [](const io::Model& m, const Force& f, const State& s) {
    return beam_resultant(force_vector(m, f, s), 0, 6);
  };
  auto moved = [](State s, const Vec3& dr) {
    for (int n = 0; n < 6; ++n) s.q.segment<3>(6 * n) += dr;
    return s;
  };
  const double grad_u = 2 * k * a * w * std::cosh(k * (zt + d)) / std::sinh(k * d);
  const double u_max = a * w * std::cosh(k * (zt + d)) / std::sinh(k * d) * std::sqrt(2.0) + U;
  const Vec3 dr = 0.8 * delta * Vec3(1, -1, 1);
  const double du = grad_u * dr.norm(), da = w * du;
  const double bound =
      L * (0.5 * rho * Cd * D * (2 * u_max + du) * du + rho * 0.25 * kPi * D * D * Cm * da);
  for (const double t : {0.7, 1.9, 3.4, 6.1}) {
    State s = with.system->initial_state();
    s.t = t;
    const Vec3 f0 = resultant(with, fw, s);  // first call: found, kept
    EXPECT_EQ((f0 - resultant(without, fo, s)).norm(), 0.0) << t;
    const State s1 = moved(s, dr);
    const Vec3 reused = resultant(with, fw, s1), exact = resultant(without, fo, s1);
    EXPECT_LT((reused - f0).norm(), 1e-12 * f0.norm()) << t;  // the kept fluid
    EXPECT_GT((reused - exact).norm(), 1e-3 * bound) << t;    // ... which is not the new one
    EXPECT_LT((reused - exact).norm(), bound) << t;
    const State s2 = moved(s, 2.0 * delta * Vec3(1, 0, 0));  // beyond delta: found again
    EXPECT_EQ((resultant(with, fw, s2) - resultant(without, fo, s2)).norm(), 0.0) << t;
    State s3 = s;
    s3.t = t + 0.01;  // another time: found again
    EXPECT_EQ((resultant(with, fw, s3) - resultant(without, fo, s3)).norm(), 0.0) << t;
  }
}
