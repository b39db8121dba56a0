// Attachments on a line (issue 18): clump weights, point buoys and buoyancy modules, each a
// small body fixed to an ANCF beam at an arc length, whose loads are applied at that point
// through the shape functions (thesis eq. 3: r = S(xi) e, so Q = S^T f and the mass enters
// as S^T m S), as OrcaFlex's "clump type" attachments (OrcaFlex manual, Line data:
// Attachments): the module's own external load, never a change of the line's diameter,
// so the wall tension of the pipe stays its own.
// Per attachment of mass m, displaced volume V, drag area A_d (the area its drag
// coefficient refers to) and added-mass coefficient Ca (on V), with the fluid velocity u
// and local acceleration a (hydro/ocean.hpp) and the point's velocity r_dot:
//   weight       m g
//   buoyancy     -rho V g                          when the point is below the surface
//   drag         1/2 rho Cd A_d |u - r_dot| (u - r_dot)           (Morison drag, isotropic)
//   inertia      rho V (1 + Ca) a                    (Froude-Krylov and added-mass parts of
//                                                     the Morison inertia term, DNV-RP-C205
//                                                     (2021) eq. 6.2.2 with Cm = 1 + Ca)
//   mass         (m + rho Ca V) S^T S in the mass matrix (the added mass where wet)
// Smeared attachments (buoyancy modules spread over a range of arc length, the usual
// model of a buoyancy section, e.g. DNV-RP-F204 / OrcaFlex's equivalent line type) apply
// the same terms per unit length, m, V and A_d divided by the range's length per module,
// integrated with 3 Gauss points over each element's part of the range: an ANCF element,
// whose strain is continuous at the nodes, represents a distributed load's linearly
// varying tension exactly, whereas a point load at a node makes the effective tension of
// the elements next to it oscillate (by about a fifth of the point load).
// Weight, buoyancy, drag and inertia are external loads: statics steps them in with the
// load factor, as the line's own weight and buoyancy. The buoyancy and added mass switch
// at the instantaneous surface (no partial immersion of an attachment).
// Tangents: dQ/dv of the drag exact; dQ/dq of the drag and inertia through the fluid
// field by central differences of the position (as forces/morison_beam).
#pragma once

#include <memory>
#include <vector>

#include "seaflex/elements/ancf_beam.hpp"
#include "seaflex/hydro/ocean.hpp"
#include "seaflex/model/force.hpp"

namespace seaflex {

/// One kind of attachment (SI). Every point of a BeamAttachment has these properties.
struct AttachmentProperties {
  double mass = 0.0;       ///< m (kg)
  double volume = 0.0;     ///< V (m^3), displaced
  double cd = 0.0;         ///< drag coefficient
  double drag_area = 0.0;  ///< A_d (m^2)
  double ca = 0.0;         ///< added-mass coefficient on V
};

class BeamAttachment : public Force {
 public:
  /// Attachments with properties p at the reference arc lengths (m from the beam's start,
  /// each in [0, beam.length()]); gravity g (m/s^2, world); ocean may be null (in air:
  /// weight and mass only).
  BeamAttachment(std::string name, const AncfBeam& beam, std::vector<double> arc_lengths,
                 AttachmentProperties p, Vec3 g, std::shared_ptr<const hydro::Ocean> ocean);
  /// count attachments with properties p smeared evenly over [from, to] (m of arc length).
  static std::unique_ptr<BeamAttachment> smeared(std::string name, const AncfBeam& beam,
                                                 double from, double to, int count,
                                                 AttachmentProperties p, Vec3 g,
                                                 std::shared_ptr<const hydro::Ocean> ocean);

  void declare_blocks(math::SparseBlockAssembler& matrix) override;
  void assemble(const State& state, double load_factor, AssemblyTarget& target) const override;
  double potential_energy(const State&) const override { return 0.0; }
  bool constant_mass() const override;
  /// <name>.count (-), <name>.net_weight (N, the weight less the buoyancy of all of them
  /// at the current state, positive down).
  void add_channels(ChannelList& channels) const override;

  const AncfBeam& beam() const { return beam_; }
  /// The attachments' arc lengths (m); for smeared ones the centres of their shares.
  const std::vector<double>& arc_lengths() const { return arc_lengths_; }
  /// The quadrature of the loads: arc length (m) and the share of one attachment's
  /// properties (1 for a discrete attachment).
  std::vector<std::pair<double, double>> load_points() const;
  const AttachmentProperties& properties() const { return p_; }
  /// The vertical load (N, positive down) of one attachment fully submerged in still water
  /// (or in air without an ocean): m |g| - rho |g| V.
  double submerged_weight() const;

 private:
  struct Point {
    int element = 0;
    double xi = 0.0;
    double share = 1.0;  // of one attachment's m, V and A_d
    math::BlockId block{};
  };
  // the load (N) of one whole attachment at r with velocity rdot at time t; df_dv its
  // velocity derivative
  Vec3 load(const Vec3& r, const Vec3& rdot, double t, bool* wet, Mat3* df_dv) const;

  const AncfBeam& beam_;
  std::vector<double> arc_lengths_;
  std::vector<Point> points_;
  AttachmentProperties p_;
  Vec3 g_;
  std::shared_ptr<const hydro::Ocean> ocean_;
};

}  // namespace seaflex
