// A force element: writes generalized forces and their exact tangents into the global
// structures. It owns no coordinates; it is a const function of the state (memory, when
// a force needs it, lives in State::z). External loads scale with the load factor
// used by static load stepping.
#pragma once

#include <string>

#include "seaflex/model/assembly.hpp"
#include "seaflex/model/channel.hpp"
#include "seaflex/model/state.hpp"

namespace seaflex {

class Force {
 public:
  explicit Force(std::string name) : name_(std::move(name)) {}
  virtual ~Force() = default;
  Force(const Force&) = delete;
  Force& operator=(const Force&) = delete;

  const std::string& name() const { return name_; }

  /// Called once after coordinates are numbered: declare matrix blocks (may be none).
  virtual void declare_blocks(math::SparseBlockAssembler& matrix) = 0;

  /// Adds Q and its tangent as the target asks; external loads scale with load_factor,
  /// internal force elements (springs) do not.
  virtual void assemble(const State& state, double load_factor, AssemblyTarget& target) const = 0;

  /// Potential energy (J) for forces that define one (gravity, springs). External loads,
  /// which may vary in time, return 0: their work is not part of System::energies().
  virtual double potential_energy(const State& state) const = 0;

  /// Appends output channels (tension, angle); none by default.
  virtual void add_channels(ChannelList& /*channels*/) const {}

  /// False when the force adds a mass matrix that depends on the state (added mass in
  /// the direction normal to a beam or in a body's current axes): the integrator must
  /// then refactor the augmented matrix.
  virtual bool constant_mass() const { return true; }

  /// Memory (a radiation force's velocity history): called once with the initial state
  /// of a time simulation, and after every accepted time step. RK4 stages and Newton
  /// iterations in between only evaluate. Nothing by default.
  virtual void start(const State& /*state*/) {}
  virtual void accept_step(const State& /*state*/) {}
  /// True when start()/accept_step() keep a memory (a radiation force's history), which
  /// restart files do not hold yet.
  virtual bool has_memory() const { return false; }

 private:
  std::string name_;
};

}  // namespace seaflex
