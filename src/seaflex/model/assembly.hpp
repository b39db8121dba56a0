// What a body or force writes during one evaluation.
//
// Generalized forces Q (right-hand side of thesis eq. 132) are added to *forces.
// The system matrix receives  km * M  -  kq * dQ/dq  -  kv * dQ/dv  : one scaled matrix
// serves the RK4 mass solve (km = 1), Newton statics (kq = 1) and implicit integrators.
#pragma once

#include "seaflex/core/types.hpp"
#include "seaflex/math/sparse_block_assembler.hpp"

namespace seaflex {

struct MatrixScales {
  double km = 0.0;  ///< scale of the mass matrix
  double kq = 0.0;  ///< scale of -dQ/dq (tangent stiffness)
  double kv = 0.0;  ///< scale of -dQ/dv (tangent damping)
  bool any() const { return km != 0.0 || kq != 0.0 || kv != 0.0; }
};

struct AssemblyTarget {
  VecX* forces = nullptr;                        ///< Q += ... when not null
  math::SparseBlockAssembler* matrix = nullptr;  ///< matrix += ... when not null
  MatrixScales scales;
  /// When not null (and kq != 0), bodies and loads whose mass matrix depends on q add
  /// kq * d(M(q) a)/dq for these accelerations a to the matrix (implicit integrators).
  const VecX* acceleration = nullptr;
};

}  // namespace seaflex
