// The System numbers coordinates, fixes the sparsity pattern once, and assembles
// Q, C, C_q, gamma and the scaled Newton (KKT) matrix from its bodies, forces and
// constraints. No solver logic and no I/O.
#pragma once

#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "seaflex/model/body.hpp"
#include "seaflex/model/channel.hpp"
#include "seaflex/model/constraint.hpp"
#include "seaflex/model/force.hpp"
#include "seaflex/system/dae.hpp"

namespace seaflex {

struct Energies {
  double kinetic = 0.0;    ///< 1/2 v^T M v (J)
  double strain = 0.0;     ///< elastic strain energy (J)
  double potential = 0.0;  ///< potential of conservative forces, gravity included (J)
  double total() const { return kinetic + strain + potential; }
};

class System : public Dae {
 public:
  System() = default;

  Body& add_body(std::unique_ptr<Body> body);
  void add_force(std::unique_ptr<Force> force);
  void add_constraint(std::unique_ptr<Constraint> constraint);

  /// Numbers coordinates and constraint rows and fixes the matrix pattern. Call once,
  /// after everything has been added.
  void finalize();
  bool finalized() const { return finalized_; }

  /// Body by name, or nullptr.
  const Body* find_body(std::string_view name) const;
  const std::vector<std::unique_ptr<Body>>& bodies() const { return bodies_; }
  const std::vector<std::unique_ptr<Force>>& forces() const { return forces_; }
  const std::vector<std::unique_ptr<Constraint>>& constraints() const { return constraints_; }

  /// The initial state: coordinates and velocities from the bodies, zero multipliers.
  State initial_state() const;

  Energies energies(const State& state) const;
  ChannelList channels() const;

  // Dae
  Index num_coordinates() const override { return n_; }
  Index num_constraints() const override { return m_; }
  DaeEval make_eval() const override;
  void evaluate(const State& state, const DaeRequest& request, DaeEval& out) const override;
  bool constant_mass_kkt() const override;
  bool constant_mass() const override;
  std::string coordinate_name(Index i) const override;
  std::string constraint_name(Index row) const override;
  double step_scale(const State& state, const VecX& dq) const override;
  double length_scale() const override;
  std::vector<Index> reaction_only_rows() const override { return reaction_only_rows_; }
  bool supports_product() const override { return true; }
  bool supports_constraint_jacobian() const override { return true; }
  void start(const State& state) override;
  void accept_step(const State& state) override;
  /// The constraint that owns a row of the multiplier vector; nullptr when out of range.
  const Constraint* constraint_at_row(Index row) const;

 private:
  std::vector<std::unique_ptr<Body>> bodies_;
  std::unordered_map<std::string, const Body*> body_index_;  // find_body in O(1)
  std::vector<std::unique_ptr<Force>> forces_;
  std::vector<std::unique_ptr<Constraint>> constraints_;
  bool finalized_ = false;
  Index n_ = 0;
  Index m_ = 0;
  std::vector<Index> row_offset_;  // constraint -> first row
  std::size_t constraint_index(Index row) const;
  std::size_t body_index(Index coordinate) const;  // bodies_.size() when none holds it
  std::vector<std::vector<Index>> constraint_dofs_;
  std::vector<math::BlockId> cq_block_, cqt_block_, hess_block_;
  math::SparseBlockAssembler pattern_;
  std::vector<math::BlockId> cq_only_block_;  // C_q alone (DaeRequest::constraint_jacobian)
  math::SparseBlockAssembler cq_pattern_;
  std::vector<Index> reaction_only_rows_;
};

}  // namespace seaflex
