#include "seaflex/forces/rigid_morison.hpp"

#include <cmath>
#include <numbers>

#include "seaflex/hydro/wet_interval.hpp"
#include "seaflex/math/gauss_legendre.hpp"
#include "seaflex/math/rotation.hpp"

namespace seaflex {

RigidMorison::RigidMorison(std::string name, const RigidBody& body,
                           std::vector<MorisonMember> members,
                           std::shared_ptr<const hydro::Ocean> ocean)
    : RigidBodyLoad(std::move(name), body), members_(std::move(members)), ocean_(std::move(ocean)) {
  for (const auto& mem : members_) {
    if (mem.ca != 0.0) has_added_mass_ = true;
    rules_.push_back(math::gauss_legendre_unit(mem.strips));
  }
}

std::pair<double, double> RigidMorison::wet_interval(const MorisonMember& mem,
                                                     const RigidBodyMotion& m) const {
  const Vec3 A = m.point(mem.a), B = m.point(mem.b);
  // height above the instantaneous surface along the member, s in [0, 1]
  auto above = [&](double s) {
    const Vec3 x = A + s * (B - A);
    return x.z() - ocean_->elevation(x.x(), x.y(), m.t);
  };
  return hydro::wet_interval(above, 1e-10);
}

namespace {

double section_area(const MorisonMember& mem) {
  return 0.25 * std::numbers::pi * mem.diameter * mem.diameter;
}

// calls f(u_body, ds) at the Gauss points of the wet part [s0, s1] of a member: the
// point in body axes and its share of the member's length
template <class F>
void for_each_strip(const MorisonMember& mem, const math::QuadratureRule& rule, double s0,
                    double s1, F&& f) {
  const Vec3 axis_b = mem.b - mem.a;
  const double L = axis_b.norm();
  for (std::size_t g = 0; g < rule.points.size(); ++g)
    f(Vec3(mem.a + (s0 + (s1 - s0) * rule.points[g]) * axis_b), L * (s1 - s0) * rule.weights[g]);
}

}  // namespace

Wrench RigidMorison::wrench(const RigidBodyMotion& m) const {
  Wrench W;
  const double rho = ocean_->rho();
  for (const auto& mem : members_) {
    const auto [s0, s1] = wet_interval(mem, m);
    if (s1 <= s0) continue;
    const Vec3 t = (m.R * (mem.b - mem.a)).normalized();
    const double area = section_area(mem);
    for_each_strip(mem, rules_[&mem - members_.data()], s0, s1, [&](const Vec3& u_body, double ds) {
      const Vec3 x = m.point(u_body);
      const hydro::FluidPoint fl = ocean_->fluid(x, m.t);
      const Vec3 u = fl.velocity - m.point_velocity(u_body);
      const double ua = u.dot(t);
      const Vec3 un = u - ua * t;
      Vec3 f = 0.5 * rho * mem.cd * mem.diameter * un.norm() * un;  // thesis eq. (176), drag
      f += 0.5 * rho * mem.cd_axial * std::numbers::pi * mem.diameter * std::abs(ua) * ua * t;
      const Vec3 an = fl.acceleration - fl.acceleration.dot(t) * t;
      f += rho * mem.cm * area * an;  // thesis eq. (176), inertia
      if (mem.ca != 0.0) {
        // the part of -rho Ca A (I - t t^T) a_s not in the mass matrix: w x (w x rho)
        const Vec3 arm = m.R * u_body;
        const Vec3 centripetal = m.w.cross(m.w.cross(arm));
        f -= rho * mem.ca * area * (centripetal - centripetal.dot(t) * t);
      }
      W.add_at(f * ds, x, m.r);
    });
    if (mem.end_effects) {
      // p_d A on each wet end face, pushing along the inward normal (+t at a, -t at b)
      for (int end = 0; end < 2; ++end) {
        if ((end == 0 && s0 > 0.0) || (end == 1 && s1 < 1.0)) continue;  // end above water
        const Vec3 x = m.point(end == 0 ? mem.a : mem.b);
        const hydro::FluidPoint fl = ocean_->fluid(x, m.t);
        if (!fl.wet) continue;
        W.add_at((end == 0 ? 1.0 : -1.0) * fl.dynamic_pressure * area * t, x, m.r);
      }
    }
  }
  return W;
}

Mat6 RigidMorison::added_mass(const RigidBodyMotion& m) const {
  Mat6 M = Mat6::Zero();
  for (const auto& mem : members_) {
    if (mem.ca == 0.0) continue;
    const auto [s0, s1] = wet_interval(mem, m);
    if (s1 <= s0) continue;
    const Vec3 t = (m.R * (mem.b - mem.a)).normalized();
    const Mat3 P =
        ocean_->rho() * mem.ca * section_area(mem) * (Mat3::Identity() - t * t.transpose());
    for_each_strip(mem, rules_[&mem - members_.data()], s0, s1, [&](const Vec3& u_body, double ds) {
      // a_point = a_cg - skew(arm) alpha + ...: T = [I, -skew(arm)]
      Eigen::Matrix<double, 3, 6> T;
      T.leftCols<3>().setIdentity();
      T.rightCols<3>() = -math::skew(m.R * u_body);
      M += ds * T.transpose() * P * T;
    });
  }
  return M;
}

}  // namespace seaflex
