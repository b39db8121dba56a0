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
// negative when it is below -threshold (1e-3) of that scaled matrix: modes without
// stiffness (a free spin about a hanging line, a body about a cable's axis) give pivots at
// round-off level, not unstable equilibria; an equilibrium within a few per cent of a
// buckling load is missed too (docs/model-format.md section 12, docs/verification.md
// section 32). K is symmetrized first (non-conservative loads, the L1 and T2 cable models).
#pragma once

#include <string>

#include "seaflex/system/dae.hpp"

namespace seaflex {

struct StabilityReport {
  int negative = 0;          ///< directions of negative stiffness (negative pivots)
  double most_negative = 0;  ///< the most negative scaled pivot (< 0 if any)
  Index worst = -1;          ///< the coordinate of that pivot (-1: none negative)
  bool factored = true;      ///< false: the LDL^T broke down (a zero pivot), nothing known
};

/// The stability of `state` as an equilibrium (its multipliers in state.lambda) at the
/// load factor. threshold: the smallest negative pivot counted, in the scaled matrix
/// (entries of order one; see the file header).
StabilityReport check_stability(const Dae& dae, const State& state, double load_factor = 1.0,
                                double threshold = 1e-3);

/// The same from the KKT matrix [K C_q^T; C_q 0] of such an evaluation (kq = 1 with the
/// multipliers' Hessian), n coordinates and m constraint rows: statics passes the matrix
/// its last Newton iteration evaluated at the converged state.
StabilityReport check_stability(const SpMat& kkt, Index n, Index m, double threshold = 1e-3);

/// One line for a warning, e.g. "the equilibrium found is unstable: 8 directions of
/// negative stiffness, the largest at chain.n60.r'.y ..."; empty when none.
std::string describe_instability(const Dae& dae, const StabilityReport& report);

}  // namespace seaflex
