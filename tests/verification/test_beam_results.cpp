// Beam results along the arc length (post/beam_results.hpp) against closed forms, in
// static equilibrium of models read from model files:
//  - a riser hanging under its own weight in air: wall tension = weight below;
//  - the same riser in water with contents: effective tension = submerged weight below
//    (steel + contents - buoyancy), wall tension = effective tension + p_i A_i - p_e A_e
//    with the pressures from the node depths;
//  - a pipe at depth with contents, pulled at its lower end: T_eff = T_wall - p_i A_i +
//    p_e A_e (DNV-OS-F201), and T_eff = pull + submerged weight below;
//  - a cantilever under a tip force: E I kappa = F (L - x) at the Gauss points.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "seaflex/io/model_loader.hpp"
#include "seaflex/io/output_selection.hpp"
#include "seaflex/post/beam_results.hpp"
#include "seaflex/solvers/statics.hpp"

using namespace seaflex;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kG = 9.81;

int col(post::BeamQuantity q) {
  return static_cast<int>(q);
}

struct Solved {
  io::Model model;
  State state;
  const AncfBeam* beam = nullptr;
};

Solved solve(const std::string& yaml) {
  Solved s{io::load_model_text(yaml, "model.yaml"), {}, nullptr};
  s.state = s.model.system->initial_state();
  StaticsSettings settings = s.model.statics;
  settings.tolerance = 1e-12;  // far below the tolerances asked of the results
  solve_statics(*s.model.system, s.state, settings);
  s.beam = dynamic_cast<const AncfBeam*>(s.model.system->bodies().front().get());
  return s;
}

// a 100 m steel riser, 20 elements, pinned at its top node (the start), free at the bottom
std::string riser(const std::string& top, const std::string& bottom, const std::string& extra) {
  return fmt::format(R"(
environment:
  gravity: {}
{}
bodies:
  riser:
    type: ancf_beam
    start: {}
    end: {}
    elements: 20
    outer_diameter: 0.5
    inner_diameter: 0.45
    youngs_modulus: 2.1e11
    density: 7850
supports:
  - {{body: riser, node: start, type: pinned}}
)",
                     kG, extra, top, bottom);
}

}  // namespace

TEST(BeamResults, HangingRiserInAirCarriesTheWeightBelow) {
  const Solved s = solve(riser("[0, 0, 0]", "[0, 0, -100]", ""));
  const post::BeamResults results(*s.beam, io::pipe_pressure(s.model, *s.beam));
  MatX out;
  results.compute(s.state, out);
  const double A = kPi / 4 * (0.5 * 0.5 - 0.45 * 0.45), w = 7850 * A * kG, L = 100.0;
  const double I = kPi / 64 * (std::pow(0.5, 4) - std::pow(0.45, 4)), E = 2.1e11;
  ASSERT_EQ(results.num_stations(), 3 * 20 + 1);  // nodes and 2 Gauss points per element
  for (Index i = 0; i < results.num_stations(); ++i) {
    const double sref = results.stations()[static_cast<std::size_t>(i)].s;
    const double expected = w * (L - sref);
    // the strain of the hanging riser (u' linear in s) is exact in the cubic elements;
    // what is left is the statics tolerance and the nonlinear strain: 1e-6 relative
    // (1e-9 of the top tension where the tension vanishes)
    EXPECT_NEAR(out(i, col(post::BeamQuantity::kTensionWall)), expected,
                1e-6 * expected + 1e-9 * w * L)
        << "station " << i << " at s = " << sref;
    // in air: no pressure, effective = wall tension
    EXPECT_EQ(out(i, col(post::BeamQuantity::kTensionEffective)),
              out(i, col(post::BeamQuantity::kTensionWall)));
    // a straight line does not bend: round-off of E I (1e6 N m^2) times r'' (~1e-16)
    EXPECT_LE(out(i, col(post::BeamQuantity::kMoment)), 1e-12 * w * L * L);
    EXPECT_NEAR(out(i, col(post::BeamQuantity::kStressAxial)), expected / A,
                1e-6 * expected / A + 1e-9 * w * L / A);
    // no bending, no pressure: von Mises = |axial stress|
    EXPECT_NEAR(out(i, col(post::BeamQuantity::kStressVonMises)),
                std::abs(out(i, col(post::BeamQuantity::kStressAxial))), 1e-9 * w * L / A);
  }
  EXPECT_GT(E * I, 0.0);
}

TEST(BeamResults, HangingRiserInWaterWithContents) {
  const std::string water = R"(  water: {density: 1025, depth: 1000}
)";
  const std::string hydro = R"(
hydrodynamics:
  riser: {cd: 1.0, contents_density: 1200}
)";
  const Solved s = solve(riser("[0, 0, -10]", "[0, 0, -110]", water) + hydro);
  const post::PipePressure p = io::pipe_pressure(s.model, *s.beam).at(0);
  ASSERT_EQ(p.water_density, 1025.0);
  ASSERT_EQ(p.external_diameter, 0.5);   // the Morison diameter: outer_diameter
  ASSERT_EQ(p.contents_diameter, 0.45);  // contents_diameter: inner_diameter
  const post::BeamResults results(*s.beam, p);
  MatX out;
  results.compute(s.state, out);
  const double Ae = kPi / 4 * 0.5 * 0.5, Ai = kPi / 4 * 0.45 * 0.45, A = Ae - Ai, L = 100.0;
  const double w_sub = (7850 * A + 1200 * Ai - 1025 * Ae) * kG;  // submerged weight per m
  const double z_top = s.state.q[s.beam->node_index(0) + 2];
  ASSERT_GT(w_sub, 0.0);
  for (int k = 0; k <= 20; ++k) {
    const Index i = 3 * k;  // node k
    const double sref = s.beam->node_arc_length(k);
    const double z = s.state.q[s.beam->node_index(k) + 2];
    const double T_eff = w_sub * (L - sref);
    // as in air: the model's axial force carries the effective weight below
    EXPECT_NEAR(out(i, col(post::BeamQuantity::kTensionEffective)), T_eff,
                1e-6 * T_eff + 1e-9 * w_sub * L)
        << "node " << k;
    // wall tension from the pressures at the node's depth; the lower part is in
    // compression (the water pushes on the closed lower end)
    const double p_e = 1025 * kG * (-z), p_i = 1200 * kG * (z_top - z);
    const double T_wall = T_eff + p_i * Ai - p_e * Ae;
    EXPECT_NEAR(out(i, col(post::BeamQuantity::kTensionWall)), T_wall, 1e-6 * w_sub * L)
        << "node " << k;
    EXPECT_NEAR(out(i, col(post::BeamQuantity::kPressureExternal)), p_e, 1e-12 * p_e);
    EXPECT_NEAR(out(i, col(post::BeamQuantity::kPressureInternal)), p_i, 1e-12 * p_e);
  }
  // at the free lower end the wall force is the pressures on the closed end:
  // -p_e A_e + p_i A_i, exactly what a capped pipe feels
  const double z_bot = s.state.q[s.beam->node_index(20) + 2];
  EXPECT_NEAR(out(60, col(post::BeamQuantity::kTensionWall)),
              -1025 * kG * (-z_bot) * Ae + 1200 * kG * (z_top - z_bot) * Ai, 1e-6 * w_sub * L);
}

TEST(BeamResults, EffectiveTensionOfAPressurizedPipeUnderTension) {
  const std::string model =
      riser("[0, 0, -50]", "[0, 0, -150]", R"(  water: {density: 1025, depth: 1000}
)") + R"(
hydrodynamics:
  riser: {contents_density: 850, contents_diameter: 0.44}
loads:
  - {type: point_force, body: riser, node: end, force: [0, 0, -2.0e6]}
)";
  const Solved s = solve(model);
  const post::BeamResults results(*s.beam, io::pipe_pressure(s.model, *s.beam));
  MatX out;
  results.compute(s.state, out);
  const double Ae = kPi / 4 * 0.5 * 0.5, Ai = kPi / 4 * 0.44 * 0.44, L = 100.0;
  const double A = kPi / 4 * (0.5 * 0.5 - 0.45 * 0.45);
  const double w_sub = (7850 * A + 850 * Ai - 1025 * Ae) * kG, F = 2.0e6;
  double z_top = -1e9;
  for (int k = 0; k <= 20; ++k) z_top = std::max(z_top, s.state.q[s.beam->node_index(k) + 2]);
  for (Index i = 0; i < results.num_stations(); ++i) {
    const double T_wall = out(i, col(post::BeamQuantity::kTensionWall));
    const double T_eff = out(i, col(post::BeamQuantity::kTensionEffective));
    const double z = out(i, col(post::BeamQuantity::kZ));
    const double p_i = 850 * kG * (z_top - z), p_e = 1025 * kG * (-z);
    // the definition of DNV-OS-F201 with the pressures at the station's depth: only
    // round-off of sums of about 2 MN (1e-9 relative)
    EXPECT_NEAR(T_eff, T_wall - p_i * Ai + p_e * Ae, 1e-9 * F) << "station " << i;
    // and the equilibrium: the pull plus the submerged weight below
    const double sref = results.stations()[static_cast<std::size_t>(i)].s;
    EXPECT_NEAR(T_eff, F + w_sub * (L - sref), 1e-6 * F) << "station " << i;
  }
}

// A state that is not finite (a node's coordinates NaN, as a diverging run leaves them) gives
// NaN stresses at the stations of the elements it touches, not 0: the envelopes and code
// checks read a NaN as a failed result (std::max(0, NaN) is 0, which hid it until the
// twelfth session). The stations of the other elements keep their finite values.
TEST(BeamResults, AStateThatIsNotFiniteGivesNaNStressesNotZero) {
  const std::string model =
      riser("[0, 0, -50]", "[0, 0, -150]", R"(  water: {density: 1025, depth: 1000}
)") + R"(
hydrodynamics:
  riser: {contents_density: 850, contents_diameter: 0.44}
)";
  Solved s = solve(model);
  const post::BeamResults results(*s.beam, io::pipe_pressure(s.model, *s.beam));
  MatX out;
  results.compute(s.state, out);
  const int vm = col(post::BeamQuantity::kStressVonMises);
  for (Index i = 0; i < results.num_stations(); ++i) ASSERT_GT(out(i, vm), 0.0) << i;
  State bad = s.state;
  const int node = 10;  // an interior node: elements 9 and 10
  for (int j = 0; j < 6; ++j) bad.q[s.beam->node_index(node) + j] = std::nan("");
  results.compute(bad, out);
  int nan_stations = 0;
  for (Index i = 0; i < results.num_stations(); ++i) {
    const post::BeamStation& st = results.stations()[static_cast<std::size_t>(i)];
    const bool touched = st.element == node - 1 || st.element == node ||
                         (st.node >= node - 1 && st.node <= node + 1);
    if (touched) {
      EXPECT_TRUE(std::isnan(out(i, vm))) << "station " << i << ": " << out(i, vm);
      EXPECT_TRUE(std::isnan(out(i, col(post::BeamQuantity::kStressBending)))) << i;
      ++nan_stations;
    } else {
      EXPECT_TRUE(std::isfinite(out(i, vm))) << "station " << i;
    }
  }
  EXPECT_GE(nan_stations, 5);  // the two elements' Gauss points and three nodes
}

TEST(BeamResults, CantileverMomentUnderATipForce) {
  // 10 m cantilever, 10 elements, tip force 1 kN down (tip deflection F L^3/(3 EI) =
  // 0.19 m, 2 % of L: close to linear)
  const Solved s = solve(R"(
environment: {gravity: 0}
bodies:
  beam: {type: ancf_beam, start: [0, 0, 0], end: [10, 0, 0], elements: 10, area: 0.01,
         second_moment: 8.33e-6, youngs_modulus: 210e9, density: 7850}
supports:
  - {body: beam, node: start, type: clamped}
loads:
  - {type: point_force, body: beam, node: end, force: [0, 0, -1000]}
)");
  const post::BeamResults results(*s.beam, io::pipe_pressure(s.model, *s.beam));
  MatX out;
  results.compute(s.state, out);
  const double F = 1000.0, L = 10.0;
  int gauss = 0;
  for (Index i = 0; i < results.num_stations(); ++i) {
    const post::BeamStation& st = results.stations()[static_cast<std::size_t>(i)];
    if (st.node >= 0) continue;
    ++gauss;
    const double expected = F * (L - st.s);
    // cubic elements hold a linear moment exactly (and the Gauss points are the Barlow
    // points); the 2 % deflection changes the lever arm by well under 1 %
    EXPECT_NEAR(out(i, col(post::BeamQuantity::kMoment)), expected, 0.01 * expected)
        << "Gauss point at s = " << st.s;
    // bending in the x-z plane: the moment vector is along y (hogging: +y for r' x r'')
    EXPECT_NEAR(out(i, col(post::BeamQuantity::kMomentY)), expected, 0.01 * expected);
    EXPECT_NEAR(out(i, col(post::BeamQuantity::kMomentX)), 0.0, 1e-9 * F * L);
    EXPECT_NEAR(out(i, col(post::BeamQuantity::kMomentZ)), 0.0, 1e-9 * F * L);
    // no section diameters: no fibre stresses
    EXPECT_TRUE(std::isnan(out(i, col(post::BeamQuantity::kStressVonMises))));
  }
  EXPECT_EQ(gauss, 20);
}

// BeamResults::compute takes each station's shape functions from a table made once and each
// element's coordinates once for all its stations (post/beam_results.hpp). Against the
// evaluation it replaced, point by point from the element's coordinates
// (CableElasticity::curvature_vector(e, xi), the shape functions at xi): cantilevers bent out
// of their plane by a tip force with three components, with 0, 2 and 3 stations per element
// between the nodes; one of 7 equal elements with the default models, one of two sections of
// unequal elements (3 of 1.5 m, 4 of 1.375 m: two elasticity kernels) with the L1 axial
// model (chord strain) and T2 (the deformed-length curvature). Position, strain, effective
// tension EA eps |r'| and moment vector at every station (the mean of the two elements at an
// interior node), and the von Mises stress of the pipe in air, |T / A| + M r_o / I.
// Tolerances: 1e-13 of each quantity's scale (10 m for positions, 1 for the strain, whose
// terms |r'|^2 are of order 1, EA for the tension, the root moment for the moments): the same
// arithmetic, which a build that contracts multiply-adds may round differently.
TEST(BeamResults, StationsFromTheirTablesEqualThePointwiseEvaluation) {
  const std::string uniform = R"(
environment: {gravity: 0}
bodies:
  beam: {type: ancf_beam, start: [0, 0, 0], end: [10, 0, 0], elements: 7, outer_diameter: 0.2,
         inner_diameter: 0.16, youngs_modulus: 210e9, density: 7850}
supports:
  - {body: beam, node: start, type: clamped}
loads:
  - {type: point_force, body: beam, node: end, force: [-2.0e4, 6.0e4, -1.0e5]}
)";
  std::string sections = uniform;
  sections.replace(sections.find("elements: 7"), 11,
                   "axial_model: L1, bending_model: T2,\n         sections: "
                   "[{name: a, length: 4.5, segment_length: 1.5}, {name: b, length: 5.5, "
                   "segment_length: 1.4}]");
  const double scale_m = 10.0 * std::hypot(6.0e4, 1.0e5);  // the root moment, about
  for (const std::string& model : {uniform, sections}) {
    const Solved s = solve(model);
    const AncfBeam& beam = *s.beam;
    const int n = beam.num_elements();
    ASSERT_EQ(n, 7);
    const bool l1 = beam.options().axial == ancf_cable::AxialModel::kL1;
    struct Point {
      Vec3 r, m;
      double eps, t_eff;
    };
    auto point = [&](int el, double xi) {  // by hand, from the element's coordinates
      const double l = beam.element_length(el);
      const BeamSection& sec = beam.section(el);
      const ancf_cable::Vec12 e = beam.element_coordinates(s.state.q, el);
      const ancf_cable::Mat34 R = ancf_cable::relative_nodes(e);
      const Vec3 rp = R * ancf_cable::shape_dx(xi, l);
      const double eps = l1 ? ((R.col(2) - R.col(0)).norm() - l) / l  // thesis eq. (24)
                            : 0.5 * (rp.squaredNorm() - 1.0);         // thesis eq. (12)
      return Point{Eigen::Map<const ancf_cable::Mat34>(e.data()) * ancf_cable::shape(xi, l),
                   sec.EI() * beam.elasticity(el).curvature_vector(e, xi), eps,
                   sec.EA() * eps * rp.norm()};
    };
    constexpr double kTol = 1e-13;
    for (int gauss : {0, 2, 3}) {
      const post::BeamResults results(beam, io::pipe_pressure(s.model, beam), gauss);
      MatX out;
      results.compute(s.state, out);
      ASSERT_EQ(results.num_stations(), n + 1 + n * gauss);
      double m_max = 0.0;
      for (Index i = 0; i < results.num_stations(); ++i) {
        const post::BeamStation& st = results.stations()[static_cast<std::size_t>(i)];
        const BeamSection& sec = beam.section(st.element);
        Point p = point(st.element, st.xi);
        if (st.node > 0 && st.node < n) {
          const Point left = point(st.node - 1, 1.0);
          p.m = 0.5 * (p.m + left.m);
          p.eps = 0.5 * (p.eps + left.eps);
          p.t_eff = 0.5 * (p.t_eff + left.t_eff);
        }
        const std::string where = fmt::format("station {}, {} per element, {}", i, gauss,
                                              l1 ? "sections, L1" : "uniform");
        for (int c = 0; c < 3; ++c)
          EXPECT_NEAR(out(i, col(post::BeamQuantity::kX) + c), p.r[c], kTol * 10.0) << where;
        EXPECT_NEAR(out(i, col(post::BeamQuantity::kStrain)), p.eps, kTol) << where;
        EXPECT_NEAR(out(i, col(post::BeamQuantity::kTensionEffective)), p.t_eff, kTol * sec.EA())
            << where;
        EXPECT_EQ(out(i, col(post::BeamQuantity::kTensionWall)),
                  out(i, col(post::BeamQuantity::kTensionEffective)));  // in air, empty
        const double M = p.m.norm();
        m_max = std::max(m_max, M);
        for (int c = 0; c < 3; ++c)
          EXPECT_NEAR(out(i, col(post::BeamQuantity::kMomentX) + c), p.m[c], kTol * scale_m)
              << where;
        EXPECT_NEAR(out(i, col(post::BeamQuantity::kMoment)), M, kTol * scale_m) << where;
        const double vm = std::abs(p.t_eff / sec.area) + M * 0.1 / sec.second_moment;
        EXPECT_NEAR(out(i, col(post::BeamQuantity::kStressVonMises)), vm,
                    kTol * (sec.EA() / sec.area + scale_m * 0.1 / sec.second_moment))
            << where;
      }
      // the bending is not trivial: the root moment is |L x F| of the tip force's transverse
      // components (within the deflection's change of the lever arm)
      EXPECT_GT(m_max, 0.9 * scale_m);
    }
  }
}
