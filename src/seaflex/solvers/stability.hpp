// Stability of a static equilibrium: the signs of the tangent stiffness K (the Hessian of
// the Lagrangian, kq = 1 in the KKT matrix, geometric stiffness and d(C_q^T mu)/dq included)
// on the null space of the constraints' Jacobian C_q.
//
// Finsler's lemma (Debreu 1952, Econometrica 20:295-300): Z^T K Z is positive definite,
// Z a basis of the null space of C_q, if and only if K + rho C_q^T C_q is for every rho
// above some rho*; and for rho large enough the penalized matrix has exactly as many
// negative eigenvalues as Z^T K Z (the constrained directions gain rho |C_q d|^2 > 0).
// Those are counted as the negative pivots of a sparse LDL^T factorization (Sylvester's law
// of inertia), without forming Z: the cost of one sparse factorization, linear in the
// size of a line's model.
//
// Scaling: K's rows and columns by the square root of each row's largest entry (positions,
// slopes and rotations have different units; the scaled entries are at most one) and
// C_q's rows to unit length (the same null space), with rho = 1e9. A pivot counts as
// negative when it is below -threshold (1e-3) of that scaled matrix. The threshold is
// what keeps modes without stiffness (a free spin about a hanging line, a body about a
// cable's axis, a floating body's yaw) out of the count: a finite rho biases them
// slightly negative (Finsler's lemma holds with equal inertia only for a nonsingular
// Z^T K Z) and round-off is about rho eps. Pivots are not eigenvalues: their sizes depend
// on the elimination order (AMD here) and on how the negative stiffness compares with the
// line's axial stiffness, so a column just past its buckling load is missed (1.03 P_cr;
// counted from 1.2 P_cr, docs/verification.md section 32) and the count of a mode at the
// edge may differ by one from seaflex modes', which is exact. K is symmetrized first
// (non-conservative loads, the L1 and T2 cable models).
#pragma once

#include <string>

#include "seaflex/system/dae.hpp"

namespace seaflex {

struct StabilityReport {
  int negative = 0;      ///< directions of negative stiffness (negative pivots)
  VecX direction;        ///< a direction of the most negative pivot (x^T K x < 0), or empty
  bool factored = true;  ///< false: the LDL^T broke down (a zero pivot), nothing known
};

/// The stability of an equilibrium from the KKT matrix [K C_q^T; C_q 0] evaluated there
/// (kq = 1 with the multipliers' Hessian, not regularized), n coordinates and m
/// constraint rows: statics passes the matrix its last Newton iteration evaluated at the
/// converged state. threshold: the smallest negative pivot counted, in the scaled matrix.
StabilityReport check_stability(const SpMat& kkt, Index n, Index m, double threshold = 1e-3);

/// The coordinate of a direction's largest position component (its largest component when
/// no position moves); -1 for an empty direction.
Index worst_position(const Dae& dae, const VecX& direction);

/// One line for a warning, e.g. "the equilibrium found is unstable: 8 directions of
/// negative stiffness, the most negative moving chain.n165.r.z most ..."; empty when none.
std::string describe_instability(const Dae& dae, const StabilityReport& report);

/// The warning of seaflex modes (and the Python API) for modes with omega^2 < 0; empty
/// when none.
std::string describe_unstable_modes(int unstable, double lowest_omega2);

}  // namespace seaflex
