// Seabed contact of listed points of a rigid body (the corners of a clump weight, an anchor
// or a hull): the point-wise counterpart of forces/seabed_contact.hpp, with the same laws.
// At a body-fixed point u (body axes, from the centre of gravity), x = r + A(p) u, with
// velocity x' = J v (J = dx/dq, model/marker.hpp), the seabed's outward normal n and the
// penetration d below its local tangent plane (hydro/seabed.hpp):
//   normal    F = k d + c d',  d' = -n . x',  f_n = max(F, 0) n   (no suction)
//             k (N/m) per point: a stiffness, or the seabed's stiffness per unit contact
//             area times the point's contact area (OrcaFlex's 3D/6D buoys take a contact
//             area times the seabed's normal stiffness in the same way);
//             c = 2 zeta k sqrt(m / K), K = sum of k over the body's points: the points
//             share the damping 2 zeta sqrt(K m) of the body's mass m on all its springs
//             (a fraction zeta of critical for the body's heave on the seabed) in
//             proportion to their stiffness. Added mass is not in m.
//   friction  the regularized Coulomb law of the beam contact (MoorDyn v2, Hall 2020), with
//             one isotropic coefficient mu (a point has no line axis):
//               f_f = -mu max(F, 0) P x' / sqrt(|P x'|^2 + v_s^2),  P = I - n n^T.
//             Sliding (|P x'| >> v_s) gives mu F against the motion along the seabed; near
//             rest it is a viscous damper mu F / v_s, smooth for Newton. Without memory it
//             cannot stick: a body held below the friction limit creeps at
//             v_s r / sqrt(1 - r^2), r = tangential load / (mu F), and statics (zero
//             velocity) feels no friction.
// Generalized force Q = J^T f per point. Exact tangents:
//   dQ/dq = J^T (df/dx J + df/dx' J_v) + d(J^T f)/dq|_f,   dQ/dv = J^T df/dx' J,
//   df/dx = (n - mu P x'/s) dF/dx,  dF/dx = -k n^T,
//   df/dx' = (n - mu P x'/s) dF/dx' - mu F (P/s - P x' (P x')^T / s^3),  dF/dx' = -c n^T,
// s = sqrt(|P x'|^2 + v_s^2), J_v = d(J v)/dq; exact on flat and sloped seabeds; on a grid
// the turning of the normal across a cell is left out, as in the beam contact.
// The contact is an internal force: statics does not scale it with the load factor.
#pragma once

#include <memory>
#include <vector>

#include "seaflex/elements/rigid_body.hpp"
#include "seaflex/hydro/seabed.hpp"
#include "seaflex/model/force.hpp"

namespace seaflex {

/// One point of a rigid body that touches the seabed.
struct SeabedContactPoint {
  Vec3 position = Vec3::Zero();  ///< u, body axes from the centre of gravity (m)
  double stiffness = 0.0;        ///< k (N/m), > 0
};

/// The laws shared by the points of one body (SI).
struct PointContactProperties {
  double damping = 0.0;         ///< zeta, fraction of critical (see the file header)
  double friction = 0.0;        ///< mu, isotropic Coulomb coefficient
  double slip_velocity = 0.01;  ///< v_s (m/s), the regularization of Coulomb friction
};

class RigidBodySeabedContact : public Force {
 public:
  /// points: at least one, each with k > 0 (std::invalid_argument otherwise).
  RigidBodySeabedContact(std::string name, const RigidBody& body,
                         std::shared_ptr<const hydro::Seabed> seabed,
                         std::vector<SeabedContactPoint> points, PointContactProperties properties);

  void declare_blocks(math::SparseBlockAssembler& matrix) override;
  void assemble(const State& state, double load_factor, AssemblyTarget& target) const override;
  /// The springs' energy, sum of k d^2 / 2 over the points below the seabed.
  double potential_energy(const State& state) const override;
  /// <name>.force (N, the magnitude of the resultant normal contact force),
  /// <name>.friction (N, the magnitude of the resultant friction force) and, per point i
  /// (in the order given), <name>.p<i>.force (N, its normal force max(F, 0)).
  void add_channels(ChannelList& channels) const override;

  /// Normal and friction force at point i (N, world axes).
  struct PointForce {
    Vec3 normal = Vec3::Zero();    ///< f_n
    Vec3 friction = Vec3::Zero();  ///< f_f
    double penetration = 0.0;      ///< d (m), positive below the seabed
  };
  PointForce point_force(const State& state, int i) const;
  int num_points() const { return static_cast<int>(points_.size()); }
  const RigidBody& body() const { return body_; }
  /// c of point i (N s/m).
  double damping_coefficient(int i) const { return c_[i]; }
  const std::vector<SeabedContactPoint>& points() const { return points_; }
  const PointContactProperties& properties() const { return properties_; }

 private:
  struct Eval {
    PointForce f;
    Mat3 df_dx = Mat3::Zero();
    Mat3 df_dxd = Mat3::Zero();
  };
  Eval evaluate(int i, const Vec3& x, const Vec3& xd, bool derivatives) const;

  const RigidBody& body_;
  std::shared_ptr<const hydro::Seabed> seabed_;
  std::vector<SeabedContactPoint> points_;
  std::vector<RigidBodyMarker> markers_;
  std::vector<double> c_;
  PointContactProperties properties_;
  math::BlockId block_ = -1;
};

}  // namespace seaflex
