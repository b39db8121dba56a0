// Model check of the constraint set at a state, before any solve: rows of C_q that are
// linear combinations of earlier rows (redundant or over-constrained joints, which make
// the augmented matrix of eq. 132 singular), and rows that are not satisfied (joint
// markers that do not meet, conflicting supports).
#pragma once

#include <vector>

#include "seaflex/system/dae.hpp"

namespace seaflex {

struct RedundantRow {
  Index row;                      ///< constraint row dependent on earlier ones
  std::vector<Index> depends_on;  ///< the earlier rows of the combination
};

struct ViolatedRow {
  Index row;
  double value;  ///< C at the state
};

struct ConstraintAudit {
  std::vector<RedundantRow> redundant;
  std::vector<ViolatedRow> violated;
  std::vector<ViolatedRow> velocity_violated;  ///< value = C_q v + C_t
  bool ok() const { return redundant.empty() && violated.empty() && velocity_violated.empty(); }
};

/// Rows are taken in order; a row whose component orthogonal to the span of the earlier
/// independent rows is below rank_tolerance of its norm is redundant (a rank-revealing
/// sparse QR of C_q^T, SuiteSparseQR: O(m) for chains of bodies; see constraint_audit.cpp).
/// depends_on is filled for the first 20 redundant rows whose neighbourhood is small enough. A row
/// is violated when |C| > violation_tolerance, its velocity when |C_q v + C_t| >
/// velocity_tolerance.
ConstraintAudit audit_constraints(const Dae& dae, const State& state,
                                  double violation_tolerance = 1e-6,
                                  double velocity_tolerance = 1e-6, double rank_tolerance = 1e-9);

}  // namespace seaflex
