#include "seaflex/forces/morison_beam.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "seaflex/hydro/wet_interval.hpp"

namespace seaflex {

namespace {
using ancf_cable::add_shape_product;
using ancf_cable::Mat12;
using ancf_cable::Vec12;
using ancf_cable::Vec4;
}  // namespace

MorisonBeam::MorisonBeam(std::string name, const AncfBeam& beam,
                         MorisonBeamCoefficients coefficients,
                         std::shared_ptr<const hydro::Ocean> ocean)
    : MorisonBeam(std::move(name), beam,
                  std::vector<MorisonBeamCoefficients>(beam.sections().size(), coefficients),
                  std::move(ocean)) {}

MorisonBeam::MorisonBeam(std::string name, const AncfBeam& beam,
                         std::vector<MorisonBeamCoefficients> coefficients,
                         std::shared_ptr<const hydro::Ocean> ocean)
    : Force(std::move(name)),
      beam_(beam),
      coefficients_(std::move(coefficients)),
      ocean_(std::move(ocean)) {
  if (coefficients_.size() != beam_.sections().size())
    throw std::invalid_argument("MorisonBeam: one set of coefficients per beam section needed");
  const double rho = ocean_->rho();
  for (const MorisonBeamCoefficients& c : coefficients_) {
    const double D = c.diameter;
    const double area = 0.25 * std::numbers::pi * D * D;
    PointConstants k;
    k.drag = 0.5 * rho * c.cd * D;  // thesis eq. (176)
    k.drag_axial = 0.5 * rho * c.cd_axial * std::numbers::pi * D;
    k.inertia = rho * c.cm * area;
    k.inertia_axial = rho * c.cm_axial * area;
    k.buoyancy = c.buoyancy ? rho * ocean_->g() * area : 0.0;
    constants_.push_back(k);
  }
  rule_ = math::gauss_legendre_unit(coefficients_.front().gauss_points);
  reuse_ = coefficients_.front().fluid_reuse;
  if (!(reuse_ >= 0.0)) throw std::invalid_argument("MorisonBeam: fluid_reuse must be >= 0");
  if (reuse_ > 0.0)
    kept_.resize(static_cast<std::size_t>(beam_.num_elements()) * rule_.points.size());
  for (int k = 0; k < beam_.num_elements(); ++k)
    for (const double xi : rule_.points) {
      wet_shape_.push_back(ancf_cable::shape(xi, beam_.element_length(k)));
      wet_shape_dx_.push_back(ancf_cable::shape_dx(xi, beam_.element_length(k)));
    }
}

hydro::FluidPoint MorisonBeam::fluid_at(int k, std::size_t g, const Vec3& r, double t,
                                        bool fresh) const {
  // the beam's load uses the water's velocity and acceleration, not its dynamic pressure
  if (reuse_ <= 0.0) return ocean_->fluid(r, t, false);
  KeptFluid& kept = kept_[static_cast<std::size_t>(k) * rule_.points.size() + g];
  if (!fresh && kept.t == t && (r - kept.r).lpNorm<Eigen::Infinity>() <= reuse_) return kept.fluid;
  kept.t = t;
  kept.r = r;
  kept.fluid = ocean_->fluid(r, t, false);
  return kept.fluid;
}

bool MorisonBeam::constant_mass() const {
  for (const auto& c : coefficients_)
    if (c.ca != 0.0 || c.ca_axial != 0.0) return false;
  return true;
}

void MorisonBeam::declare_blocks(math::SparseBlockAssembler& matrix) {
  blocks_ = beam_.declare_element_blocks(matrix);
}

std::pair<double, double> MorisonBeam::wet_interval(const State& state, int k) const {
  const Vec12 e = beam_.element_coordinates(state.q, k);
  // both ends below the deepest trough the sea can have: wholly wet, as hydro::wet_interval
  // finds from the two ends, without asking the sea for the elevation (the riser's deep part)
  const double deepest = -ocean_->waves().elevation_bound();
  if (e[2] < deepest && e[8] < deepest) return {0.0, 1.0};
  const double l = beam_.element_length(k);
  auto above = [&](double xi) {
    const Vec3 r = ancf_cable::as_nodes(e) * ancf_cable::shape(xi, l);  // thesis eq. (3)
    return r.z() - ocean_->elevation(r.x(), r.y(), state.t);
  };
  return hydro::wet_interval(above);
}

MorisonBeam::PointLoad MorisonBeam::point_load(const PointConstants& c, const hydro::FluidPoint& fl,
                                               const Vec3& rp, const Vec3& rdot, double load_factor,
                                               bool derivatives, bool with_buoyancy) const {
  PointLoad out;
  const double stretch = rp.norm();
  const Vec3 tt = rp / stretch;
  out.t = tt;
  const Vec3 u = fl.velocity - rdot;
  const double ua = tt.dot(u);
  const Vec3 un = u - ua * tt;
  const double unn = un.norm();
  const double cd = c.drag, cax = c.drag_axial, ci = c.inertia, cia = c.inertia_axial;
  const double aa = tt.dot(fl.acceleration);
  const Vec3 an = fl.acceleration - aa * tt;
  out.f = cd * unn * un + cax * std::abs(ua) * ua * tt + ci * an + cia * aa * tt;
  if (with_buoyancy) out.f.z() += c.buoyancy;
  out.f *= load_factor;  // an external load: statics steps it in with the load factor
  if (!derivatives) return out;
  // d f / d u_n of the drag, and the derivatives through u = U - r_dot and t = r'/|r'|
  const Mat3 P = Mat3::Identity() - tt * tt.transpose();
  Mat3 Dn = cd * unn * Mat3::Identity();
  if (unn > 0.0) Dn += (cd / unn) * un * un.transpose();
  const Mat3 Da = cax * 2.0 * std::abs(ua) * tt * tt.transpose();
  out.df_dv = -(Dn * P + Da);
  const Mat3 dt_drp = P / stretch;
  const Mat3 dun_dt = -(tt * u.transpose() + ua * Mat3::Identity());
  const Mat3 dfa_dt =
      cax * (2.0 * std::abs(ua) * tt * u.transpose() + std::abs(ua) * ua * Mat3::Identity());
  // d/dt [ci (a - (t.a) t) + cia (t.a) t] = (cia - ci) (t a^T + (t.a) I)
  const Mat3 dfi_dt = (cia - ci) * (tt * fl.acceleration.transpose() + aa * Mat3::Identity());
  out.df_drp = load_factor * (Dn * dun_dt + dfa_dt + dfi_dt) * dt_drp;
  out.df_dv *= load_factor;
  return out;
}

void MorisonBeam::assemble(const State& state, double load_factor, AssemblyTarget& target) const {
  const MatrixScales& s = target.scales;
  const bool want_matrix = target.matrix != nullptr && s.any();
  // the beam's even, then odd elements; in parallel within each (core/parallel.hpp)
  for_each_colored(beam_.coloring(), [&](int k) {
    const MorisonBeamCoefficients& c = coefficients_[beam_.section_index(k)];
    const PointConstants& pc = constants_[beam_.section_index(k)];
    const double area_i = 0.25 * std::numbers::pi * c.internal_diameter * c.internal_diameter;
    const double m_int = c.internal_density * area_i;  // contents' mass per length
    const double area = 0.25 * std::numbers::pi * c.diameter * c.diameter;
    const double ca_mass = ocean_->rho() * c.ca * area;
    const double ca_axial_mass = ocean_->rho() * c.ca_axial * area;
    const bool added_mass = ca_mass != 0.0 || ca_axial_mass != 0.0;
    // product mode with the mass alone (M(q) a for generalized-alpha): the added mass and the
    // contents' mass times the vector, point by point, without the 12 x 12 block
    const bool product = want_matrix && target.matrix->in_product() && s.kq == 0.0 && s.kv == 0.0;
    Vec12 y = Vec12::Zero();
    Mat12 K;
    const double l = beam_.element_length(k);
    const Vec12 e = beam_.element_coordinates(state.q, k);
    const Vec12 ed = state.v.segment<12>(beam_.node_index(k));
    const auto E = ancf_cable::as_nodes(e);
    const auto Ed = ancf_cable::as_nodes(ed);
    const Vec12 x = product ? Vec12(target.matrix->product_x().segment<12>(beam_.node_index(k)))
                            : Vec12::Zero();
    if (want_matrix && !product) K.setZero();
    // contents: weight and mass over the whole element
    if (m_int > 0.0) {
      if (target.forces)
        target.forces->segment<12>(beam_.node_index(k)) +=
            ancf_cable::uniform_load(Vec3(0, 0, -load_factor * m_int * ocean_->g()), l);
      if (product && s.km != 0.0)
        y += s.km * ancf_cable::mass_matrix(m_int, l) * x;
      else if (want_matrix && s.km != 0.0)
        K += s.km * ancf_cable::mass_matrix(m_int, l);
    }
    const auto [xi0, xi1] = wet_interval(state, k);
    const bool wholly_wet = xi0 == 0.0 && xi1 == 1.0;
    for (std::size_t g = 0; xi1 > xi0 && g < rule_.points.size(); ++g) {
      const double xi = xi0 + (xi1 - xi0) * rule_.points[g];
      const double dx = l * (xi1 - xi0) * rule_.weights[g];
      const std::size_t at = static_cast<std::size_t>(k) * rule_.points.size() + g;
      const Vec4 sh = wholly_wet ? wet_shape_[at] : ancf_cable::shape(xi, l);
      const Vec4 shx = wholly_wet ? wet_shape_dx_[at] : ancf_cable::shape_dx(xi, l);
      const Vec3 r = E * sh, rp = E * shx, rdot = Ed * sh;
      const bool deriv = want_matrix && (s.kq != 0.0 || s.kv != 0.0);
      // the Newton matrix from the water found at this iterate (fluid_at: a restart forms
      // it again from the iterate alone)
      const PointLoad pl =
          point_load(pc, fluid_at(k, g, r, state.t, deriv), rp, rdot, load_factor, deriv);
      if (target.forces) {
        auto Q = target.forces->segment<12>(beam_.node_index(k));
        for (int i = 0; i < 4; ++i) Q.segment<3>(3 * i) += (dx * sh[i]) * pl.f;  // eq. (177)
      }
      if (!want_matrix) continue;
      if (product) {
        if (s.km != 0.0 && added_mass) {  // sum_i S_i^T (ca I + (ca_ax - ca) t t^T) S x dx
          const Vec3& tt = pl.t;
          const Vec3 x_at = ancf_cable::as_nodes(x) * sh;
          const Vec3 f =
              (s.km * dx) * (ca_mass * x_at + (ca_axial_mass - ca_mass) * tt.dot(x_at) * tt);
          for (int i = 0; i < 4; ++i) y.segment<3>(3 * i) += sh[i] * f;
        }
        continue;
      }
      if (s.km != 0.0 && added_mass) {
        const Vec3& tt = pl.t;
        add_shape_product(
            K, sh, sh, ca_mass * Mat3::Identity() + (ca_axial_mass - ca_mass) * tt * tt.transpose(),
            s.km * dx);
      }
      if (s.kq != 0.0 && added_mass && target.acceleration) {
        // the added mass turns with the axis: d/dr' [(ca I + (ca_ax - ca) t t^T) a] with
        // t = r'/|r'|, dt/dr' = (I - t t^T)/|r'|, is (ca_ax - ca) (t a^T + (t.a) I) (I - t
        // t^T)/|r'|
        const Vec12 ea = target.acceleration->segment<12>(beam_.node_index(k));
        const Vec3 ax = ancf_cable::as_nodes(ea) * sh;
        const double stretch = rp.norm();
        const Vec3 tt = rp / stretch;
        const Mat3 P = Mat3::Identity() - tt * tt.transpose();
        const Mat3 D = (ca_axial_mass - ca_mass) *
                       (tt * ax.transpose() + tt.dot(ax) * Mat3::Identity()) * P / stretch;
        add_shape_product(K, sh, shx, D, s.kq * dx);
      }
      if (s.kv != 0.0) add_shape_product(K, sh, sh, pl.df_dv, -s.kv * dx);
      if (s.kq != 0.0) add_shape_product(K, sh, shx, pl.df_drp, -s.kq * dx);
      if (s.kq != 0.0 && reuse_ <= 0.0) {
        // position: central differences of the fluid field (current profile, waves)
        Mat3 df_dr;
        const double h = 1e-4;
        for (int j = 0; j < 3; ++j) {
          Vec3 rp_ = r, rm_ = r;
          rp_[j] += h;
          rm_[j] -= h;
          // buoyancy is uniform where wet: left out, so the surface is no step
          df_dr.col(j) = (point_load(pc, ocean_->fluid(rp_, state.t, false), rp, rdot, load_factor,
                                     false, false)
                              .f -
                          point_load(pc, ocean_->fluid(rm_, state.t, false), rp, rdot, load_factor,
                                     false, false)
                              .f) /
                         (2.0 * h);
        }
        add_shape_product(K, sh, sh, df_dr, -s.kq * dx);
      }
    }
    if (product)
      target.matrix->product_y().segment<12>(beam_.node_index(k)) += y;
    else if (want_matrix)
      target.matrix->add(blocks_[k], K);
  });
}

}  // namespace seaflex
