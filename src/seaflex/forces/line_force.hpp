// A force along the line between the points of two markers a and b: the base of the
// spring (spring_damper) and the pneumatic cylinder. With d = p_b - p_a, L = |d|,
// n = d / L and L' = n . d', a tension T(L, L') (positive when it pulls the points
// together) puts T n on a and -T n on b, Q = -J_d^T T n. Exact tangents:
//   dQ/dq = -(J^T F_d J + J^T F_r J_v + d(J^T f)/dq),  dQ/dv = -J^T F_r J,
//   F_d = T_L n n^T + T/L (I - n n^T) + T_L' n ((I - n n^T) d')^T / L,  F_r = T_L' n n^T,
// with T_L = dT/dL and T_L' = dT/dL'; the last term holds the attitude terms of rigid-body
// markers (MarkerPair::add_hessian).
#pragma once

#include <memory>
#include <string>

#include "seaflex/model/force.hpp"
#include "seaflex/model/marker_pair.hpp"

namespace seaflex {

/// T and its derivatives at the current L and L'.
struct LineTension {
  double T = 0.0;       ///< N, positive pulling the points together
  double dT_dL = 0.0;   ///< N/m
  double dT_dLd = 0.0;  ///< N s/m
};

/// The line between two markers: d = p_b - p_a, its length and rate.
struct LineState {
  PairVectorEval d;
  double length = 0.0;  ///< L (m)
  double rate = 0.0;    ///< L' (m/s); 0 when L = 0
};

class LineForce : public Force {
 public:
  LineForce(std::string name, std::unique_ptr<Marker> a, std::unique_ptr<Marker> b);

  void declare_blocks(math::SparseBlockAssembler& matrix) override;
  /// L = |p_b - p_a| (m)
  double length(const State& state) const;

 protected:
  /// d, L and L' in state.
  LineState line(const State& state) const;
  /// As line(), for assembly: throws SolverError when the points meet (the line of action
  /// is undefined); what names the element in the message ("spring", "cylinder").
  LineState line_for_assembly(const State& state, const char* what) const;
  /// Adds Q and the scaled tangent of the tension t to target.
  void assemble_line(const LineState& line, const LineTension& t, const State& state,
                     AssemblyTarget& target) const;
  bool has_coordinates() const { return !pair_.dofs().empty(); }

 private:
  MarkerPair pair_;
  math::BlockId block_ = -1;
};

}  // namespace seaflex
