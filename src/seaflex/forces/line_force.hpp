// A force along the line between the points of two markers a and b, shared by the spring
// (spring_damper) and the pneumatic cylinder: with d = p_b - p_a, L = |d|, n = d / L and
// L' = n . d', a tension T(L, L') (positive when it pulls the points together) puts T n on
// a and -T n on b, Q = -J_d^T T n. Exact tangents:
//   dQ/dq = -(J^T F_d J + J^T F_r J_v + d(J^T f)/dq),  dQ/dv = -J^T F_r J,
//   F_d = T_L n n^T + T/L (I - n n^T) + T_L' n ((I - n n^T) d')^T / L,  F_r = T_L' n n^T,
// with T_L = dT/dL and T_L' = dT/dL'; the last term holds the attitude terms of rigid-body
// markers (MarkerPair::add_hessian).
#pragma once

#include "seaflex/math/sparse_block_assembler.hpp"
#include "seaflex/model/assembly.hpp"
#include "seaflex/model/marker_pair.hpp"

namespace seaflex {

/// T and its derivatives at the current L and L'.
struct LineTension {
  double T = 0.0;       ///< N, positive pulling the points together
  double dT_dL = 0.0;   ///< N/m
  double dT_dLd = 0.0;  ///< N s/m
};

/// Adds Q and the scaled tangent of a line force to target; d is the pair's evaluation of
/// p_b - p_a (MarkerVector::kPoint, signs -1, +1) with |d| > 0, block the pair's block.
void assemble_line_force(const MarkerPair& pair, const PairVectorEval& d, const LineTension& t,
                         const State& state, math::BlockId block, AssemblyTarget& target);

}  // namespace seaflex
