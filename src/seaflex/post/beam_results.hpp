// Results of an ANCF beam along its arc length at one state: wall and effective tension,
// axial strain, curvature, bending moment, and the stresses at the outer fibre of a pipe.
//
// Symbols: r' = dr/dx (x the unstretched arc length), lambda = |r'| the stretch,
//   eps   axial strain of the beam's axial model: Green-Lagrange 1/2 (r'.r' - 1)
//         (thesis eq. 12) for the exact and L2 models, the chord strain (d - l)/l
//         (thesis eq. 24) for L1;
//   kappa = |r' x r''| / |r'|^n, the curvature of the beam's bending model: n = 2 (per
//         reference length, d theta/dx) for `exact`, n = 3 (thesis eq. 14, per deformed
//         length) for `exact_deformed`, T1 and T2
//   A_e = pi D_e^2 / 4 (D_e the hydrodynamic diameter of the Morison entry),
//   A_i = pi D_i^2 / 4 (D_i the contents diameter), A and I those of the section.
// Tensions. The elastic axial force of the element is N = EA eps r' (the variation of
// the axial energy of thesis eq. 15 is int EA eps r'.dr' dx), so its magnitude
//   T_axial = EA eps lambda
// is the force the section carries in the deformed state. Buoyancy and the contents'
// weight enter the model as distributed loads (forces/morison_beam.hpp), which makes this
// force the effective tension (Sparks 1984; DNV-OS-F201 and API RP 2RD, effective tension):
//   T_eff  = T_axial
//   T_wall = T_eff + p_i A_i - p_e A_e        (DNV-OS-F201: T_eff = T_wall - p_i A_i + p_e A_e)
// with p_e = rho_w g max(0, -z) the hydrostatic pressure below the mean surface z = 0 and
// p_i = rho_i g (z_top - z) the pressure of a contents column whose free surface is at
// the beam's highest node. A beam in air without contents has T_wall = T_eff.
// Bending: M = EI r' x r'' / |r'|^n, the moment vector EI kappa b (b the binormal); the
// resultant |M| = EI kappa and its three components in global axes are given (for a
// vertical riser M_x and M_y are the moments of bending in the y-z and x-z planes).
// Stresses at the outer fibre r_o = D_o/2 of a pipe section (outer/inner diameter):
//   sigma_a = T_wall / A,  sigma_b = |M| r_o / I,
//   Lame (thick wall) at r_o: sigma_r = -p_e,
//                             sigma_h = (2 p_i r_i^2 - p_e (r_o^2 + r_i^2)) / (r_o^2 - r_i^2)
//   von Mises of the three principal stresses (no shear or torsion): the larger of the values at
//   the fibres sigma_z = sigma_a +- sigma_b. NaN for sections given by area/second moment.
// Neglected: the bending energy's share of the axial force (of order EI kappa^2), wave
// pressure in p_e, the Poisson coupling of pressure and strain.
// Stations: every node, and the Gauss-Legendre points of each element (2 by default: the
// Barlow points, where the bending moment of cubic elements is most accurate). At an
// interior node the two adjacent elements' values are averaged (equal for the tension of
// the exact and L2 models, where r' is a nodal coordinate).
#pragma once

#include <array>
#include <string_view>
#include <vector>

#include "seaflex/elements/ancf_beam.hpp"
#include "seaflex/model/state.hpp"

namespace seaflex::post {

/// What the water and the contents do to a beam's section. All zero: a beam in air
/// without contents.
struct PipePressure {
  double water_density = 0.0;      ///< rho_w (kg/m^3); 0 when the beam feels no water
  double gravity = 0.0;            ///< g (m/s^2)
  double external_diameter = 0.0;  ///< D_e on which the buoyancy acts (m)
  double contents_density = 0.0;   ///< rho_i (kg/m^3); 0 when empty
  double contents_diameter = 0.0;  ///< D_i (m)
};

/// A point along the beam where results are given.
struct BeamStation {
  int element = 0;  ///< the element the point lies in (the right one at a node)
  double xi = 0.0;  ///< local coordinate in [0, 1]
  double s = 0.0;   ///< unstretched arc length from the start node (m)
  int node = -1;    ///< node number when the station is a node, else -1
};

/// The quantities at a station, in output order (the columns of BeamResults::compute).
enum class BeamQuantity {
  kX,
  kY,
  kZ,
  kStrain,
  kTensionWall,
  kTensionEffective,
  kCurvature,
  kMoment,
  kMomentX,
  kMomentY,
  kMomentZ,
  kPressureInternal,
  kPressureExternal,
  kStressAxial,
  kStressBending,
  kStressVonMises,
};
inline constexpr int kBeamQuantityCount = 16;

struct BeamQuantityInfo {
  std::string_view name;  ///< output column / dataset name
  std::string_view unit;
};
/// Names and units, indexed by BeamQuantity.
const std::array<BeamQuantityInfo, kBeamQuantityCount>& beam_quantities();

class BeamResults {
 public:
  /// gauss_points: stations per element between the nodes (>= 0).
  BeamResults(const AncfBeam& beam, PipePressure pressure, int gauss_points = 2);
  /// A line made of sections: pressures[i] for the beam's section i (one per
  /// beam.sections()).
  BeamResults(const AncfBeam& beam, std::vector<PipePressure> pressures, int gauss_points = 2);

  const AncfBeam& beam() const { return beam_; }
  /// The pressures of the beam's section i.
  const PipePressure& pressure(int section = 0) const { return pressures_[section]; }
  const std::vector<BeamStation>& stations() const { return stations_; }
  Index num_stations() const { return static_cast<Index>(stations_.size()); }

  /// Every quantity at every station: out(station, quantity), resized to
  /// num_stations() x kBeamQuantityCount. Cost linear in the number of elements.
  void compute(const State& state, MatX& out) const;

 private:
  struct Point {
    Vec3 r, rp, m;  // position, slope, moment vector
    double eps = 0.0;
    double t_eff = 0.0;  // EA eps |r'|, the effective tension
  };
  // One element at one xi, its shape functions computed once: s and s' with the element's
  // length (r, r'), s' and s'' with its elasticity kernel's length (the curvature, as
  // CableElasticity::curvature_vector(e, xi) takes them)
  struct Sample {
    int element = -1;  // -1: none (the left side of a station that is not an interior node)
    ancf_cable::Vec4 s, s_x, s_x_kernel, s_xx_kernel;
  };
  // An element's coordinates and relative node matrix, shared by its samples
  struct Coordinates {
    int element = -1;
    ancf_cable::Vec12 e;
    ancf_cable::Mat34 R;
  };
  Sample sample(int element, double xi) const;
  Point evaluate(const Sample& sample, const Coordinates& c) const;

  const AncfBeam& beam_;
  std::vector<PipePressure> pressures_;  // per beam section
  std::vector<BeamStation> stations_;
  std::vector<Sample> own_;   // per station: its element at its xi
  std::vector<Sample> left_;  // per station: at an interior node, the element before it at 1
};

}  // namespace seaflex::post
