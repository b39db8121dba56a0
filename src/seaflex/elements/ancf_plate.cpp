#include "seaflex/elements/ancf_plate.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace seaflex {

using ancf_plate::Mat48;
using ancf_plate::Vec48;

namespace {

double element_size(const Vec3& edge, int n) {
  if (n < 1) throw std::invalid_argument("AncfPlate: element counts must be at least 1");
  return edge.norm() / n;
}

Mat3 skew(const Vec3& v) {
  Mat3 S;
  S << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return S;
}

}  // namespace

AncfPlate::AncfPlate(std::string name, PlateGeometry geometry, ancf_plate::PlateMaterial material,
                     PlateOptions options)
    : Body(std::move(name)),
      geometry_(geometry),
      material_(material),
      options_(options),
      a_(element_size(geometry.edge1, geometry.nx)),
      b_(element_size(geometry.edge2, geometry.ny)),
      t1_(geometry.edge1.normalized()),
      t2_(geometry.edge2.normalized()),
      elasticity_((a_ > 0.0 && b_ > 0.0) ? a_ : 1.0, (a_ > 0.0 && b_ > 0.0) ? b_ : 1.0, material,
                  options.midplane, options.transverse, options.gauss_points) {
  const double l1 = geometry.edge1.norm(), l2 = geometry.edge2.norm();
  if (!(l1 > 0.0) || !(l2 > 0.0))
    throw std::invalid_argument("AncfPlate: the edge vectors must not be zero");
  if (std::abs(t1_.dot(t2_)) > 1e-6)
    throw std::invalid_argument("AncfPlate: the edge vectors must be perpendicular");
  // input rounded to a few digits: make the reference exactly orthonormal (no initial strain)
  t2_ = (t2_ - t2_.dot(t1_) * t1_).normalized();
  mass_ = ancf_plate::mass_matrix(material_.mass_per_area(), a_, b_);
  for (int ei = 0; ei < nx(); ++ei)
    for (int ej = 0; ej < ny(); ++ej) {
      std::array<Index, 48> locals{};
      for (int c = 0; c < 16; ++c) {
        const ancf_plate::ColumnRole role = ancf_plate::column_role(c);
        const Index first = node_local(ei + role.corner1, ej + role.corner2) + 3 * role.kind;
        for (int k = 0; k < 3; ++k) locals[3 * c + k] = first + k;
      }
      element_locals_.push_back(locals);
    }
  // element (ei, ej) has the nodes ei..ei+1 x ej..ej+1: elements of equal parities share none
  std::vector<int> color(element_locals_.size());
  for (int ei = 0; ei < nx(); ++ei)
    for (int ej = 0; ej < ny(); ++ej) color[element_number(ei, ej)] = 2 * (ei % 2) + ej % 2;
  coloring_ = ElementColoring(color);
}

Vec3 AncfPlate::node_position(int i, int j) const {
  return geometry_.corner + (i * a_) * t1_ + (j * b_) * t2_;
}

Eigen::Matrix<double, 12, 1> AncfPlate::node_initial(int i, int j) const {
  Eigen::Matrix<double, 12, 1> x;
  x << node_position(i, j), t1_, t2_, Vec3::Zero();
  return x;
}

void AncfPlate::write_initial_state(VecX& q, VecX& v) const {
  for (int i = 0; i <= nx(); ++i)
    for (int j = 0; j <= ny(); ++j) {
      q.segment<12>(node_index(i, j)) = node_initial(i, j);
      v.segment<12>(node_index(i, j)).setZero();
    }
}

Vec48 AncfPlate::element_coordinates(const VecX& q, int el) const {
  Vec48 e;
  const auto& locals = element_locals_[el];
  for (int k = 0; k < 48; ++k) e[k] = q[offset() + locals[k]];
  return e;
}

void AncfPlate::scatter(int el, const Vec48& Qe, VecX& Q) const {
  const auto& locals = element_locals_[el];
  for (int k = 0; k < 48; ++k) Q[offset() + locals[k]] += Qe[k];
}

void AncfPlate::declare_blocks(math::SparseBlockAssembler& matrix) {
  blocks_.clear();
  std::vector<Index> dofs(48);
  for (int el = 0; el < num_elements(); ++el) {
    for (int k = 0; k < 48; ++k) dofs[k] = offset() + element_locals_[el][k];
    blocks_.push_back(matrix.declare_block(dofs, dofs));
  }
}

void AncfPlate::assemble(const State& state, AssemblyTarget& target) const {
  const MatrixScales& k = target.scales;
  const bool want_K = target.matrix && k.kq != 0.0;
  // 4 colors by (i mod 2, j mod 2), in parallel within each (core/parallel.hpp); the
  // scratch matrices live on each thread's stack
  for_each_colored(coloring_, [&](int el) {
    const Vec48 e = element_coordinates(state.q, el);
    Vec48 Q = Vec48::Zero();
    Mat48 K;
    if (want_K) K.setZero();
    elasticity_.add_forces(e, Q, want_K ? &K : nullptr);
    if (target.forces) scatter(el, Q, *target.forces);
    if (target.matrix) {
      // km M + kq K, K = -dQ/de (no velocity dependence)
      Mat48 H = k.km * mass_;
      if (want_K) H += k.kq * K;
      target.matrix->add(blocks_[el], H);
    }
  });
}

void AncfPlate::add_gravity(const Vec3& g, const State&, AssemblyTarget& target) const {
  if (!target.forces) return;
  // thesis eq. (126, 128): the uniform load mu g over each element
  const Vec48 Qg = ancf_plate::uniform_load(material_.mass_per_area() * g, a_, b_);
  for (int el = 0; el < num_elements(); ++el) scatter(el, Qg, *target.forces);
}

double AncfPlate::gravity_potential(const Vec3& g, const State& state) const {
  // the gravity force is constant, so V = -Q_g . q
  const Vec48 Qg = ancf_plate::uniform_load(material_.mass_per_area() * g, a_, b_);
  double V = 0.0;
  for (int el = 0; el < num_elements(); ++el) V -= Qg.dot(element_coordinates(state.q, el));
  return V;
}

double AncfPlate::kinetic_energy(const State& state) const {
  double T = 0.0;
  for (int el = 0; el < num_elements(); ++el) {
    const Vec48 ve = element_coordinates(state.v, el);
    T += 0.5 * ve.dot(mass_ * ve);  // thesis eq. (69)
  }
  return T;
}

double AncfPlate::strain_energy(const State& state) const {
  double U = 0.0;
  for (int el = 0; el < num_elements(); ++el) {
    Vec48 Q = Vec48::Zero();
    U += elasticity_.add_forces(element_coordinates(state.q, el), Q, nullptr);
  }
  return U;
}

std::string AncfPlate::coordinate_name(Index local) const {
  static constexpr const char* kAxis[] = {"x", "y", "z"};
  static constexpr const char* kKind[] = {"r", "r_p1", "r_p2", "r_p1p2"};
  const Index node = local / 12, c = local % 12;
  const Index i = node / (ny() + 1), j = node % (ny() + 1);
  return fmt::format("{}.n{}_{}.{}.{}", name(), i, j, kKind[c / 3], kAxis[c % 3]);
}

void AncfPlate::add_channels(ChannelList& channels) const {
  static constexpr const char* kAxis[] = {"x", "y", "z"};
  for (int i = 0; i <= nx(); ++i)
    for (int j = 0; j <= ny(); ++j)
      for (int c = 0; c < 3; ++c) {
        const AncfPlate* self = this;
        channels.push_back(
            {fmt::format("{}.n{}_{}.{}", name(), i, j, kAxis[c]),
             [self, i, j, c](const State& s) { return s.q[self->node_index(i, j) + c]; }});
      }
}

std::string AncfPlate::summary() const {
  return fmt::format(
      "{} x {} elements, {} nodes, {} coordinates; {:g} m x {:g} m, thickness {:g} m, mass "
      "{:.6g} kg; E {:.4g} Pa, nu {:g}, D {:.4g} N m; midplane {}, transverse {}",
      nx(), ny(), num_nodes(), num_coordinates(), geometry_.edge1.norm(), geometry_.edge2.norm(),
      material_.thickness, mass(), material_.youngs_modulus, material_.poisson_ratio,
      material_.flexural_rigidity(), ancf_plate::to_string(options_.midplane),
      ancf_plate::to_string(options_.transverse));
}

PlateMarker::PlateMarker(const AncfPlate& plate, int i, int j) : plate_(plate), i_(i), j_(j) {
  if (i < 0 || i > plate.nx() || j < 0 || j > plate.ny())
    throw std::out_of_range(fmt::format("node n{}_{} outside plate {} (n0_0 .. n{}_{})", i, j,
                                        plate.name(), plate.nx(), plate.ny()));
}

std::string PlateMarker::describe() const {
  return fmt::format("{}.n{}_{}", plate_.name(), i_, j_);
}

std::vector<Index> PlateMarker::coordinates() const {
  std::vector<Index> dofs(9);
  for (int k = 0; k < 9; ++k) dofs[k] = plate_.node_index(i_, j_) + k;
  return dofs;
}

void PlateMarker::evaluate(MarkerVector which, const State& state, MarkerVectorEval& out) const {
  const Index first = plate_.node_index(i_, j_);
  out.J.setZero(3, 9);
  out.Jv.setZero(3, 9);
  out.bias.setZero();
  if (which != MarkerVector::kAxisZ) {
    const int slot = which == MarkerVector::kPoint ? 0 : which == MarkerVector::kAxisX ? 1 : 2;
    out.J.block<3, 3>(0, 3 * slot).setIdentity();
    out.value = state.q.segment<3>(first + 3 * slot);
    out.rate = state.v.segment<3>(first + 3 * slot);
    return;
  }
  // z = a x b, a = r_p1, b = r_p2: dz = -[b]x da + [a]x db, z'' = J q'' + 2 a' x b'
  const Vec3 a = state.q.segment<3>(first + 3), b = state.q.segment<3>(first + 6);
  const Vec3 ad = state.v.segment<3>(first + 3), bd = state.v.segment<3>(first + 6);
  out.value = a.cross(b);
  out.J.block<3, 3>(0, 3) = -skew(b);
  out.J.block<3, 3>(0, 6) = skew(a);
  out.rate = ad.cross(b) + a.cross(bd);
  out.bias = 2.0 * ad.cross(bd);
  out.Jv.block<3, 3>(0, 3) = -skew(bd);
  out.Jv.block<3, 3>(0, 6) = skew(ad);
}

void PlateMarker::add_hessian(MarkerVector which, const State&, const Vec3& F,
                              Eigen::Ref<MatX> H) const {
  if (which != MarkerVector::kAxisZ) return;
  // F . (a x b) = -a^T [F]x b
  const Mat3 SF = skew(F);
  H.block<3, 3>(3, 6) -= SF;
  H.block<3, 3>(6, 3) += SF;
}

}  // namespace seaflex
