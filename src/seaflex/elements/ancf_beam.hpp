// An ANCF beam: a mesh of N cable elements (ancf_cable) sharing N+1 nodes, each node
// carrying r and r' (6 coordinates), thesis section 2.2. Node k's coordinates are
// offset() + 6k ... offset() + 6k + 5, so element k's 12 coordinates are contiguous.
// The stress-free shape of every element is straight with its reference length; a
// polyline start shape is a first guess for statics, not a stress-free curve.
// A line made of sections (issue 18) is one beam whose elements carry different
// cross-sections and materials: element k has section section_index(k).
#pragma once

#include <memory>
#include <vector>

#include "seaflex/core/parallel.hpp"
#include "seaflex/elements/ancf_cable.hpp"
#include "seaflex/elements/ancf_cable_elastic.hpp"
#include "seaflex/model/body.hpp"
#include "seaflex/model/marker.hpp"

namespace seaflex {

/// Cross-section and material of a beam. All SI.
struct BeamSection {
  double area = 0.0;            ///< A (m^2)
  double second_moment = 0.0;   ///< I (m^4), same in both bending planes
  double youngs_modulus = 0.0;  ///< E (Pa)
  double density = 0.0;         ///< rho (kg/m^3)
  double outer_diameter = 0.0;  ///< m; 0 when the section was given as A and I
  double inner_diameter = 0.0;  ///< m

  /// Pipe section from outer and inner diameter: A = pi/4 (Do^2 - Di^2), I = pi/64 (Do^4 - Di^4).
  static BeamSection pipe(double outer_diameter, double inner_diameter, double youngs_modulus,
                          double density);
  double EA() const { return youngs_modulus * area; }
  double EI() const { return youngs_modulus * second_moment; }
  double mass_per_length() const { return density * area; }
};

/// Initial node positions and unit slopes, and the reference length of each element.
struct BeamGeometry {
  std::vector<Vec3> positions;
  std::vector<Vec3> slopes;
  std::vector<double> element_lengths;

  /// n equal elements on the segment start -> end.
  static BeamGeometry straight(const Vec3& start, const Vec3& end, int elements);
  /// counts[i] equal elements on segment i of the polyline; interior vertex slopes are the
  /// normalized mean of the adjacent segment directions.
  static BeamGeometry polyline(const std::vector<Vec3>& points, const std::vector<int>& counts);
};

struct BeamOptions {
  ancf_cable::AxialModel axial = ancf_cable::AxialModel::kExact;
  ancf_cable::BendingModel bending = ancf_cable::BendingModel::kExact;
  int gauss_points = 5;
};

class AncfBeam : public Body {
 public:
  AncfBeam(std::string name, BeamGeometry geometry, BeamSection section, BeamOptions options);
  /// A line made of sections: element k has sections[section_of[k]] (section_of has one
  /// entry per element, each a valid index into sections).
  AncfBeam(std::string name, BeamGeometry geometry, std::vector<BeamSection> sections,
           std::vector<int> section_of, BeamOptions options);

  std::string_view kind() const override { return "ancf_beam"; }
  Index num_coordinates() const override { return 6 * num_nodes(); }
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
  /// The shortest element (m).
  double length_scale() const override;

  int num_elements() const { return static_cast<int>(element_lengths_.size()); }
  int num_nodes() const { return num_elements() + 1; }
  double element_length(int k) const { return element_lengths_[k]; }
  /// Total reference (unstretched) length (m).
  double length() const { return total_length_; }
  /// Reference arc length of node k from the start node (m).
  double node_arc_length(int k) const { return node_arc_[k]; }
  /// The cross-section and material of element k.
  const BeamSection& section(int k) const { return sections_[section_of_[k]]; }
  /// Index into sections() of element k's section.
  int section_index(int k) const { return section_of_[k]; }
  /// The distinct sections, in the order given (one for a uniform beam).
  const std::vector<BeamSection>& sections() const { return sections_; }
  /// Total mass (kg) of the beam's own material.
  double mass() const;
  /// Initial node positions and slopes, as built.
  const BeamGeometry& initial_geometry() const { return geometry_; }
  /// Replaces the initial node positions and slopes (a better first guess for statics,
  /// found once the loads are known); the element lengths stay. Before the run starts.
  void set_initial_shape(std::vector<Vec3> positions, std::vector<Vec3> slopes);
  const BeamOptions& options() const { return options_; }

  /// Global index of the first coordinate of node k (r), r' follows at +3.
  Index node_index(int k) const { return offset() + 6 * k; }
  /// One 12 x 12 block per element (its coordinates, contiguous): for the beam itself and
  /// for forces along it (Morison, seabed contact). Call after numbering.
  std::vector<math::BlockId> declare_element_blocks(math::SparseBlockAssembler& matrix) const;
  /// Element k's 12 coordinates from q.
  ancf_cable::Vec12 element_coordinates(const VecX& q, int k) const {
    return q.segment<12>(node_index(k));
  }
  /// Element kernels (elasticity of element k).
  const ancf_cable::CableElasticity& elasticity(int k) const { return kernels_[kernel_of_[k]]; }

  /// Element and local xi of the reference arc length s in [0, length()].
  std::pair<int, double> locate(double s) const;
  /// Even and odd elements: no two elements of one color share a node. Element loops
  /// over the beam (its own, Morison loads) run color by color (core/parallel.hpp).
  const ElementColoring& coloring() const { return coloring_; }

 private:
  BeamGeometry geometry_;
  std::vector<BeamSection> sections_;
  std::vector<int> section_of_;  // element -> section
  BeamOptions options_;
  std::vector<double> element_lengths_;
  std::vector<double> node_arc_;
  double total_length_ = 0.0;
  std::vector<ancf_cable::CableElasticity> kernels_;  // one per distinct (length, section)
  std::vector<ancf_cable::Mat12> masses_;             // per distinct (length, section)
  std::vector<int> kernel_of_;                        // element -> kernel
  // the weights of a uniform load at each node (thesis eq. 127 summed over the elements that
  // share it): Q_r = gravity_r_[i] g, Q_r' = gravity_s_[i] g (gravity is constant in q)
  std::vector<double> gravity_r_, gravity_s_;
  std::vector<math::BlockId> blocks_;  // element -> matrix block
  ElementColoring coloring_;
};

/// A marker on an ANCF beam at a reference arc length: the point r = S(xi) e (thesis
/// eq. 3) and one axis, kAxisZ = the slope r' = S_x(xi) e (not normalized; its length is
/// the stretch). Both are linear in e, so the bias and the Hessian vanish. At a node the
/// marker depends on the node's six coordinates only.
class BeamMarker : public Marker {
 public:
  /// s: reference arc length from the start node (m), 0 <= s <= beam.length().
  BeamMarker(const AncfBeam& beam, double s);
  /// Exactly at node k.
  static std::unique_ptr<BeamMarker> at_node(const AncfBeam& beam, int k);

  std::string describe() const override;
  const Body* body() const override;
  std::vector<Index> coordinates() const override;
  bool has(MarkerVector which) const override;
  void evaluate(MarkerVector which, const State& state, MarkerVectorEval& out) const override;
  void add_hessian(MarkerVector, const State&, const Vec3&, Eigen::Ref<MatX>) const override {}
  bool linear() const override { return true; }

 private:
  const AncfBeam& beam_;
  int node_ = -1;  // >= 0 when exactly at a node
  int element_ = 0;
  double xi_ = 0.0;
  double s_ = 0.0;
};

}  // namespace seaflex
