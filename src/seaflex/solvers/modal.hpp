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
};

/// The lowest `count` modes (all when count <= 0 or too large).
ModalResult solve_modes(const Dae& dae, const State& state, int count);

}  // namespace seaflex
