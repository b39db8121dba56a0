// The first guess of a slack line's statics (issue 18): the inextensible catenary through
// the line's two ends with its unstretched length, in the vertical plane that holds them,
// lying on the seabed from its lower end where the hanging curve would dip below it.
//
// Free-hanging (Irvine, Cable Structures, 1981, sec. 1.2; z up, x horizontal from the
// start): z(x) = z_v + a (cosh((x - x_v) / a) - 1), arc length s(x) = a sinh((x - x_v) / a),
// so that sqrt(L^2 - h^2) = 2 a sinh(X / (2 a)) for a line of length L over the span X
// and the rise h, and x_v = X / 2 - a asinh(h / (2 a sinh(X / (2 a)))).
// With a laid length (the touchdown catenary of mooring analysis, e.g. Faltinsen, Sea
// Loads on Ships and Offshore Structures, 1990, sec. 8.1, with EA -> infinity): the line
// lies straight from its lower end over L_b and hangs from the touchdown point, where it
// is tangent to the seabed: the suspended length L_s = sqrt(h^2 + 2 a h), its span
// x_s = a asinh(L_s / a), and L_b + x_s = X, L_b + L_s = L.
// The catenary's shape depends on the geometry only (a = H / w cancels the weight), so
// the guess needs no loads; the stretch under tension is left to statics.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "seaflex/core/types.hpp"
#include "seaflex/elements/ancf_beam.hpp"

namespace seaflex {

struct CatenaryShape {
  double a = 0.0;            ///< catenary parameter H / w (m)
  double laid_length = 0.0;  ///< length on the seabed from the lower end (m)
  bool touchdown = false;    ///< part of the line lies on the seabed
};

/// Nodes equally spaced in arc length (elements equal, each length / elements) on the
/// catenary from start to end; slopes its unit tangents. seabed_z: the height of the
/// seabed under the lower end, if there is a seabed; the line is laid at the lower end's
/// height where the hanging curve would go below seabed_z. Throws std::invalid_argument
/// with a sentence for the user when no catenary exists: length not longer than the
/// chord, a vertical chord, or a line longer than the path along the seabed and straight
/// up (it would have to pile up). shape, when given, receives a and the laid length.
BeamGeometry catenary_geometry(const Vec3& start, const Vec3& end, double length, int elements,
                               std::optional<double> seabed_z, CatenaryShape* shape = nullptr);
/// The same with the given element lengths (from start; their sum is the line's length).
BeamGeometry catenary_geometry(const Vec3& start, const Vec3& end,
                               const std::vector<double>& element_lengths,
                               std::optional<double> seabed_z, CatenaryShape* shape = nullptr);

}  // namespace seaflex
