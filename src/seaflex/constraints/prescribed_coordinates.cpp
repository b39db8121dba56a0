#include "seaflex/constraints/prescribed_coordinates.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace seaflex {

PrescribedCoordinates::PrescribedCoordinates(std::string name, const Body& body,
                                             std::vector<Row> rows,
                                             std::shared_ptr<const Motion> motion,
                                             const Vec3& origin)
    : Constraint(std::move(name)),
      body_(body),
      rows_(std::move(rows)),
      motion_(std::move(motion)),
      origin_(origin) {
  for (const Row& r : rows_)
    if (r.local < 0 || r.local >= body_.num_coordinates() || r.component < 0 || r.component > 2)
      throw std::out_of_range("PrescribedCoordinates: coordinate outside the body");
}

std::vector<Index> PrescribedCoordinates::coordinates() const {
  std::vector<Index> dofs;
  for (const Row& r : rows_) dofs.push_back(body_.offset() + r.local);
  return dofs;
}

void PrescribedCoordinates::evaluate(const State& state, ConstraintEval& out) const {
  const MotionPose pose = motion_->pose(state.t);
  out.Cq.setZero();
  for (std::size_t i = 0; i < rows_.size(); ++i) {
    const Row& r = rows_[i];
    const MovingVector f =
        r.point ? displaced_point(pose, origin_, r.rest) : displaced_axis(pose, r.rest);
    out.C[i] = state.q[body_.offset() + r.local] - f.value[r.component];
    out.Cq(i, i) = 1.0;
    out.Ct[i] = -f.rate[r.component];
    out.gamma[i] = f.accel[r.component];  // C'' = q'' - f'' = 0: C_q q'' = f''
  }
}

std::string PrescribedCoordinates::row_name(Index row) const {
  return name() + ": " + rows_.at(row).label;
}

void PrescribedCoordinates::add_channels(ChannelList& channels, Index row_offset) const {
  for (std::size_t i = 0; i < rows_.size(); ++i) {
    if (!rows_[i].point) continue;
    const Index row = row_offset + static_cast<Index>(i);
    channels.push_back({fmt::format("{}.f{}", name(), rows_[i].label), [row](const State& s) {
                          if (s.lambda.size() <= row)
                            throw std::logic_error("PrescribedCoordinates: no multipliers");
                          return -s.lambda[row];
                        }});
  }
}

}  // namespace seaflex
