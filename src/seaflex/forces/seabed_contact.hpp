// Seabed contact of an ANCF beam, along its length (Gauss points of the part of each
// element below the seabed, whose ends are found by false position as for the wet part
// of a Morison element, so that a touchdown inside an element is integrated exactly).
// Per unit reference length at a point r with velocity r_dot and axis t = r'/|r'|, with
// the seabed's outward normal n and the penetration d (hydro/seabed.hpp):
//   normal    F = k d + c d_dot,  d_dot = -n . r_dot,  f_n = max(F, 0) n
//             k = k_a w (k_a: stiffness per unit contact area, N/m/m^2; w: the contact
//             width, the line's outer diameter: OrcaFlex's and MoorDyn's convention);
//             c = 2 zeta sqrt(k m) (zeta: fraction of critical damping of the line's mass
//             per length m on the spring k), so the contact never pulls (no suction).
//   friction  a regularized (viscous-limited) Coulomb law with separate axial and lateral
//             coefficients, the seabed-friction model of MoorDyn (Hall 2020, MoorDyn v2
//             theory: "friction with a linear damping region below a slip velocity"):
//               f_f = -max(F, 0) M r_dot / sqrt(|P r_dot|^2 + v_s^2),
//               M = mu_a a a^T + mu_l b b^T,  P = I - n n^T,
//             a the line's axis projected on the seabed (unit), b = n x a, v_s the slip
//             velocity. Sliding (|P r_dot| >> v_s) gives the Coulomb force mu F along
//             each direction; near rest the law is a viscous damper mu F / v_s, which is
//             smooth, so Newton converges through stick-slip. It is a function of the state
//             (no memory, restart files hold it): a line held by a steady force below the
//             friction limit creeps at a speed below v_s times force/limit instead of
//             sticking, and static equilibrium has no friction (the velocity is zero).
// Tangents: the exact derivatives of the discrete Q on flat and sloped seabeds, the motion
// of a touchdown point inside an element (and of the Gauss points with it) included; on a
// grid the turning of the normal across a cell (the bilinear cross-derivative) is left
// out of the tangent.
// The contact is an internal force: statics does not scale it with the load factor.
#pragma once

#include <memory>
#include <vector>

#include "seaflex/elements/ancf_beam.hpp"
#include "seaflex/hydro/seabed.hpp"
#include "seaflex/math/gauss_legendre.hpp"
#include "seaflex/model/force.hpp"

namespace seaflex {

/// Contact properties of the seabed (SI).
struct SeabedContactProperties {
  double normal_stiffness = 0.0;  ///< k_a, per unit contact area (N/m/m^2 = N/m^3)
  double damping = 0.0;           ///< zeta, fraction of critical damping
  double friction_axial = 0.0;    ///< mu_a along the line's axis
  double friction_lateral = 0.0;  ///< mu_l across it
  double slip_velocity = 0.01;    ///< v_s (m/s), the regularization of Coulomb friction
  int gauss_points = 5;           ///< per element, on the part in contact
};

class SeabedContact : public Force {
 public:
  /// width: the contact width (m, the line's outer diameter); mass_per_length (kg/m) for
  /// the damping.
  SeabedContact(std::string name, const AncfBeam& beam, std::shared_ptr<const hydro::Seabed> seabed,
                SeabedContactProperties properties, double width, double mass_per_length);
  /// A line made of sections: widths[i] and masses_per_length[i] for the beam's section i.
  SeabedContact(std::string name, const AncfBeam& beam, std::shared_ptr<const hydro::Seabed> seabed,
                SeabedContactProperties properties, const std::vector<double>& widths,
                const std::vector<double>& masses_per_length);

  void declare_blocks(math::SparseBlockAssembler& matrix) override;
  void assemble(const State& state, double load_factor, AssemblyTarget& target) const override;
  double potential_energy(const State& state) const override;
  /// <name>.force (N, the resultant of the normal contact force), <name>.laid_length (m,
  /// the reference length in contact), <name>.touchdown (m, arc length from the line's
  /// start of the end of the contact nearest to the line's free part; NaN without
  /// contact), <name>.friction (N, the magnitude of the resultant friction force).
  void add_channels(ChannelList& channels) const override;

  /// Part [xi0, xi1] of element k below the seabed; xi1 <= xi0 when none.
  std::pair<double, double> contact_interval(const State& state, int k) const;
  /// Resultant normal and friction forces (N), and the reference length in contact (m).
  struct Totals {
    Vec3 normal = Vec3::Zero();
    Vec3 friction = Vec3::Zero();
    double laid_length = 0.0;
  };
  Totals totals(const State& state) const;
  /// Arc length of the touchdown point (m): see add_channels.
  double touchdown(const State& state) const;

  const SeabedContactProperties& properties() const { return properties_; }
  /// Normal stiffness per unit length (N/m/m) on the beam's section i.
  double stiffness_per_length(int section = 0) const { return k_[section]; }

 private:
  struct PointForce {
    Vec3 normal = Vec3::Zero();    // f_n
    Vec3 friction = Vec3::Zero();  // f_f
    Mat3 df_dr = Mat3::Zero();
    Mat3 df_drp = Mat3::Zero();
    Mat3 df_dv = Mat3::Zero();
  };
  PointForce point_force(int section, const Vec3& r, const Vec3& rp, const Vec3& rdot,
                         bool derivatives) const;

  const AncfBeam& beam_;
  std::shared_ptr<const hydro::Seabed> seabed_;
  SeabedContactProperties properties_;
  std::vector<double> k_;  // per beam section, per unit length (N/m/m)
  std::vector<double> c_;  // per beam section, per unit length (N s/m/m)
  math::QuadratureRule rule_;
  std::vector<math::BlockId> blocks_;
};

}  // namespace seaflex
