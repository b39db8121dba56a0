// Holds chosen coordinates of a body on an imposed motion (a beam support that moves):
//   C_i = q_k(i) - f_i(t) = 0,   C_q = unit rows,   C_t = -f_i'(t),   gamma = f_i''(t)
// (thesis eq. 133 with C_qq = C_qt = 0 and C_tt = -f''). Each row is one component of a
// point p0 or of a direction s0 (a nodal slope) at rest, displaced by the Motion about its
// origin (model/motion.hpp): a point p(t) = o + x + R (p0 - o), a slope R s0.
#pragma once

#include <memory>

#include "seaflex/model/body.hpp"
#include "seaflex/model/constraint.hpp"
#include "seaflex/model/motion.hpp"

namespace seaflex {

class PrescribedCoordinates : public Constraint {
 public:
  struct Row {
    Index local;        ///< coordinate of the body
    bool point;         ///< a point (true) or a direction (false)
    Vec3 rest;          ///< the point p0 or direction s0 at rest
    int component;      ///< 0, 1, 2
    std::string label;  ///< for messages
  };
  PrescribedCoordinates(std::string name, const Body& body, std::vector<Row> rows,
                        std::shared_ptr<const Motion> motion, const Vec3& origin);

  Index num_rows() const override { return static_cast<Index>(rows_.size()); }
  std::vector<Index> coordinates() const override;
  bool is_linear() const override { return true; }
  void evaluate(const State& state, ConstraintEval& out) const override;
  void add_multiplier_hessian(const State&, const Eigen::Ref<const VecX>&,
                              Eigen::Ref<MatX>) const override {}
  std::string row_name(Index row) const override;
  /// Channels <name>.f<label> (N): the force the support exerts on the coordinate,
  /// -lambda (M q'' + C_q^T lambda = Q).
  void add_channels(ChannelList& channels, Index row_offset) const override;

 private:
  const Body& body_;
  std::vector<Row> rows_;
  std::shared_ptr<const Motion> motion_;
  Vec3 origin_;
};

}  // namespace seaflex
