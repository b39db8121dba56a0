#include "seaflex/forces/seabed_contact.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "seaflex/hydro/wet_interval.hpp"

namespace seaflex {

namespace {
using ancf_cable::add_shape_product;
using ancf_cable::Mat12;
using ancf_cable::Vec12;
using ancf_cable::Vec4;
}  // namespace

SeabedContact::SeabedContact(std::string name, const AncfBeam& beam,
                             std::shared_ptr<const hydro::Seabed> seabed,
                             SeabedContactProperties properties, double width,
                             double mass_per_length)
    : SeabedContact(std::move(name), beam, std::move(seabed), properties,
                    std::vector<double>(beam.sections().size(), width),
                    std::vector<double>(beam.sections().size(), mass_per_length)) {}

SeabedContact::SeabedContact(std::string name, const AncfBeam& beam,
                             std::shared_ptr<const hydro::Seabed> seabed,
                             SeabedContactProperties properties, const std::vector<double>& widths,
                             const std::vector<double>& masses_per_length)
    : Force(std::move(name)),
      beam_(beam),
      seabed_(std::move(seabed)),
      properties_(properties),
      rule_(math::gauss_legendre_unit(properties.gauss_points)) {
  if (widths.size() != beam.sections().size() || masses_per_length.size() != widths.size())
    throw std::invalid_argument("SeabedContact: one width and mass per beam section needed");
  for (std::size_t i = 0; i < widths.size(); ++i) {
    k_.push_back(properties_.normal_stiffness * widths[i]);
    c_.push_back(2.0 * properties_.damping * std::sqrt(k_.back() * masses_per_length[i]));
  }
}

void SeabedContact::declare_blocks(math::SparseBlockAssembler& matrix) {
  blocks_ = beam_.declare_element_blocks(matrix);
}

std::pair<double, double> SeabedContact::contact_interval(const State& state, int k) const {
  const Vec12 e = beam_.element_coordinates(state.q, k);
  const double l = beam_.element_length(k);
  // the height above the seabed's local tangent plane, negative in contact
  auto above = [&](double xi) {
    const Vec3 r = ancf_cable::as_nodes(e) * ancf_cable::shape(xi, l);  // thesis eq. (3)
    return -seabed_->at(r.x(), r.y()).penetration(r);
  };
  return hydro::wet_interval(above);
}

SeabedContact::PointForce SeabedContact::point_force(int section, const Vec3& r, const Vec3& rp,
                                                     const Vec3& rdot, bool derivatives) const {
  PointForce out;
  const double k = k_[section], c = c_[section];
  const hydro::SeabedPoint sp = seabed_->at(r.x(), r.y());
  const Vec3 n = sp.normal();
  const double d = sp.penetration(r);
  const double F = k * d - c * n.dot(rdot);  // k d + c d_dot, d_dot = -n . r_dot
  // no contact, or separating: no suction. At exactly d = 0 (a line laid on the seabed in
  // its first guess) the point is in contact with zero force: its tangent is the contact's
  // (the one-sided derivative), so the first Newton step of statics is held by the seabed
  // instead of letting the laid part fall freely (61 iterations instead of 8 for a
  // catenary chain laid at the seabed's height)
  if (!(d >= 0.0) || !(F >= 0.0)) return out;
  out.normal = F * n;
  const SeabedContactProperties& p = properties_;
  // friction directions: the axis projected on the seabed, and across it
  const Mat3 P = Mat3::Identity() - n * n.transpose();
  const double stretch = rp.norm();
  const Vec3 t = rp / stretch;
  const Vec3 a_raw = P * t;
  const double a_norm = a_raw.norm();
  const bool axis_on_seabed = a_norm > 1e-9;
  const Vec3 a = axis_on_seabed ? Vec3(a_raw / a_norm) : Vec3::Zero();
  // M = mu_l P + (mu_a - mu_l) a a^T  (a, b = n x a and n orthonormal)
  const Mat3 M =
      p.friction_lateral * P + (p.friction_axial - p.friction_lateral) * a * a.transpose();
  const bool friction = p.friction_axial > 0.0 || p.friction_lateral > 0.0;
  const Vec3 vt = P * rdot;
  const double s = std::sqrt(vt.squaredNorm() + p.slip_velocity * p.slip_velocity);
  const Vec3 Mv = M * rdot;
  if (friction) out.friction = -F * Mv / s;
  if (!derivatives) return out;
  // dF/dr = -k n^T (the normal of a plane is constant), dF/dv = -c n^T
  const Eigen::RowVector3d dF_dr = -k * n.transpose();
  const Eigen::RowVector3d dF_dv = -c * n.transpose();
  out.df_dr = n * dF_dr;
  out.df_dv = n * dF_dv;
  if (!friction) return out;
  out.df_dr += -(Mv / s) * dF_dr;
  out.df_dv += -F * (M / s - Mv * vt.transpose() / (s * s * s)) - (Mv / s) * dF_dv;
  if (axis_on_seabed && p.friction_axial != p.friction_lateral) {
    // d(a (a . v))/dr' = ((a . v) I + a v^T) da/dr',
    // da/dr' = (I - a a^T)/|P t| P (I - t t^T)/|r'|
    const Mat3 da_drp = (Mat3::Identity() - a * a.transpose()) / a_norm * P *
                        (Mat3::Identity() - t * t.transpose()) / stretch;
    out.df_drp = -(F / s) * (p.friction_axial - p.friction_lateral) *
                 (a.dot(rdot) * Mat3::Identity() + a * rdot.transpose()) * da_drp;
  }
  return out;
}

void SeabedContact::assemble(const State& state, double, AssemblyTarget& target) const {
  const MatrixScales& s = target.scales;
  const bool want_matrix = target.matrix != nullptr && (s.kq != 0.0 || s.kv != 0.0);
  // the beam's even, then odd elements; in parallel within each (core/parallel.hpp)
  for_each_colored(beam_.coloring(), [&](int k) {
    const auto [xi0, xi1] = contact_interval(state, k);
    if (!(xi1 > xi0)) return;
    Mat12 K;
    if (want_matrix) K.setZero();
    const double l = beam_.element_length(k);
    const Vec12 e = beam_.element_coordinates(state.q, k);
    const Vec12 ed = state.v.segment<12>(beam_.node_index(k));
    const auto E = ancf_cable::as_nodes(e);
    const auto Ed = ancf_cable::as_nodes(ed);
    // one end of the contact inside the element (a touchdown point)
    const bool lower = xi0 > 0.0;
    const bool track_end = want_matrix && s.kq != 0.0 && (xi0 > 0.0 || xi1 < 1.0);
    Vec12 dQ_dxc = Vec12::Zero();
    for (std::size_t g = 0; g < rule_.points.size(); ++g) {
      const double xi = xi0 + (xi1 - xi0) * rule_.points[g];
      const double dx = l * (xi1 - xi0) * rule_.weights[g];
      const Vec4 sh = ancf_cable::shape(xi, l);
      const Vec4 shx = ancf_cable::shape_dx(xi, l);
      const PointForce pf =
          point_force(beam_.section_index(k), E * sh, E * shx, Ed * sh, want_matrix);
      if (target.forces) {
        auto Q = target.forces->segment<12>(beam_.node_index(k));
        const Vec3 f = pf.normal + pf.friction;
        for (int i = 0; i < 4; ++i) Q.segment<3>(3 * i) += (dx * sh[i]) * f;  // Q = int S^T f dx
      }
      if (!want_matrix) continue;
      if (track_end) {
        // d/dx_c of (xi1 - xi0) l w_g S(xi_g)^T f(xi_g), xi_g = xi0 + (xi1 - xi0) p_g
        const double dlen = lower ? -1.0 : 1.0;
        const double dxg = lower ? 1.0 - rule_.points[g] : rule_.points[g];
        const Vec4 shxx = ancf_cable::shape_dxx(xi, l);
        const Vec3 f = pf.normal + pf.friction;
        const Vec3 df_dxi =
            l * (pf.df_dr * (E * shx) + pf.df_drp * (E * shxx) + pf.df_dv * (Ed * shx));
        for (int i = 0; i < 4; ++i)
          dQ_dxc.segment<3>(3 * i) +=
              l * rule_.weights[g] *
              (dlen * sh[i] * f + (xi1 - xi0) * dxg * (l * shx[i] * f + sh[i] * df_dxi));
      }
      if (s.kq != 0.0) {
        add_shape_product(K, sh, sh, pf.df_dr, -s.kq * dx);
        add_shape_product(K, sh, shx, pf.df_drp, -s.kq * dx);
      }
      if (s.kv != 0.0) add_shape_product(K, sh, sh, pf.df_dv, -s.kv * dx);
    }
    // a touchdown point x_c inside the element moves with e, and the Gauss points with it:
    // dQ/de += dQ/dx_c dx_c/de, with dx_c/de_j = -S_j(x_c) n^T / (l n . r'(x_c)) from
    // d(x_c) = 0 on a plane; so the matrix is the exact derivative of the discrete Q
    if (track_end) {
      const double xc = lower ? xi0 : xi1;
      const Vec4 sh = ancf_cable::shape(xc, l);
      const Vec3 r = E * sh, rp = E * ancf_cable::shape_dx(xc, l);
      const Vec3 n = seabed_->at(r.x(), r.y()).normal();
      const double nrp = n.dot(rp);
      if (std::abs(nrp) > 1e-12 * rp.norm()) {
        Vec12 dxc_de;
        for (int j = 0; j < 4; ++j) dxc_de.segment<3>(3 * j) = -sh[j] * n / (l * nrp);
        K.noalias() -= s.kq * dQ_dxc * dxc_de.transpose();
      }
    }
    if (want_matrix) target.matrix->add(blocks_[k], K);
  });
}

double SeabedContact::potential_energy(const State& state) const {
  // the normal spring's energy, int k d^2 / 2 dx (damping and friction dissipate)
  double energy = 0.0;
  for (int k = 0; k < beam_.num_elements(); ++k) {
    const auto [xi0, xi1] = contact_interval(state, k);
    if (!(xi1 > xi0)) continue;
    const double l = beam_.element_length(k);
    const Vec12 e = beam_.element_coordinates(state.q, k);
    const auto E = ancf_cable::as_nodes(e);
    for (std::size_t g = 0; g < rule_.points.size(); ++g) {
      const double xi = xi0 + (xi1 - xi0) * rule_.points[g];
      const Vec3 r = E * ancf_cable::shape(xi, l);
      const double d = seabed_->at(r.x(), r.y()).penetration(r);
      if (d > 0.0)
        energy += 0.5 * k_[beam_.section_index(k)] * d * d * l * (xi1 - xi0) * rule_.weights[g];
    }
  }
  return energy;
}

SeabedContact::Totals SeabedContact::totals(const State& state) const {
  Totals out;
  for (int k = 0; k < beam_.num_elements(); ++k) {
    const auto [xi0, xi1] = contact_interval(state, k);
    if (!(xi1 > xi0)) continue;
    const double l = beam_.element_length(k);
    out.laid_length += l * (xi1 - xi0);
    const Vec12 e = beam_.element_coordinates(state.q, k);
    const Vec12 ed = state.v.segment<12>(beam_.node_index(k));
    const auto E = ancf_cable::as_nodes(e);
    const auto Ed = ancf_cable::as_nodes(ed);
    for (std::size_t g = 0; g < rule_.points.size(); ++g) {
      const double xi = xi0 + (xi1 - xi0) * rule_.points[g];
      const double dx = l * (xi1 - xi0) * rule_.weights[g];
      const Vec4 sh = ancf_cable::shape(xi, l);
      const PointForce pf = point_force(beam_.section_index(k), E * sh,
                                        E * ancf_cable::shape_dx(xi, l), Ed * sh, false);
      out.normal += dx * pf.normal;
      out.friction += dx * pf.friction;
    }
  }
  return out;
}

double SeabedContact::touchdown(const State& state) const {
  // the contact that reaches the line's start (an anchor end) ends at the touchdown point;
  // otherwise the contact that reaches the end does; otherwise the first contact from the
  // start
  const int n = beam_.num_elements();
  auto arc = [&](int k, double xi) {
    return beam_.node_arc_length(k) + xi * beam_.element_length(k);
  };
  const auto first = contact_interval(state, 0);
  if (first.second > first.first && first.first == 0.0) {
    for (int k = 0; k < n; ++k) {
      const auto [xi0, xi1] = contact_interval(state, k);
      if (!(xi1 > xi0) || xi0 > 0.0) return k == 0 ? arc(0, 0.0) : arc(k - 1, 1.0);
      if (xi1 < 1.0) return arc(k, xi1);
    }
    return beam_.length();
  }
  const auto last = contact_interval(state, n - 1);
  if (last.second > last.first && last.second == 1.0) {
    for (int k = n - 1; k >= 0; --k) {
      const auto [xi0, xi1] = contact_interval(state, k);
      if (!(xi1 > xi0) || xi1 < 1.0) return k == n - 1 ? beam_.length() : arc(k + 1, 0.0);
      if (xi0 > 0.0) return arc(k, xi0);
    }
    return 0.0;
  }
  for (int k = 0; k < n; ++k) {
    const auto [xi0, xi1] = contact_interval(state, k);
    if (xi1 > xi0) return arc(k, xi0);
  }
  return std::numeric_limits<double>::quiet_NaN();
}

void SeabedContact::add_channels(ChannelList& channels) const {
  channels.push_back(
      {name() + ".force", [this](const State& s) { return totals(s).normal.norm(); }});
  channels.push_back(
      {name() + ".friction", [this](const State& s) { return totals(s).friction.norm(); }});
  channels.push_back(
      {name() + ".laid_length", [this](const State& s) { return totals(s).laid_length; }});
  channels.push_back({name() + ".touchdown", [this](const State& s) { return touchdown(s); }});
}

}  // namespace seaflex
