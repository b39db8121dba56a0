#include "seaflex/forces/beam_attachment.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "seaflex/math/gauss_legendre.hpp"

namespace seaflex {

namespace {
using ancf_cable::add_shape_product;
using ancf_cable::Mat12;
using ancf_cable::Vec12;
using ancf_cable::Vec4;
}  // namespace

BeamAttachment::BeamAttachment(std::string name, const AncfBeam& beam,
                               std::vector<double> arc_lengths, AttachmentProperties p, Vec3 g,
                               std::shared_ptr<const hydro::Ocean> ocean)
    : Force(std::move(name)),
      beam_(beam),
      arc_lengths_(std::move(arc_lengths)),
      p_(p),
      g_(std::move(g)),
      ocean_(std::move(ocean)) {
  if (arc_lengths_.empty()) throw std::invalid_argument("BeamAttachment: no arc lengths");
  for (double s : arc_lengths_) {
    const auto [element, xi] = beam_.locate(s);  // throws outside [0, length]
    points_.push_back({element, xi, 1.0, {}});
  }
}

std::unique_ptr<BeamAttachment> BeamAttachment::smeared(std::string name, const AncfBeam& beam,
                                                        double from, double to, int count,
                                                        AttachmentProperties p, Vec3 g,
                                                        std::shared_ptr<const hydro::Ocean> ocean) {
  if (!(to > from) || count < 1)
    throw std::invalid_argument("BeamAttachment::smeared: need from < to and count >= 1");
  std::vector<double> centres;
  const double share = (to - from) / count;
  for (int i = 0; i < count; ++i) centres.push_back(from + (i + 0.5) * share);
  auto a = std::make_unique<BeamAttachment>(std::move(name), beam, std::move(centres), p,
                                            std::move(g), std::move(ocean));
  // 3-point Gauss-Legendre on each element's part of [from, to], weights per unit length
  // count / (to - from)
  const math::QuadratureRule rule = math::gauss_legendre_unit(3);
  const double per_length = count / (to - from);
  a->points_.clear();
  for (int k = 0; k < beam.num_elements(); ++k) {
    const double s0 = std::max(from, beam.node_arc_length(k));
    const double s1 = std::min(to, beam.node_arc_length(k + 1));
    if (!(s1 > s0)) continue;
    const double l = beam.element_length(k);
    for (std::size_t q = 0; q < rule.points.size(); ++q) {
      const double s = s0 + (s1 - s0) * rule.points[q];
      a->points_.push_back(
          {k, (s - beam.node_arc_length(k)) / l, per_length * (s1 - s0) * rule.weights[q], {}});
    }
  }
  return a;
}

std::vector<std::pair<double, double>> BeamAttachment::load_points() const {
  std::vector<std::pair<double, double>> out;
  for (const Point& pt : points_)
    out.emplace_back(beam_.node_arc_length(pt.element) + pt.xi * beam_.element_length(pt.element),
                     pt.share);
  return out;
}

void BeamAttachment::declare_blocks(math::SparseBlockAssembler& matrix) {
  std::vector<Index> dofs(12);
  for (Point& pt : points_) {
    for (int i = 0; i < 12; ++i) dofs[i] = beam_.node_index(pt.element) + i;
    pt.block = matrix.declare_block(dofs, dofs);
  }
}

bool BeamAttachment::constant_mass() const {
  // the added mass switches at the surface
  return !(ocean_ && p_.ca * p_.volume > 0.0);
}

double BeamAttachment::submerged_weight() const {
  const double g = g_.norm();
  return p_.mass * g - (ocean_ ? ocean_->rho() * g * p_.volume : 0.0);
}

Vec3 BeamAttachment::load(const Vec3& r, const Vec3& rdot, double t, bool* wet, Mat3* df_dv) const {
  Vec3 f = p_.mass * g_;
  if (df_dv) df_dv->setZero();
  *wet = false;
  if (!ocean_) return f;
  const hydro::FluidPoint fl = ocean_->fluid(r, t);
  if (!fl.wet) return f;
  *wet = true;
  const double rho = ocean_->rho();
  f -= rho * p_.volume * g_;                               // buoyancy, against gravity
  f += rho * p_.volume * (1.0 + p_.ca) * fl.acceleration;  // DNV-RP-C205 eq. 6.2.2
  const Vec3 w = fl.velocity - rdot;                       // relative velocity
  const double cd = 0.5 * rho * p_.cd * p_.drag_area;      // Morison drag
  const double wn = w.norm();
  f += cd * wn * w;
  if (df_dv) {
    // d(|w| w)/dw = |w| I + w w^T / |w|; dw/d(r_dot) = -I
    *df_dv = -cd * wn * Mat3::Identity();
    if (wn > 0.0) *df_dv -= (cd / wn) * w * w.transpose();
  }
  return f;
}

void BeamAttachment::assemble(const State& state, double load_factor,
                              AssemblyTarget& target) const {
  const MatrixScales& s = target.scales;
  const bool want_matrix = target.matrix != nullptr && s.any();
  for (const Point& pt : points_) {
    const double l = beam_.element_length(pt.element);
    const Index first = beam_.node_index(pt.element);
    const Vec4 sh = ancf_cable::shape(pt.xi, l);  // thesis eq. (3)
    const Vec12 e = state.q.segment<12>(first), ed = state.v.segment<12>(first);
    const auto E = ancf_cable::as_nodes(e);
    const auto Ed = ancf_cable::as_nodes(ed);
    const Vec3 r = E * sh, rdot = Ed * sh;
    bool wet = false;
    Mat3 df_dv;
    const double scale = load_factor * pt.share;
    const Vec3 f = scale * load(r, rdot, state.t, &wet, want_matrix ? &df_dv : nullptr);
    if (target.forces) {
      auto Q = target.forces->segment<12>(first);
      for (int i = 0; i < 4; ++i) Q.segment<3>(3 * i) += sh[i] * f;  // Q = S^T f
    }
    if (!want_matrix) continue;
    Mat12 K = Mat12::Zero();
    if (s.km != 0.0) {
      const double m = p_.mass + (wet ? ocean_->rho() * p_.ca * p_.volume : 0.0);
      add_shape_product(K, sh, sh, pt.share * m * Mat3::Identity(), s.km);
    }
    if (s.kv != 0.0) add_shape_product(K, sh, sh, scale * df_dv, -s.kv);
    if (s.kq != 0.0 && wet && ocean_) {
      // the fluid field's gradient by central differences; buoyancy (uniform where wet)
      // left out so that the surface is no step
      Mat3 df_dr;
      const double h = 1e-4;
      for (int j = 0; j < 3; ++j) {
        Vec3 rp = r, rm = r;
        rp[j] += h;
        rm[j] -= h;
        bool wp = false, wm = false;
        Vec3 fp = load(rp, rdot, state.t, &wp, nullptr);
        Vec3 fm = load(rm, rdot, state.t, &wm, nullptr);
        if (wp != wm) {
          df_dr.col(j).setZero();
          continue;
        }
        df_dr.col(j) = scale * (fp - fm) / (2.0 * h);
      }
      add_shape_product(K, sh, sh, df_dr, -s.kq);
    }
    target.matrix->add(pt.block, K);
  }
}

void BeamAttachment::add_channels(ChannelList& channels) const {
  const BeamAttachment* self = this;
  const double count = static_cast<double>(points_.size());
  channels.push_back({fmt::format("{}.count", name()), [count](const State&) { return count; }});
  channels.push_back({fmt::format("{}.net_weight", name()), [self](const State& state) {
                        const double g = self->g_.norm();
                        double w = 0.0;
                        for (const Point& pt : self->points_) {
                          const double l = self->beam_.element_length(pt.element);
                          const Vec12 e = state.q.segment<12>(self->beam_.node_index(pt.element));
                          const Vec3 r = ancf_cable::as_nodes(e) * ancf_cable::shape(pt.xi, l);
                          const bool wet = self->ocean_ && self->ocean_->fluid(r, state.t).wet;
                          w += pt.share * (self->p_.mass * g -
                                           (wet ? self->ocean_->rho() * g * self->p_.volume : 0.0));
                        }
                        return w;
                      }});
}

}  // namespace seaflex
