// A body owns a contiguous range of the system's coordinates and supplies its mass,
// internal (elastic, inertial) forces with their exact tangents, gravity, energies and
// output channels. New body kinds (rigid body, ANCF plate) derive from this class.
#pragma once

#include <limits>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "seaflex/model/assembly.hpp"
#include "seaflex/model/channel.hpp"
#include "seaflex/model/constraint.hpp"
#include "seaflex/model/state.hpp"

namespace seaflex {

class Body {
 public:
  explicit Body(std::string name) : name_(std::move(name)) {}
  virtual ~Body() = default;
  Body(const Body&) = delete;
  Body& operator=(const Body&) = delete;

  const std::string& name() const { return name_; }
  virtual std::string_view kind() const = 0;

  virtual Index num_coordinates() const = 0;
  /// First global coordinate; set by the System when it numbers coordinates.
  Index offset() const { return offset_; }
  void set_offset(Index offset) { offset_ = offset; }

  /// Writes the initial coordinates and velocities into the body's range of q and v.
  virtual void write_initial_state(VecX& q, VecX& v) const = 0;

  /// Declares the dense blocks this body will add to the system matrix (global indices).
  virtual void declare_blocks(math::SparseBlockAssembler& matrix) = 0;

  /// Adds internal forces and/or km M - kq dQ/dq - kv dQ/dv, as the target asks.
  virtual void assemble(const State& state, AssemblyTarget& target) const = 0;

  /// True when the mass matrix does not depend on the state (lets RK4 factor it once).
  virtual bool constant_mass() const = 0;

  /// Adds the generalized force of the uniform acceleration field g (m/s^2) on the mass.
  virtual void add_gravity(const Vec3& g, const State& state, AssemblyTarget& target) const = 0;
  /// Potential energy of gravity g (J), zero at the origin.
  virtual double gravity_potential(const Vec3& g, const State& state) const = 0;

  virtual double kinetic_energy(const State& state) const = 0;
  virtual double strain_energy(const State& state) const = 0;

  /// Name of a local coordinate for messages, e.g. "n3.r'.z".
  virtual std::string coordinate_name(Index local) const = 0;

  /// One line for `seaflex check`: size, mass, models.
  virtual std::string summary() const = 0;

  /// Appends this body's output channels.
  virtual void add_channels(ChannelList& channels) const = 0;

  /// Largest fraction (<= 1) of a Newton update dq (global vector) that this body accepts
  /// in one iteration; 1 unless the body's coordinates have a limited safe range.
  virtual double step_scale(const State& /*state*/, const VecX& /*dq*/) const { return 1.0; }

  /// The shortest length over which this body's coordinates are differenced into strains
  /// (m): a flexible body's shortest element side; +inf for a rigid body. An error dq in the
  /// positions is a strain error of about dq / length_scale() (the integrators' position
  /// tolerances are relative to it).
  virtual double length_scale() const { return std::numeric_limits<double>::infinity(); }

  /// Constraints that belong to the body's parametrization (the Euler-parameter
  /// normalization of a rigid body); the System adds them with the body.
  virtual std::vector<std::unique_ptr<Constraint>> internal_constraints() const { return {}; }

 private:
  std::string name_;
  Index offset_ = 0;
};

}  // namespace seaflex
