#include "seaflex/elements/ancf_beam.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace seaflex {

using ancf_cable::Mat12;
using ancf_cable::Vec12;

BeamSection BeamSection::pipe(double outer_diameter, double inner_diameter, double youngs_modulus,
                              double density) {
  BeamSection s;
  const double d2o = outer_diameter * outer_diameter, d2i = inner_diameter * inner_diameter;
  s.area = std::numbers::pi / 4.0 * (d2o - d2i);
  s.second_moment = std::numbers::pi / 64.0 * (d2o * d2o - d2i * d2i);
  s.youngs_modulus = youngs_modulus;
  s.density = density;
  s.outer_diameter = outer_diameter;
  s.inner_diameter = inner_diameter;
  return s;
}

BeamGeometry BeamGeometry::straight(const Vec3& start, const Vec3& end, int elements) {
  return polyline({start, end}, {elements});
}

BeamGeometry BeamGeometry::polyline(const std::vector<Vec3>& points,
                                    const std::vector<int>& counts) {
  if (points.size() < 2 || counts.size() != points.size() - 1)
    throw std::invalid_argument("polyline: need n points and n-1 element counts");
  BeamGeometry g;
  std::vector<Vec3> dirs;
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const Vec3 d = points[i + 1] - points[i];
    if (!(d.norm() > 0.0) || counts[i] < 1)
      throw std::invalid_argument("polyline: zero-length segment or element count < 1");
    dirs.push_back(d.normalized());
  }
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const Vec3 d = points[i + 1] - points[i];
    const double l = d.norm() / counts[i];
    for (int k = 0; k < counts[i]; ++k) {
      g.positions.push_back(points[i] + (static_cast<double>(k) / counts[i]) * d);
      Vec3 t = dirs[i];
      if (k == 0 && i > 0) t = (dirs[i - 1] + dirs[i]).normalized();
      g.slopes.push_back(t);
      g.element_lengths.push_back(l);
    }
  }
  g.positions.push_back(points.back());
  g.slopes.push_back(dirs.back());
  return g;
}

AncfBeam::AncfBeam(std::string name, BeamGeometry geometry, BeamSection section,
                   BeamOptions options)
    : AncfBeam(std::move(name), geometry, std::vector<BeamSection>{section},
               std::vector<int>(geometry.element_lengths.size(), 0), options) {}

AncfBeam::AncfBeam(std::string name, BeamGeometry geometry, std::vector<BeamSection> sections,
                   std::vector<int> section_of, BeamOptions options)
    : Body(std::move(name)),
      geometry_(std::move(geometry)),
      sections_(std::move(sections)),
      section_of_(std::move(section_of)),
      options_(options),
      element_lengths_(geometry_.element_lengths) {
  if (element_lengths_.empty()) throw std::invalid_argument("AncfBeam: no elements");
  if (section_of_.size() != element_lengths_.size())
    throw std::invalid_argument("AncfBeam: one section index per element needed");
  for (int s : section_of_)
    if (s < 0 || s >= static_cast<int>(sections_.size()))
      throw std::invalid_argument("AncfBeam: section index out of range");
  node_arc_.push_back(0.0);
  for (double l : element_lengths_) node_arc_.push_back(node_arc_.back() + l);
  total_length_ = node_arc_.back();
  // one kernel per distinct (element length, section): one for a uniform straight mesh
  std::vector<std::pair<double, int>> kernel_keys;
  for (std::size_t el = 0; el < element_lengths_.size(); ++el) {
    const double l = element_lengths_[el];
    const int s = section_of_[el];
    int found = -1;
    for (std::size_t k = 0; k < kernel_keys.size(); ++k)
      if (kernel_keys[k].second == s && std::abs(kernel_keys[k].first - l) <= 1e-12 * l)
        found = static_cast<int>(k);
    if (found < 0) {
      const BeamSection& sec = sections_[s];
      kernel_keys.emplace_back(l, s);
      kernels_.emplace_back(l, sec.EA(), sec.EI(), options_.axial, options_.bending,
                            options_.gauss_points);
      masses_.push_back(ancf_cable::mass_matrix(sec.mass_per_length(), l));
      found = static_cast<int>(kernels_.size() - 1);
    }
    kernel_of_.push_back(found);
  }
  // gravity's nodal weights: int_0^l rho A S dx = rho A [l/2, l^2/12, l/2, -l^2/12] per element
  // (thesis eq. 127), summed at the shared nodes once here instead of at every evaluation
  gravity_r_.assign(element_lengths_.size() + 1, 0.0);
  gravity_s_.assign(element_lengths_.size() + 1, 0.0);
  for (std::size_t el = 0; el < element_lengths_.size(); ++el) {
    const double m = sections_[section_of_[el]].mass_per_length(), l = element_lengths_[el];
    gravity_r_[el] += 0.5 * m * l;
    gravity_s_[el] += m * l * l / 12.0;
    gravity_r_[el + 1] += 0.5 * m * l;
    gravity_s_[el + 1] -= m * l * l / 12.0;
  }
  // elements k and k + 1 share node k + 1: even and odd elements share nothing
  std::vector<int> color(element_lengths_.size());
  for (std::size_t el = 0; el < color.size(); ++el) color[el] = static_cast<int>(el % 2);
  coloring_ = ElementColoring(color);
}

void AncfBeam::set_initial_shape(std::vector<Vec3> positions, std::vector<Vec3> slopes) {
  if (positions.size() != geometry_.positions.size() || slopes.size() != geometry_.slopes.size())
    throw std::invalid_argument("AncfBeam::set_initial_shape: one position and slope per node");
  geometry_.positions = std::move(positions);
  geometry_.slopes = std::move(slopes);
}

void AncfBeam::write_initial_state(VecX& q, VecX& v) const {
  for (int k = 0; k < num_nodes(); ++k) {
    q.segment<3>(node_index(k)) = geometry_.positions[k];
    q.segment<3>(node_index(k) + 3) = geometry_.slopes[k];
    v.segment<6>(node_index(k)).setZero();
  }
}

std::vector<math::BlockId> AncfBeam::declare_element_blocks(
    math::SparseBlockAssembler& matrix) const {
  std::vector<math::BlockId> blocks;
  std::vector<Index> dofs(12);
  for (int k = 0; k < num_elements(); ++k) {
    for (int i = 0; i < 12; ++i) dofs[i] = node_index(k) + i;
    blocks.push_back(matrix.declare_block(dofs, dofs));
  }
  return blocks;
}

void AncfBeam::declare_blocks(math::SparseBlockAssembler& matrix) {
  blocks_ = declare_element_blocks(matrix);
}

void AncfBeam::assemble(const State& state, AssemblyTarget& target) const {
  const MatrixScales& k = target.scales;
  const bool want_K = target.matrix && k.kq != 0.0;
  // even, then odd elements; in parallel within each (core/parallel.hpp)
  for_each_colored(coloring_, [&](int el) {
    const Vec12 e = element_coordinates(state.q, el);
    Vec12 Q = Vec12::Zero();
    Mat12 K;  // zeroed only when the tangent is asked for (RK4 stages need forces only)
    if (want_K) K.setZero();
    elasticity(el).add_forces(e, Q, want_K ? &K : nullptr);
    if (target.forces) target.forces->segment<12>(node_index(el)) += Q;
    if (target.matrix && !want_K && target.matrix->in_product()) {
      // km M x alone: M = m (x) I3 (thesis eq. 10), so M x is the 3 x 4 node matrix of x
      // times the 4 x 4 m, without the 12 x 12 block
      const Mat12& M = masses_[kernel_of_[el]];
      Eigen::Matrix4d m4;
      for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) m4(i, j) = M(3 * i, 3 * j);
      const Vec12 x = target.matrix->product_x().segment<12>(node_index(el));
      Eigen::Map<ancf_cable::Mat34>(target.matrix->product_y().data() + node_index(el)) +=
          k.km * (ancf_cable::as_nodes(x) * m4.transpose());
    } else if (target.matrix) {
      // km M + kq K, K = -dQ/de (no velocity dependence: kv contributes nothing)
      Mat12 H = k.km * masses_[kernel_of_[el]];
      if (want_K) H += k.kq * K;
      target.matrix->add(blocks_[el], H);
    }
  });
}

void AncfBeam::add_gravity(const Vec3& g, const State&, AssemblyTarget& target) const {
  if (!target.forces) return;
  // thesis eq. (175): uniform load rho A g per unit length through eq. (127), by node
  for (std::size_t i = 0; i < gravity_r_.size(); ++i) {
    const Index at = node_index(static_cast<int>(i));
    target.forces->segment<3>(at) += gravity_r_[i] * g;
    target.forces->segment<3>(at + 3) += gravity_s_[i] * g;
  }
}

double AncfBeam::gravity_potential(const Vec3& g, const State& state) const {
  // the gravity force is constant, so V = -Q_g . q
  double V = 0.0;
  for (int el = 0; el < num_elements(); ++el)
    V -= ancf_cable::uniform_load(section(el).mass_per_length() * g, element_lengths_[el])
             .dot(element_coordinates(state.q, el));
  return V;
}

double AncfBeam::kinetic_energy(const State& state) const {
  double T = 0.0;
  for (int el = 0; el < num_elements(); ++el) {
    const Vec12 ve = state.v.segment<12>(node_index(el));
    T += 0.5 * ve.dot(masses_[kernel_of_[el]] * ve);
  }
  return T;
}

double AncfBeam::strain_energy(const State& state) const {
  double U = 0.0;
  for (int el = 0; el < num_elements(); ++el) {
    Vec12 Q = Vec12::Zero();
    U += elasticity(el).add_forces(element_coordinates(state.q, el), Q, nullptr);
  }
  return U;
}

std::string AncfBeam::coordinate_name(Index local) const {
  static constexpr const char* kAxis[] = {"x", "y", "z"};
  const Index node = local / 6, c = local % 6;
  return fmt::format("{}.n{}.{}.{}", name(), node, c < 3 ? "r" : "r'", kAxis[c % 3]);
}

void AncfBeam::add_channels(ChannelList& channels) const {
  static constexpr const char* kAxis[] = {"x", "y", "z"};
  for (int k = 0; k < num_nodes(); ++k)
    for (int c = 0; c < 3; ++c) {
      const AncfBeam* self = this;
      channels.push_back({fmt::format("{}.n{}.{}", name(), k, kAxis[c]),
                          [self, k, c](const State& s) { return s.q[self->node_index(k) + c]; }});
    }
}

double AncfBeam::mass() const {
  double m = 0.0;
  for (int el = 0; el < num_elements(); ++el)
    m += section(el).mass_per_length() * element_lengths_[el];
  return m;
}

double AncfBeam::length_scale() const {
  return *std::min_element(element_lengths_.begin(), element_lengths_.end());
}

std::string AncfBeam::summary() const {
  if (sections_.size() > 1)
    return fmt::format(
        "{} elements, {} nodes, {} coordinates; length {:g} m, mass {:.6g} kg; {} sections; "
        "axial {}, bending {}",
        num_elements(), num_nodes(), num_coordinates(), total_length_, mass(), sections_.size(),
        ancf_cable::to_string(options_.axial), ancf_cable::to_string(options_.bending));
  const BeamSection& sec = sections_.front();
  return fmt::format(
      "{} elements, {} nodes, {} coordinates; length {:g} m, mass {:.6g} kg; EA {:.4g} N, "
      "EI {:.4g} N m^2; axial {}, bending {}",
      num_elements(), num_nodes(), num_coordinates(), total_length_, mass(), sec.EA(), sec.EI(),
      ancf_cable::to_string(options_.axial), ancf_cable::to_string(options_.bending));
}

std::pair<int, double> AncfBeam::locate(double s) const {
  if (s < 0.0 || s > total_length_ * (1.0 + 1e-12))
    throw std::out_of_range(
        fmt::format("arc length {} m outside beam {} of length {} m", s, name(), total_length_));
  // the first element whose end is at or beyond s (binary search: many attachments on
  // long lines)
  const auto it = std::lower_bound(node_arc_.begin() + 1, node_arc_.end(), s);
  const int el = std::min(static_cast<int>(it - node_arc_.begin()) - 1, num_elements() - 1);
  return {el, std::clamp((s - node_arc_[el]) / element_lengths_[el], 0.0, 1.0)};
}

BeamMarker::BeamMarker(const AncfBeam& beam, double s) : beam_(beam), s_(s) {
  std::tie(element_, xi_) = beam.locate(s);
  const double tol = 1e-12;
  if (xi_ <= tol) node_ = element_;
  if (xi_ >= 1.0 - tol) node_ = element_ + 1;
}

std::unique_ptr<BeamMarker> BeamMarker::at_node(const AncfBeam& beam, int k) {
  if (k < 0 || k >= beam.num_nodes())
    throw std::out_of_range(
        fmt::format("node {} outside beam {} (nodes 0..{})", k, beam.name(), beam.num_nodes() - 1));
  return std::make_unique<BeamMarker>(beam, beam.node_arc_length(k));
}

std::string BeamMarker::describe() const {
  if (node_ >= 0) return fmt::format("{}.n{}", beam_.name(), node_);
  return fmt::format("{}@{:g}m", beam_.name(), s_);
}

const Body* BeamMarker::body() const {
  return &beam_;
}

std::vector<Index> BeamMarker::coordinates() const {
  std::vector<Index> dofs;
  const int count = node_ >= 0 ? 6 : 12;
  const Index first = beam_.node_index(node_ >= 0 ? node_ : element_);
  for (int i = 0; i < count; ++i) dofs.push_back(first + i);
  return dofs;
}

bool BeamMarker::has(MarkerVector which) const {
  return which == MarkerVector::kPoint || which == MarkerVector::kAxisZ;
}

void BeamMarker::evaluate(MarkerVector which, const State& state, MarkerVectorEval& out) const {
  if (!has(which)) throw std::logic_error("BeamMarker: a beam marker has no x or y axis");
  const bool slope = which == MarkerVector::kAxisZ;
  const Index n = node_ >= 0 ? 6 : 12;
  out.J.setZero(3, n);
  out.Jv.setZero(3, n);
  out.bias.setZero();
  if (node_ >= 0) {
    out.J.block<3, 3>(0, slope ? 3 : 0).setIdentity();
  } else {
    const double l = beam_.element_length(element_);
    // thesis eq. (3) and its x-derivative
    const ancf_cable::Vec4 S = slope ? ancf_cable::shape_dx(xi_, l) : ancf_cable::shape(xi_, l);
    for (int i = 0; i < 4; ++i) out.J.block<3, 3>(0, 3 * i).diagonal().setConstant(S[i]);
  }
  const Index first = beam_.node_index(node_ >= 0 ? node_ : element_);
  out.value = out.J * state.q.segment(first, n);
  out.rate = out.J * state.v.segment(first, n);
}

}  // namespace seaflex
