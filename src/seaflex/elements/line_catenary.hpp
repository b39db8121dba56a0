// The first guess of a slack line whose weight varies along it (issue 18: lines made of
// sections, clumps, buoyancy modules; a lazy-wave riser): the inextensible catenary of a
// chain of pieces of constant submerged weight per length, with point weights between
// them, through the line's two ends, laid on the seabed from its lower end where its
// tension has no vertical part.
// Equilibrium of the part of the line from its lower end P to arc length sigma (no
// bending, no current): the horizontal tension H is constant and the vertical one is
// V(sigma) = V_P + W(sigma), W the weight of the line and its point loads up to sigma
// (positive down). Over a piece of constant weight w (N/m) from V_a to V_b = V_a + w ds
// the catenary gives (Irvine, Cable Structures, 1981, sec. 1.2, piecewise)
//   dx = H / w (asinh(V_b / H) - asinh(V_a / H)),  dz = (sqrt(H^2 + V_b^2) - sqrt(H^2 + V_a^2)) / w
// and a straight piece when w = 0. With V_P < 0 and a seabed, the line lies straight on
// the seabed from P up to the touchdown sigma_td, V_P + W(sigma_td) = 0 (the classic
// touchdown catenary of mooring analysis, e.g. Faltinsen 1990, sec. 8.1, with EA -> inf).
// H and V_P are found by Newton's method (a finite-difference Jacobian, backtracking)
// so that the line ends at the upper end; the uniform catenary (catenary_shape.hpp)
// gives the start.
#pragma once

#include <optional>
#include <utility>
#include <vector>

#include "seaflex/core/types.hpp"
#include "seaflex/elements/ancf_beam.hpp"
#include "seaflex/elements/catenary_shape.hpp"

namespace seaflex {

/// The submerged weight along a line, by reference arc length from its start.
struct LineWeights {
  std::vector<double> per_length;                 ///< per element (N/m), positive down
  std::vector<std::pair<double, double>> points;  ///< (arc length (m), weight (N) down)
};

/// The node positions and unit slopes of the weighted catenary from start to end with
/// the given element lengths (their sum: the line's length, longer than the chord) and
/// weights, laid on the seabed at the lower end's height when seabed is true; guess and
/// shape: the uniform catenary's geometry and parameters (catenary_geometry), which
/// start the iteration.
/// nullopt when no such catenary is found (a line that does not hang, e.g. one lighter
/// than water in all, or no convergence): the caller keeps its guess.
std::optional<BeamGeometry> weighted_catenary(const Vec3& start, const Vec3& end,
                                              const std::vector<double>& element_lengths,
                                              const LineWeights& weights, bool seabed,
                                              const BeamGeometry& guess,
                                              const CatenaryShape& shape);

}  // namespace seaflex
