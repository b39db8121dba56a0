#include "seaflex/forces/hydro_matrices.hpp"

#include "seaflex/math/rotation.hpp"

namespace seaflex {

namespace {
Mat6 block_rotation(const Mat3& R) {
  Mat6 Q = Mat6::Zero();
  Q.topLeftCorner<3, 3>() = R;
  Q.bottomRightCorner<3, 3>() = R;
  return Q;
}
}  // namespace

HydroMatrices::HydroMatrices(std::string name, const RigidBody& body, HydroMatrixSet set)
    : RigidBodyLoad(std::move(name), body), set_(std::move(set)) {}

Mat6 HydroMatrices::added_mass(const RigidBodyMotion& m) const {
  // A in world axes at the point, moved to the CG: T^T A_w T, T = [I -skew(R u); 0 I]
  const Mat6 Q = block_rotation(m.R);
  const Mat6 T = point_transform(m.R * set_.reference);
  return T.transpose() * (Q * set_.added_mass * Q.transpose()) * T;
}

Wrench HydroMatrices::wrench(const RigidBodyMotion& m) const {
  Wrench W;
  const Vec3& u = set_.reference;
  const Vec6 v = body_velocity_at(m, u);
  Vec6 f = -set_.linear_damping * v;
  f -= set_.quadratic_damping * v.cwiseAbs().cwiseProduct(v);
  if (!set_.added_mass.isZero(0.0)) {
    // -A (a_u, alpha) minus what the mass matrix holds: the point's centripetal acceleration
    const Vec3 arm = m.R * u;
    Vec6 bias = Vec6::Zero();
    bias.head<3>() = m.R.transpose() * m.w.cross(m.w.cross(arm));
    f -= set_.added_mass * bias;
  }
  add_body_wrench(W, m, u, f);
  if (set_.has_stiffness) {
    // xi in the axes of the heading at rest
    const Mat3 H = math::rotation_from_roll_pitch_yaw(0.0, 0.0, set_.heading);
    const Mat3 R_rel = H.transpose() * m.R;
    const Vec3 angles = math::roll_pitch_yaw_from_rotation(R_rel);
    Vec6 xi;
    xi.head<3>() = H.transpose() * (m.point(u) - set_.still_water_position);
    xi.tail<3>() = angles;
    Vec6 fh = -set_.stiffness * xi;
    fh[2] += set_.rho * set_.g * set_.displaced_volume;
    const Vec3 force = H * fh.head<3>();
    W.force += force;
    W.moment += H * fh.tail<3>() + (m.R * u).cross(force);
  }
  return W;
}

}  // namespace seaflex
