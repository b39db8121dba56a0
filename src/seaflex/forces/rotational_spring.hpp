// A rotational spring-damper between the z axes of two markers (the bending stiffness of
// a riser flex joint): with a, b the axes (a beam marker's axis is its slope) and theta
// the angle between them,
//   V = 1/2 k theta^2,  theta^2 = g(w) = acos(1 - w)^2,  w = 1 - a^.b^,
// written through w because g is analytic at w = 0 (g = 2w + w^2/3 + ...), so the force
// and its exact tangent stay regular when the axes are aligned. The moment on b's body is
// -k theta n, n = (a x b)/|a x b|. Damping acts on the rate of r = b^ - a^ (the relative
// angular velocity across the axes for small angles): Q = -c J_r^T r'; its q-derivative
// is left out of the tangent (exact at rest, i.e. in statics).
#pragma once

#include <memory>

#include "seaflex/model/force.hpp"
#include "seaflex/model/marker_pair.hpp"

namespace seaflex {

class RotationalSpring : public Force {
 public:
  /// stiffness in N m/rad, damping in N m s/rad.
  RotationalSpring(std::string name, std::unique_ptr<Marker> a, std::unique_ptr<Marker> b,
                   double stiffness, double damping);

  void declare_blocks(math::SparseBlockAssembler& matrix) override;
  void assemble(const State& state, double load_factor, AssemblyTarget& target) const override;
  double potential_energy(const State& state) const override;
  void add_channels(ChannelList& channels) const override;

  double angle(const State& state) const;  ///< rad
  /// Moment (N m, world axes) of the spring and damper on marker b's body.
  Vec3 moment_on_b(const State& state) const;

 private:
  MarkerPair pair_;
  double stiffness_, damping_;
  math::BlockId block_ = -1;
};

}  // namespace seaflex
