// The flat state of a system: everything that changes in time, nothing else.
#pragma once

#include "seaflex/core/types.hpp"

namespace seaflex {

/// t (s), coordinates q, velocities v (same size as q today), Lagrange multipliers
/// lambda (one per constraint row), and auxiliary states z owned by forces.
///
/// One hand-over besides: static_residual is the force residual Q - C_q^T lambda that
/// statics left at q (its round-off, below the statics tolerance), set by solve_statics and
/// empty otherwise. A dynamic run that starts from that state takes it for the equilibrium
/// it stands for: generalized-alpha's initial accelerations leave the residual out (a
/// round-off of 10 N over the 5e-7 kg m^2 slope mass of a 3 cm beam element is 1e7 rad/s^2,
/// which the first steps cannot absorb). Simulation clears it after the start; it is not
/// part of a checkpoint.
struct State {
  double t = 0.0;
  VecX q;
  VecX v;
  VecX lambda;
  VecX z;
  VecX static_residual;
};

}  // namespace seaflex
