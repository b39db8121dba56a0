// Fatigue damage of pipe sections from a stress history: hot-spot stresses at points
// around the circumference, streaming rainflow counting (rainflow.hpp) and Miner's sum
// over an S-N curve (sn_curve.hpp).
//
// Stress at a point of the outer fibre. A pipe with wall (true) tension T_wall, bending
// moment vector M (perpendicular to the unit tangent t), area A and second moment I; the
// point at angle theta has the unit radial direction
//   n(theta) = cos(theta) e1 + sin(theta) e2,  e2 = t x e1,
// and the nominal axial stress (Navier; the moment vector M = EI r' x r'' / |r'|^3 of
// post/beam_results.hpp)
//   sigma(theta) = T_wall / A + ((t x M) . n(theta)) r_o / I
// (positive in tension: for t = z, M = M_x x the fibre at +y is stretched). The hot-spot
// stress is SCF sigma (DNV-RP-C203 (2016) section 2.3.3 and eq. (2.3.1)); the thickness
// effect multiplies every stress range by (t/t_ref)^k (eq. (2.4.3)).
// The frame: e1 is a fixed reference axis projected on the section's plane, so points keep
// their place while the pipe bends (the ANCF cable has no torsion: the circumferential
// origin is a convention). The reference axis is chosen once per station from its first
// tangent: the global axis least parallel to it (x for a vertical riser).
// Miner's rule: D = sum_i n_i / N(dsigma_i), half cycles counted as 0.5 (DNV-RP-C203
// (2016) eq. (2.2.1), ASTM E1049-85 5.4.4).
#pragma once

#include <span>
#include <vector>

#include "seaflex/core/types.hpp"
#include "seaflex/post/rainflow.hpp"
#include "seaflex/post/sn_curve.hpp"

namespace seaflex::post {

/// The global axis least parallel to the unit tangent t (x, y or z; the first of equals).
Vec3 circumference_reference(const Vec3& t);

/// The nominal axial stress (Pa) at `points` equally spaced points of the outer fibre,
/// theta_j = 2 pi j / points from e1 = the projection of ref on the plane normal to t.
/// t need not be unit length; when ref is parallel to t, circumference_reference(t) is used.
void pipe_fibre_stresses(double tension_wall, const Vec3& moment, const Vec3& t, const Vec3& ref,
                         double area, double second_moment, double outer_radius,
                         std::span<double> out);

/// Miner damage of several stress histories that arrive sample by sample, one rainflow
/// counter per history (memory: the counters' stacks; no history is kept).
class FatigueDamage {
 public:
  /// histories: number of stress series; range_factor multiplies every stress range before
  /// the S-N curve (SCF times the thickness factor).
  FatigueDamage(int histories, SnCurve curve, double range_factor);

  /// One sample of every history (stresses in Pa, size histories()).
  void add(std::span<const double> stresses);
  /// Ends the histories: the residue's half cycles are counted. Then damage() is final;
  /// add() starts new histories whose damage adds on.
  void finish();

  int histories() const { return static_cast<int>(counters_.size()); }
  /// Damage of history i so far (closed cycles; after finish() also the residue).
  double damage(int i) const { return damage_[static_cast<std::size_t>(i)]; }
  /// Reversals held by the largest stack (the memory in use).
  std::size_t max_stack() const;
  const SnCurve& curve() const { return curve_; }

 private:
  std::vector<RainflowCounter> counters_;
  std::vector<double> damage_;
  SnCurve curve_;
  double factor_;
};

}  // namespace seaflex::post
