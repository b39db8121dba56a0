// The flat state of a system: everything that changes in time, nothing else.
#pragma once

#include "seaflex/core/types.hpp"

namespace seaflex {

/// t (s), coordinates q, velocities v (same size as q today), Lagrange multipliers
/// lambda (one per constraint row), and auxiliary states z owned by forces.
struct State {
  double t = 0.0;
  VecX q;
  VecX v;
  VecX lambda;
  VecX z;
};

}  // namespace seaflex
