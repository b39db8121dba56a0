// An ANCF thin plate: a mesh of nx x ny plate elements (ancf_plate_shape,
// ancf_plate_elastic) on a rectangle, sharing (nx + 1)(ny + 1) nodes, thesis section 2.3.
// Node (i, j) sits at corner + i a t1 + j b t2 (i along the first edge, j along the
// second, from 0; a, b the element sizes, t1, t2 the unit edge directions) and carries
// r, r_p1, r_p2, r_p1p2 (thesis eq. 61), 12 coordinates at offset() + 12 (i (ny + 1) + j).
// The stress-free shape is the flat rectangle; p1, p2 are arc lengths along t1, t2.
#pragma once

#include <algorithm>
#include <array>
#include <memory>
#include <vector>

#include "seaflex/core/parallel.hpp"
#include "seaflex/elements/ancf_plate_elastic.hpp"
#include "seaflex/model/body.hpp"
#include "seaflex/model/marker.hpp"

namespace seaflex {

/// A rectangle: a corner, two perpendicular edge vectors (m) and element counts.
struct PlateGeometry {
  Vec3 corner = Vec3::Zero();
  Vec3 edge1 = Vec3::UnitX();  ///< the first edge (i direction), full length
  Vec3 edge2 = Vec3::UnitY();  ///< the second edge (j direction), full length
  int nx = 1;                  ///< elements along edge1
  int ny = 1;                  ///< elements along edge2
};

struct PlateOptions {
  ancf_plate::MidplaneModel midplane = ancf_plate::MidplaneModel::kExact;
  ancf_plate::TransverseModel transverse = ancf_plate::TransverseModel::kExact;
  int gauss_points = 5;
};

class AncfPlate : public Body {
 public:
  /// Throws std::invalid_argument for a degenerate rectangle (zero or non-perpendicular
  /// edges, counts < 1) or an invalid material. Edges within 1e-6 (cosine) of perpendicular
  /// are accepted; the second is then made exactly perpendicular to the first.
  AncfPlate(std::string name, PlateGeometry geometry, ancf_plate::PlateMaterial material,
            PlateOptions options);

  std::string_view kind() const override { return "ancf_plate"; }
  Index num_coordinates() const override { return 12 * num_nodes(); }
  void write_initial_state(VecX& q, VecX& v) const override;
  void declare_blocks(math::SparseBlockAssembler& matrix) override;
  void assemble(const State& state, AssemblyTarget& target) const override;
  bool constant_mass() const override { return true; }
  void add_gravity(const Vec3& g, const State& state, AssemblyTarget& target) const override;
  double gravity_potential(const Vec3& g, const State& state) const override;
  double kinetic_energy(const State& state) const override;
  double strain_energy(const State& state) const override;
  std::string coordinate_name(Index local) const override;
  void add_channels(ChannelList& channels) const override;
  std::string summary() const override;
  /// The shorter element side (m).
  double length_scale() const override { return std::min(a_, b_); }

  int nx() const { return geometry_.nx; }
  int ny() const { return geometry_.ny; }
  int num_nodes() const { return (nx() + 1) * (ny() + 1); }
  int num_elements() const { return nx() * ny(); }
  /// Element sizes a (along edge1) and b (along edge2), m.
  double a() const { return a_; }
  double b() const { return b_; }
  /// Unit edge directions and the unit normal t1 x t2 of the reference rectangle.
  const Vec3& t1() const { return t1_; }
  const Vec3& t2() const { return t2_; }
  Vec3 normal() const { return t1_.cross(t2_); }
  const PlateGeometry& geometry() const { return geometry_; }
  const ancf_plate::PlateMaterial& material() const { return material_; }
  const PlateOptions& options() const { return options_; }
  double mass() const { return material_.mass_per_area() * a_ * b_ * num_elements(); }

  /// Node number of node (i, j), 0 <= i <= nx, 0 <= j <= ny.
  int node_number(int i, int j) const { return i * (ny() + 1) + j; }
  /// Local index (within the body) of the first coordinate of node (i, j); then r_p1 at
  /// +3, r_p2 at +6, r_p1p2 at +9.
  Index node_local(int i, int j) const { return 12 * node_number(i, j); }
  Index node_index(int i, int j) const { return offset() + node_local(i, j); }
  /// Initial (reference) position of node (i, j).
  Vec3 node_position(int i, int j) const;
  /// Initial values of the 12 coordinates of a node.
  Eigen::Matrix<double, 12, 1> node_initial(int i, int j) const;

  /// Local indices of element (ei, ej)'s 48 coordinates, in the order of the kernels.
  const std::array<Index, 48>& element_locals(int el) const { return element_locals_[el]; }
  int element_number(int ei, int ej) const { return ei * ny() + ej; }
  ancf_plate::Vec48 element_coordinates(const VecX& q, int el) const;
  const ancf_plate::PlateElasticity& elasticity() const { return elasticity_; }
  /// 4 colors by (ei mod 2, ej mod 2): no two elements of one color share a node.
  const ElementColoring& coloring() const { return coloring_; }

 private:
  void scatter(int el, const ancf_plate::Vec48& Qe, VecX& Q) const;

  PlateGeometry geometry_;
  ancf_plate::PlateMaterial material_;
  PlateOptions options_;
  double a_ = 0.0, b_ = 0.0;
  Vec3 t1_, t2_;
  ancf_plate::PlateElasticity elasticity_;
  ancf_plate::Mat48 mass_;
  std::vector<std::array<Index, 48>> element_locals_;
  std::vector<math::BlockId> blocks_;
  ElementColoring coloring_;
};

/// A marker at a plate node: the point r, and as axes the slopes x = r_p1, y = r_p2 and
/// z = r_p1 x r_p2 (the normal scaled by the area stretch). The axes are not normalized:
/// in the unstrained plate they are the unit edge directions and the unit normal, and
/// they stretch and shear with the plate, as a beam marker's slope does. The point and
/// x, y are linear in q; z is bilinear (it has a bias and a Hessian). Depends on the
/// node's r, r_p1 and r_p2 (9 coordinates).
class PlateMarker : public Marker {
 public:
  PlateMarker(const AncfPlate& plate, int i, int j);

  std::string describe() const override;
  const Body* body() const override { return &plate_; }
  std::vector<Index> coordinates() const override;
  bool has(MarkerVector) const override { return true; }
  void evaluate(MarkerVector which, const State& state, MarkerVectorEval& out) const override;
  void add_hessian(MarkerVector which, const State& state, const Vec3& F,
                   Eigen::Ref<MatX> H) const override;
  bool linear() const override { return false; }

 private:
  const AncfPlate& plate_;
  int i_, j_;
};

}  // namespace seaflex
