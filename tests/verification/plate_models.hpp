// The plate of thesis 3.1.2 (Table 4) as a model file, for the plate verification tests.
#pragma once

#include <fmt/format.h>

#include <string>

#include "analytic.hpp"
#include "seaflex/elements/ancf_plate.hpp"
#include "seaflex/io/model_loader.hpp"
#include "seaflex/solvers/statics.hpp"

namespace seaflex::plate_models {

// thesis Table 4; g as in the thesis (rho h g = 7798.95 Pa)
constexpr double kSide = 10.0, kH = 0.1, kE = 210e9, kNu = 0.3, kRho = 7950, kG = 9.81;

inline double flexural_rigidity() {
  return kE * kH * kH * kH / (12.0 * (1.0 - kNu * kNu));
}

/// Navier's centre deflection of the thesis plate under its own weight (m).
inline double navier_reference() {
  return analytic::navier_plate_centre(kRho * kH * kG, kSide, kSide, flexural_rigidity());
}

struct PlateCase {
  int n = 8;                                 ///< n x n elements (n even: a centre node)
  const char* support = "simply_supported";  ///< or clamped, on all four edges
  const char* midplane = "exact";
  const char* transverse = "exact";
  double load = 1.0;          ///< fraction of the self-weight (gravity kG)
  const char* in_plane = "";  ///< in_plane of a simply supported edge
};

/// The pairs of models statics can solve (the L1 tangent is singular).
inline const std::pair<const char*, const char*> kSolvableModels[] = {
    {"exact", "exact"}, {"exact", "T2"}, {"exact", "T3"},
    {"L3", "exact"},    {"L3", "T2"},    {"L3", "T3"}};

inline io::Model load(const PlateCase& c) {
  const std::string in_plane = *c.in_plane ? fmt::format(", in_plane: {}", c.in_plane) : "";
  const std::string text = fmt::format(
      R"(
environment: {{gravity: {g}}}
bodies:
  plate:
    type: ancf_plate
    corner: [0, 0, 0]
    edge1: [{a}, 0, 0]
    edge2: [0, {a}, 0]
    elements: [{n}, {n}]
    thickness: {h}
    youngs_modulus: {E}
    poisson_ratio: {nu}
    density: {rho}
    midplane_model: {m}
    transverse_model: {t}
supports:
  - {{body: plate, type: {s}, edges: [i0, i_max, j0, j_max]{ip}}}
)",
      fmt::arg("g", c.load * kG), fmt::arg("a", kSide), fmt::arg("n", c.n), fmt::arg("h", kH),
      fmt::arg("E", kE), fmt::arg("nu", kNu), fmt::arg("rho", kRho), fmt::arg("m", c.midplane),
      fmt::arg("t", c.transverse), fmt::arg("s", c.support), fmt::arg("ip", in_plane));
  return io::load_model_text(text, "plate");
}

/// Static deflection (m, positive down) of the centre node.
inline double centre_deflection(const PlateCase& c) {
  io::Model model = load(c);
  State s = model.system->initial_state();
  solve_statics(*model.system, s, model.statics);
  const auto& plate = dynamic_cast<const AncfPlate&>(*model.system->find_body("plate"));
  return -s.q[plate.node_index(c.n / 2, c.n / 2) + 2];
}

}  // namespace seaflex::plate_models
