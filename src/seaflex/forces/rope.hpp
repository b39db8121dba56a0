// A rope (wire) through a path of marker points p_0 ... p_k: over frictionless sheaves,
// fairleads and through reeved blocks, the wireline of a riser tensioner (thesis 3.3.2,
// Fig. 36). Segment i joins p_i and p_{i+1} and is run n_i times (its parts: n_i = 4
// between the two sheave blocks of a tensioner with a 4:1 reeving ratio).
//
//   L = sum_i n_i |d_i|,  d_i = p_{i+1} - p_i;   T = EA (L - L0) / L0 + c L'  while L > L0
//
// and T = 0 while the rope is slack. On a winch (forces/winch.hpp) the free length follows
// time, L0(t) = L0 + dL0(t), and the damping acts on the stretch rate L' - L0'(t).
// (a rope never pushes, also while it shortens fast).
// The tension is the same in every part (frictionless sheaves): point p_i is pulled by
// n_i T towards p_{i+1} and by n_{i-1} T towards p_{i-1}; the generalized force is
// Q = -T dL/dq. Exact tangents:
//   dQ/dq = -g (k g + c h)^T - T d2L/dq2,  dQ/dv = -c g g^T,
// with g = dL/dq, h = dL'/dq, k = EA / L0; d2L/dq2 holds the transverse stiffness
// n_i (I - u_i u_i^T) / |d_i| of each segment and the attitude terms of rigid-body markers.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "seaflex/forces/winch.hpp"
#include "seaflex/model/force.hpp"
#include "seaflex/model/marker_pair.hpp"

namespace seaflex {

class Rope : public Force {
 public:
  /// segments: the pairs (p_i, p_{i+1}) in order, with their number of parts (>= 1).
  Rope(std::string name, std::vector<MarkerPair> segments, std::vector<int> parts,
       double free_length, double axial_stiffness, double damping);

  void declare_blocks(math::SparseBlockAssembler& matrix) override;
  void assemble(const State& state, double load_factor, AssemblyTarget& target) const override;
  double potential_energy(const State& state) const override;
  void add_channels(ChannelList& channels) const override;

  /// Total length of wire between the end points, sum n_i |d_i| (m).
  double length(const State& state) const;
  double tension(const State& state) const;  ///< N, >= 0
  int num_segments() const { return static_cast<int>(segments_.size()); }
  double free_length() const { return free_length_; }
  /// The free length at the state's time, L0 + dL0(t) (m).
  double free_length(const State& state) const;
  /// Puts the rope on a winch.
  void set_winch(Winch winch) { winch_ = std::move(winch); }
  void set_free_length(double free_length) { free_length_ = free_length; }
  double axial_stiffness() const { return axial_stiffness_; }
  /// The first segment whose two points coincide in state (-1: none).
  int first_vanishing_segment(const State& state) const;

 private:
  std::vector<MarkerPair> segments_;
  std::vector<int> parts_;
  double free_length_;
  double axial_stiffness_;                // EA (N)
  double damping_;                        // N s/m on L'
  std::optional<Winch> winch_;            // the free length follows time when set
  std::vector<Index> dofs_;               // union of all markers' coordinates
  std::vector<std::vector<Index>> cols_;  // per segment: pair column -> union column
  math::BlockId block_ = -1;
};

}  // namespace seaflex
