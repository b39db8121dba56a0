// A winch on a rope: the unstretched length the winch has paid out (> 0) or hauled in
// (< 0) since t = 0, as a function of time, with its rate:
//   - a constant rate r from a start time: dL0(t) = r max(0, t - start);
//   - a time table (t, dL0) interpolated by a natural cubic spline (model/table_motion.hpp),
//     so the rate is continuous; held at the end values outside the table.
// The rope's free length is L0(t) = L0 + dL0(t) (forces/rope.hpp).
#pragma once

#include <memory>
#include <vector>

#include "seaflex/model/table_motion.hpp"

namespace seaflex {

class Winch {
 public:
  /// Pays out at rate (m/s; negative hauls in) from start (s).
  static Winch constant_rate(double rate, double start);
  /// The table (s, m); times strictly increasing, at least two rows.
  static Winch table(std::vector<double> times, std::vector<double> changes);

  double change(double t) const;  ///< dL0 (m)
  double rate(double t) const;    ///< d(dL0)/dt (m/s)

 private:
  double rate_ = 0.0, start_ = 0.0;
  std::shared_ptr<const TableMotion> table_;
};

}  // namespace seaflex
