// Natural frequencies and mode shapes of the system linearized about a state (usually
// static equilibrium): K phi = omega^2 M phi on the constraint null space, with K the
// exact tangent stiffness (kq = 1, geometric stiffness included) and M the mass matrix.
// Dense generalized symmetric eigen-solution: intended for models up to a few thousand
// coordinates.
#pragma once

#include "seaflex/system/dae.hpp"

namespace seaflex {

struct ModalResult {
  VecX omega;         ///< natural circular frequencies (rad/s), ascending
  VecX frequency_hz;  ///< omega / (2 pi)
  MatX shapes;        ///< mode shapes in the full coordinates, one column per mode, M-normalized
  MatX mass_shapes;   ///< M * shapes (kinetic energy shares: post/mode_shapes.hpp)
  /// modes with omega^2 < 0 (listed with omega = 0): the state is not a stable equilibrium;
  /// counted below -1e-12 of the largest |omega^2| (round-off of the dense eigensolver)
  int unstable = 0;
  double lowest_omega2 = 0.0;  ///< the smallest omega^2 (rad^2/s^2), negative when unstable
};

/// The lowest `count` modes (all when count <= 0 or too large).
ModalResult solve_modes(const Dae& dae, const State& state, int count);

}  // namespace seaflex
