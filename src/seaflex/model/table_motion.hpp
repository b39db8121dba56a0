// A motion given as a time table of the six displacements, interpolated by natural cubic
// splines (one per degree of freedom), so that position, velocity and acceleration are
// continuous (de Boor, A Practical Guide to Splines (1978), ch. IV: the second
// derivatives M_i solve the tridiagonal system
//   h_{i-1} M_{i-1} + 2 (h_{i-1} + h_i) M_i + h_i M_{i+1}
//     = 6 ((y_{i+1} - y_i) / h_i - (y_i - y_{i-1}) / h_{i-1}),   M_0 = M_n = 0).
// Outside the table the motion holds the end values (zero velocity and acceleration);
// the velocity jumps there unless the table ends at rest.
#pragma once

#include <vector>

#include "seaflex/model/motion.hpp"

namespace seaflex {

class TableMotion : public Motion {
 public:
  /// times strictly increasing, at least 2 rows (4 or more to use the cubic); values in
  /// m and rad. Throws std::invalid_argument otherwise.
  TableMotion(std::vector<double> times, std::vector<Vec6> values);
  MotionSample sample(double t) const override;

 private:
  std::vector<double> times_;
  std::vector<Vec6> values_;
  std::vector<Vec6> second_;  // spline second derivatives M_i
};

}  // namespace seaflex
