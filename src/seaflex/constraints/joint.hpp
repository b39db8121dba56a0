// Joints between two markers, every row of the form C = u . w (Haug 1989, ch. 9:
// "dot-1", "dot-2" and spherical conditions), so one class covers rigid-rigid,
// beam-beam, beam-rigid and ground connections:
//   ball         p_to - p_from = 0                       thesis eq. (138-143, 151-153, 157-159)
//   universal    ball + x_from . y_to = 0
//   revolute     ball + x_from . z_to = 0, y_from . z_to = 0          (hinge axis z)
//   cylindrical  x_from . z_to, y_from . z_to, x_from . d, y_from . d  thesis eq. (144-146)
//   prismatic    cylindrical + x_from . y_to = 0                       (slides along z)
//   fixed        ball + z_from . x_to, z_from . y_to, x_from . y_to    thesis eq. (147-149)
//                ball + x_from . r'_to, y_from . r'_to  (beam to)      thesis eq. (160-171)
//                ball + r'_to - r'_from = 0             (beam-beam)    thesis eq. (154-155)
// with d = p_to - p_from. Eq. (144-146) states parallel axes as a cross product whose
// three rows are dependent; the rows here use the two body-fixed normals x_from, y_from
// of the axis, which stay independent in every configuration. Eq. (160-171) uses the unit
// slope; the plain slope r' has the same zero set and keeps the rows polynomial.
//
// A beam marker has only the z axis (its slope), so the frame side ("from") must be a
// rigid body or ground; a joint given with the beam first is swapped internally and its
// reactions are still reported on the body named second.
//
// Reactions: force and moment exerted by the joint on the body named "to", in world
// axes, the moment about the "to" marker point; from the multipliers (M q'' + C_q^T
// lambda = Q): a row u . w with multiplier mu gives the "to" body the force -mu u when w
// holds p_to, and the moment mu u x a when w holds its axis a.
#pragma once

#include <functional>
#include <memory>
#include <string_view>
#include <utility>

#include "seaflex/model/constraint.hpp"
#include "seaflex/model/marker_pair.hpp"

namespace seaflex {

enum class JointType { kBall, kUniversal, kRevolute, kCylindrical, kPrismatic, kFixed };

std::string_view joint_type_name(JointType type);

class Joint : public Constraint {
 public:
  /// Throws std::invalid_argument naming the missing axis when the markers cannot carry
  /// this joint type (e.g. a prismatic joint on a beam marker).
  Joint(std::string name, JointType type, std::unique_ptr<Marker> from, std::unique_ptr<Marker> to);

  JointType type() const { return type_; }
  /// The markers as the user named them.
  const Marker& from() const { return swapped_ ? pair_.b() : pair_.a(); }
  const Marker& to() const { return swapped_ ? pair_.a() : pair_.b(); }

  Index num_rows() const override { return static_cast<Index>(rows_.size()); }
  std::vector<Index> coordinates() const override;
  bool is_linear() const override { return linear_; }
  void evaluate(const State& state, ConstraintEval& out) const override;
  void add_multiplier_hessian(const State& state, const Eigen::Ref<const VecX>& mu,
                              Eigen::Ref<MatX> H) const override;
  std::string row_name(Index row) const override;
  void add_channels(ChannelList& channels, Index row_offset) const override;

  /// Force and moment on the "to" body (see the header), for the joint's multipliers mu.
  std::pair<Vec3, Vec3> reaction(const State& state, const Eigen::Ref<const VecX>& mu) const;

  /// A moment that acts on the "to" body beside the constraint (a flex joint's spring),
  /// added to the reported reaction moment.
  void set_extra_moment(std::function<Vec3(const State&)> moment) {
    extra_moment_ = std::move(moment);
  }

 private:
  enum class Factor {
    kUnitX,
    kUnitY,
    kUnitZ,
    kFromX,
    kFromY,
    kFromZ,
    kToX,
    kToY,
    kToZ,
    kSeparation,
    kSlopeDifference
  };
  static constexpr std::size_t kFactorCount = 11;  // the Factors above
  static_assert(static_cast<std::size_t>(Factor::kSlopeDifference) + 1 == kFactorCount);
  struct Row {
    Factor u;  // never depends on the "to" marker
    Factor w;
    std::string label;
  };
  // a factor is the pair combination sign_a x_a + sign_b x_b of one marker vector
  struct FactorDef {
    MarkerVector vector;
    double sign_from, sign_to;
  };
  static FactorDef define(Factor f);
  void add_row(Factor u, Factor w, std::string label);
  void factor(Factor f, const State& state, PairVectorEval& out) const;

  JointType type_;
  bool swapped_ = false;
  // a = the frame side ("from" internally), b = "to"; its coordinate union is bound by
  // coordinates(), which the System calls once after numbering
  mutable MarkerPair pair_;
  std::vector<Row> rows_;
  bool linear_ = false;
  std::function<Vec3(const State&)> extra_moment_;
};

}  // namespace seaflex
