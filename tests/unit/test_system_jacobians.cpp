// The assembled system: its Newton matrix equals the central difference of the assembled
// forces (every body, force and constraint together), C_q equals the difference of C,
// and the mass block is the assembled eq. (10).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include "seaflex/constraints/coordinate_lock.hpp"
#include "seaflex/elements/ancf_beam.hpp"
#include "seaflex/elements/rigid_body.hpp"
#include "seaflex/forces/distributed_load.hpp"
#include "seaflex/forces/gravity.hpp"
#include "seaflex/forces/point_load.hpp"
#include "seaflex/io/model_loader.hpp"
#include "seaflex/system/system.hpp"

using namespace seaflex;

namespace {

std::unique_ptr<System> make_system(ancf_cable::AxialModel axial,
                                    ancf_cable::BendingModel bending) {
  auto sys = std::make_unique<System>();
  BeamOptions opt;
  opt.axial = axial;
  opt.bending = bending;
  auto& beam = static_cast<AncfBeam&>(sys->add_body(
      std::make_unique<AncfBeam>("beam", BeamGeometry::straight(Vec3(0, 0, 0), Vec3(4, 1, -1), 4),
                                 BeamSection::pipe(0.3, 0.25, 2.1e11, 7850), opt)));
  sys->add_force(std::make_unique<Gravity>(Vec3(0, 0, -9.81), std::vector<const Body*>{&beam}));
  sys->add_force(
      std::make_unique<PointLoad>("tip", std::make_unique<BeamMarker>(beam, 2.7),
                                  VectorSignal(Vec3(100, 2e3, -5e3), TimeSignal::constant(1))));
  sys->add_force(std::make_unique<DistributedLoad>(
      "wind", beam, 1, 2, VectorSignal(Vec3(0, 50, 0), TimeSignal::constant(1))));
  sys->add_constraint(
      std::make_unique<CoordinateLock>("support", beam, std::vector<Index>{0, 1, 2, 3, 4, 5},
                                       std::vector<double>{0, 0, 0, 0.9, 0.2, -0.2},
                                       std::vector<std::string>{"x", "y", "z", "dx", "dy", "dz"}));
  sys->finalize();
  return sys;
}

}  // namespace

TEST(SystemJacobians, NewtonMatrixMatchesFiniteDifferences) {
  using ancf_cable::AxialModel;
  using ancf_cable::BendingModel;
  for (auto axial : {AxialModel::kExact, AxialModel::kL1, AxialModel::kL2})
    for (auto bending : {BendingModel::kExact, BendingModel::kExactDeformed, BendingModel::kT1,
                         BendingModel::kT2}) {
      auto sys = make_system(axial, bending);
      State s = sys->initial_state();
      s.q += 0.02 * VecX::Random(s.q.size());  // a deformed configuration
      DaeEval ev = sys->make_eval();
      const Index n = sys->num_coordinates();
      DaeRequest req;
      req.matrix = true;
      req.scales.kq = -1.0;  // matrix top-left = +dQ/dq
      sys->evaluate(s, req, ev);
      const MatX A = MatX(ev.kkt.matrix());
      const MatX dQdq = A.topLeftCorner(n, n);
      MatX fd(n, n);
      DaeEval ev2 = sys->make_eval();
      DaeRequest fr;
      for (Index j = 0; j < n; ++j) {
        const double h = 1e-6;
        State sp = s, sm = s;
        sp.q[j] += h;
        sm.q[j] -= h;
        sys->evaluate(sp, fr, ev2);
        const VecX Qp = ev2.Q;
        sys->evaluate(sm, fr, ev2);
        fd.col(j) = (Qp - ev2.Q) / (2 * h);
      }
      EXPECT_LT((dQdq - fd).norm(), 1e-6 * dQdq.norm())
          << to_string(axial) << "/" << to_string(bending);
      // C_q in the off-diagonal blocks: C = q_i - value for the locked coordinates
      const Index m = sys->num_constraints();
      const MatX Cq = A.bottomLeftCorner(m, n);
      EXPECT_EQ(Cq.rows(), 6);
      EXPECT_LT((Cq - MatX::Identity(6, n)).norm(), 1e-15);
      EXPECT_LT((A.topRightCorner(n, m) - Cq.transpose()).norm(), 1e-15);
    }
}

TEST(SystemJacobians, MassBlockAndEnergies) {
  auto sys = make_system(ancf_cable::AxialModel::kExact, ancf_cable::BendingModel::kExact);
  State s = sys->initial_state();
  DaeEval ev = sys->make_eval();
  DaeRequest req;
  req.forces = false;
  req.matrix = true;
  req.scales.km = 1.0;
  sys->evaluate(s, req, ev);
  const Index n = sys->num_coordinates();
  const MatX M = MatX(ev.kkt.matrix()).topLeftCorner(n, n);
  // a uniform velocity u of the whole beam: 1/2 u^T M u = 1/2 m |u|^2
  VecX u = VecX::Zero(n);
  for (Index k = 0; k < n; k += 6) u.segment<3>(k) = Vec3(1, 2, 3);
  const double mass = 7850 * BeamSection::pipe(0.3, 0.25, 2.1e11, 7850).area * std::sqrt(18.0);
  EXPECT_NEAR(u.dot(M * u), mass * 14.0, 1e-9 * mass);
  s.v = u;
  EXPECT_NEAR(sys->energies(s).kinetic, 0.5 * mass * 14.0, 1e-9 * mass);
  // undeformed straight beam: no strain energy; gravity potential -m g . r_cm
  EXPECT_LT(sys->energies(s).strain, 1e-9);
  const double z_cm = -0.5;
  EXPECT_NEAR(sys->energies(s).potential, mass * 9.81 * z_cm, 1e-9 * mass);
}

// Gravity on a beam of two sections and unequal elements: the force the beam adds (nodal
// weights summed once, ancf_beam.cpp) is minus the gradient of its potential, which sums thesis
// eq. (127) element by element (V = -Q_g . q: linear in q, so the central difference is exact
// up to round-off, 1e-12 of |Q|), and its translational part adds up to the weight m g.
TEST(SystemJacobians, BeamGravityIsMinusTheGradientOfItsPotential) {
  BeamGeometry geo;
  const Vec3 dir = Vec3(3, 1, -2).normalized();
  double s = 0.0;
  for (double l : {0.0, 1.5, 0.7, 2.2, 1.1, 0.4}) {
    s += l;
    geo.positions.push_back(s * dir);
    geo.slopes.push_back(dir);
    if (l > 0.0) geo.element_lengths.push_back(l);
  }
  const std::vector<BeamSection> sections{BeamSection::pipe(0.3, 0.25, 2.1e11, 7850),
                                          BeamSection::pipe(0.5, 0.1, 2.1e11, 3000)};
  const std::vector<int> section_of{0, 1, 1, 0, 1};
  System sys;
  auto& beam = static_cast<AncfBeam&>(
      sys.add_body(std::make_unique<AncfBeam>("beam", geo, sections, section_of, BeamOptions{})));
  sys.finalize();
  State st = sys.initial_state();
  st.q += 0.1 * VecX::Random(st.q.size());
  const Vec3 g(0.3, -0.2, -9.81);
  VecX Q = VecX::Zero(st.q.size());
  AssemblyTarget target;
  target.forces = &Q;
  beam.add_gravity(g, st, target);
  for (Index j = 0; j < st.q.size(); ++j) {
    State sp = st, sm = st;
    sp.q[j] += 0.5;
    sm.q[j] -= 0.5;
    const double dV = beam.gravity_potential(g, sp) - beam.gravity_potential(g, sm);
    EXPECT_NEAR(Q[j], -dV, 1e-12 * Q.norm()) << sys.coordinate_name(j);
  }
  double mass = 0.0;
  for (std::size_t el = 0; el < geo.element_lengths.size(); ++el)
    mass += sections[section_of[el]].mass_per_length() * geo.element_lengths[el];
  Vec3 total = Vec3::Zero();
  for (Index k = 0; k < Q.size(); k += 6) total += Q.segment<3>(k);
  EXPECT_LT((total - mass * g).norm(), 1e-12 * mass * g.norm());
}

TEST(SystemJacobians, NamesCoordinatesAndRows) {
  auto sys = make_system(ancf_cable::AxialModel::kExact, ancf_cable::BendingModel::kExact);
  EXPECT_EQ(sys->coordinate_name(0), "beam.n0.r.x");
  EXPECT_EQ(sys->coordinate_name(6 * 3 + 5), "beam.n3.r'.z");
  EXPECT_EQ(sys->constraint_name(4), "support: dy");
  EXPECT_EQ(sys->num_coordinates(), 30);
  EXPECT_EQ(sys->channels().size(), 15u);
  EXPECT_EQ(sys->channels()[4].name, "beam.n1.y");
}

// beam marker points: J = dp/dq against central differences, inside an element (12
// coordinates, J = S(xi), thesis eq. 3) and at a node (6 coordinates, J = [I 0])
TEST(SystemJacobians, BeamMarkerJacobian) {
  auto sys = make_system(ancf_cable::AxialModel::kExact, ancf_cable::BendingModel::kExact);
  const auto& beam = dynamic_cast<const AncfBeam&>(*sys->find_body("beam"));
  State s = sys->initial_state();
  s.q += 0.05 * VecX::Random(s.q.size());
  for (double arc : {0.0, 1.3, beam.node_arc_length(2), beam.length()}) {
    const BeamMarker p(beam, arc);
    const auto dofs = p.coordinates();
    MarkerVectorEval e;
    p.evaluate(MarkerVector::kPoint, s, e);
    const MatX J = e.J;
    for (std::size_t j = 0; j < dofs.size(); ++j) {
      const double h = 1e-6;
      State sp = s, sm = s;
      sp.q[dofs[j]] += h;
      sm.q[dofs[j]] -= h;
      const Vec3 fd = (p.position(sp) - p.position(sm)) / (2 * h);
      EXPECT_LT((fd - J.col(j)).norm(), 1e-8) << p.describe() << " column " << j;
    }
    // the position moves with no coordinate outside coordinates()
    State so = s;
    for (Index i = 0; i < so.q.size(); ++i)
      if (std::find(dofs.begin(), dofs.end(), i) == dofs.end()) so.q[i] += 1.0;
    EXPECT_LT((p.position(so) - p.position(s)).norm(), 1e-14) << p.describe();
  }
  EXPECT_EQ(BeamMarker(beam, 1.3).coordinates().size(), 12u);
  EXPECT_EQ(BeamMarker(beam, beam.node_arc_length(2)).describe(), "beam.n2");
}

namespace {

// the top-left n x n block of the system matrix for these scales (and accelerations)
MatX matrix_block(const System& sys, const State& s, MatrixScales scales, const VecX* a) {
  DaeEval e = sys.make_eval();
  DaeRequest r;
  r.forces = false;
  r.constraints = false;
  r.matrix = true;
  r.scales = scales;
  r.acceleration = a;
  sys.evaluate(s, r, e);
  const Index n = sys.num_coordinates();
  return MatX(e.kkt.matrix()).topLeftCorner(n, n);
}

// central differences (step 1e-6) of M(q) a over every coordinate
MatX mass_times_derivative_fd(const System& sys, const State& s, const VecX& a) {
  const Index n = sys.num_coordinates();
  MatX fd(n, n);
  const double eps = 1e-6;
  for (Index j = 0; j < n; ++j) {
    State p = s, m = s;
    p.q[j] += eps;
    m.q[j] -= eps;
    fd.col(j) = (matrix_block(sys, p, MatrixScales{1.0, 0.0, 0.0}, nullptr) * a -
                 matrix_block(sys, m, MatrixScales{1.0, 0.0, 0.0}, nullptr) * a) /
                (2 * eps);
  }
  return fd;
}

}  // namespace

// d(M(q) a)/dq (DaeRequest::acceleration, for implicit integrators) equals the central
// difference of M(q) a for a rigid body, whose Euler-parameter mass block 4 Gbar^T J' Gbar
// depends on q; tolerance 1e-7 of the entries' scale (central differences at 1e-6: error
// ~ 1e-12 relative truncation plus round-off eps/1e-6 ~ 2e-10).
TEST(SystemJacobians, MassTimesAccelerationDerivative) {
  System sys;
  RigidBodyInitial init;
  init.orientation = math::rotation_from_roll_pitch_yaw(0.3, -0.5, 1.1);
  Mat3 J;
  J << 2.0, 0.1, -0.2, 0.1, 3.0, 0.3, -0.2, 0.3, 4.0;
  sys.add_body(std::make_unique<RigidBody>("body", 5.0, J, init));
  sys.finalize();
  State s = sys.initial_state();
  const Index n = sys.num_coordinates();
  s.q.tail<4>() += 0.05 * math::Vec4(0.3, -0.2, 0.5, 0.1);  // off the unit sphere too
  const VecX a = VecX::Random(n);
  const MatX dMa = matrix_block(sys, s, MatrixScales{0.0, 1.0, 0.0}, &a);
  const MatX fd = mass_times_derivative_fd(sys, s, a);
  EXPECT_GT(fd.norm(), 1.0);  // the derivative is not trivially zero
  EXPECT_LT((dMa - fd).lpNorm<Eigen::Infinity>(), 1e-7 * fd.lpNorm<Eigen::Infinity>());
}

// the same for the added mass of a Morison beam, which turns with the beam's axis:
// Ca rho A (I - t t^T) at every wet quadrature point (a tilted, bent riser in water)
// (and, with an axial added mass, Ca_ax rho A t t^T besides)
TEST(SystemJacobians, TurningAddedMassDerivative) {
  for (const char* coefficients : {"{cd: 1.0, cm: 2.0}", "{cd: 1.0, cm: 2.0, ca_axial: 0.4}"}) {
    io::Model model = io::load_model_text(fmt::format(R"(
environment: {{gravity: 9.81, water: {{density: 1025, depth: 100}}}}
bodies:
  riser: {{type: ancf_beam, start: [0, 0, -100], end: [20, 5, -10], elements: 4,
          outer_diameter: 0.5, inner_diameter: 0.4, youngs_modulus: 210e9, density: 7850}}
hydrodynamics:
  riser: {}
)",
                                                      coefficients),
                                          "morison.yaml");
    System& sys = *model.system;
    State s = sys.initial_state();
    const Index n = sys.num_coordinates();
    s.q += 0.05 * VecX::Random(n);  // bent and stretched
    const VecX a = VecX::Random(n);
    // the d(M a)/dq part alone: the matrix with the acceleration minus the one without
    const MatX dMa = matrix_block(sys, s, MatrixScales{0.0, 1.0, 0.0}, &a) -
                     matrix_block(sys, s, MatrixScales{0.0, 1.0, 0.0}, nullptr);
    const MatX fd = mass_times_derivative_fd(sys, s, a);
    EXPECT_GT(fd.norm(), 1.0);
    EXPECT_LT((dMa - fd).lpNorm<Eigen::Infinity>(), 1e-6 * fd.lpNorm<Eigen::Infinity>())
        << coefficients;
  }
}

// Product mode (DaeRequest::product_with): the top-left block times x from the same
// element blocks, without the matrix, equals the assembled block times x; the forces of
// the same pass are those of an ordinary evaluation. A barge (rigid body, hydrostatics,
// Morison riser, joints, spring) in a state off equilibrium; round-off 1e-12 relative.
// Also a riser through the surface with contents and axial added mass (the beam's and
// the Morison load's own product paths: M = m (x) I3, the added mass point by point).
TEST(SystemJacobians, ProductModeEqualsTheAssembledBlockTimesAVector) {
  for (const bool riser_only : {false, true}) {
    const io::Model model =
        riser_only
            ? io::load_model_text(R"(
environment: {gravity: 9.81, water: {density: 1025, depth: 100}}
bodies:
  riser: {type: ancf_beam, start: [0, 0, -100], end: [20, 5, 10], elements: 7,
          outer_diameter: 0.5, inner_diameter: 0.4, youngs_modulus: 210e9, density: 7850}
hydrodynamics:
  riser: {cd: 1.0, cm: 2.0, ca_axial: 0.4, contents_density: 1100}
supports:
  - {body: riser, node: start, type: pinned}
)",
                                  "riser.yaml")
            : io::load_model_file(std::string(SEAFLEX_SOURCE_DIR) + "/examples/barge_riser.yaml");
    const System& sys = *model.system;
    ASSERT_TRUE(sys.supports_product());
    State s = sys.initial_state();
    const Index n = sys.num_coordinates();
    s.q += 1e-3 * VecX::Random(n);
    s.v = 0.1 * VecX::Random(n);
    const VecX x = VecX::Random(n);
    for (const MatrixScales scales : {MatrixScales{1.0, 0.0, 0.0}, MatrixScales{1.0, 0.3, 0.02}}) {
      DaeRequest req;
      req.matrix = true;
      req.scales = scales;
      DaeEval full = sys.make_eval(), prod = sys.make_eval();
      sys.evaluate(s, req, full);
      req.product_with = &x;
      sys.evaluate(s, req, prod);
      const SpMat block = full.kkt.matrix().topLeftCorner(n, n);
      const VecX ref = block * x;
      EXPECT_GT(ref.norm(), 1.0);
      EXPECT_LT((prod.product.head(n) - ref).lpNorm<Eigen::Infinity>(),
                1e-12 * ref.lpNorm<Eigen::Infinity>() + 1e-12 * MatX(block).cwiseAbs().maxCoeff());
      EXPECT_EQ((prod.Q - full.Q).lpNorm<Eigen::Infinity>(), 0.0);
      EXPECT_EQ((prod.C - full.C).lpNorm<Eigen::Infinity>(), 0.0);
      // an ordinary evaluation with the same workspace after a product one assembles again
      req.product_with = nullptr;
      sys.evaluate(s, req, prod);
      EXPECT_EQ((MatX(prod.kkt.matrix()) - MatX(full.kkt.matrix())).norm(), 0.0);
    }
  }
}

// DaeRequest::constraint_jacobian: C_q alone (m x n) equals the KKT matrix's bottom-left
// block, entry for entry, and the constraint values are those of an ordinary evaluation; the
// barge and riser (joints, a support, Euler-parameter normalization) off equilibrium.
TEST(SystemJacobians, ConstraintJacobianAloneEqualsTheKktBlock) {
  const io::Model model =
      io::load_model_file(std::string(SEAFLEX_SOURCE_DIR) + "/examples/barge_riser.yaml");
  const System& sys = *model.system;
  ASSERT_TRUE(sys.supports_constraint_jacobian());
  State s = sys.initial_state();
  const Index n = sys.num_coordinates(), m = sys.num_constraints();
  ASSERT_GT(m, 0);
  s.q += 1e-2 * VecX::Random(n);
  s.v = 0.1 * VecX::Random(n);
  DaeRequest req;
  req.matrix = true;
  req.scales = MatrixScales{1.0, 0.3, 0.02};
  DaeEval full = sys.make_eval(), alone = sys.make_eval();
  sys.evaluate(s, req, full);
  DaeRequest only;
  only.forces = false;
  only.constraint_jacobian = true;
  for (int pass = 0; pass < 2; ++pass) {  // twice: the second starts from the first's values
    sys.evaluate(s, only, alone);
    const MatX ref = MatX(full.kkt.matrix()).bottomLeftCorner(m, n);
    const MatX cq = MatX(alone.Cq.matrix());
    ASSERT_EQ(cq.rows(), m);
    ASSERT_EQ(cq.cols(), n);
    EXPECT_GT(ref.norm(), 1.0);
    EXPECT_EQ((cq - ref).norm(), 0.0);
    EXPECT_EQ((alone.C - full.C).norm(), 0.0);
    EXPECT_EQ((alone.Cdot - full.Cdot).norm(), 0.0);
  }
}

// The shortest element: the system's length scale (generalized-alpha's projection
// tolerance); a riser of 300 m in 10 elements and a plate of 2 x 1 m in 4 x 2 cells.
TEST(SystemJacobians, LengthScaleIsTheShortestElement) {
  const io::Model model = io::load_model_text(R"(
bodies:
  riser: {type: ancf_beam, start: [0, 0, -300], end: [0, 0, 0], elements: 10,
          outer_diameter: 0.5, inner_diameter: 0.4, youngs_modulus: 210e9, density: 7850}
)",
                                              "length.yaml");
  EXPECT_NEAR(model.system->length_scale(), 30.0, 1e-12);
  System empty;
  empty.finalize();
  EXPECT_TRUE(std::isinf(empty.length_scale()));
}
