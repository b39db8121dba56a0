// A sink for output rows: one value per channel at each output time, with the state the
// values were computed from (for recorders that derive their own results from it: beam
// results along the length, node positions, VTK frames).
#pragma once

#include <span>
#include <string>
#include <vector>

#include "seaflex/core/checkpoint.hpp"
#include "seaflex/model/state.hpp"

namespace seaflex {

class Recorder {
 public:
  virtual ~Recorder() = default;
  /// Called once with the channel names, before the first row.
  virtual void begin(const std::vector<std::string>& channels) = 0;
  /// One output row at state.t: values[i] is channel i; state is complete (multipliers
  /// included) and valid only during the call.
  virtual void record(const State& state, std::span<const double> values) = 0;
  /// Every step the Simulation accepts between two output rows (the rows themselves go to
  /// record()), for recorders that keep extremes over every step (the beam envelopes,
  /// unless `output.envelope_sampling: rows`). state is valid only during the call; its
  /// multipliers are the integrator's, not brought up to date as for a row. Nothing by
  /// default.
  virtual void observe_step(const State& /*state*/) {}
  /// Makes every recorded row durable (called on failure and at the end).
  virtual void flush() = 0;

  /// Restart files: after a flush, writes the recorder's position (file sizes, running
  /// envelopes) under prefix; false when it cannot continue a run (a run with such a
  /// recorder cannot be checkpointed).
  virtual bool save(CheckpointWriter& /*out*/, const std::string& /*prefix*/) const {
    return false;
  }
  /// Continues a saved run: cuts its files back to the saved position and appends from
  /// there; begin() then writes no header. For recorders built in resume mode.
  virtual void restore(const CheckpointReader& /*in*/, const std::string& /*prefix*/) {}
};

}  // namespace seaflex
