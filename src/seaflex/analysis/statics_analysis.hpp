// Static equilibrium of a model as `seaflex statics` and `seaflex run` compute it: the
// solve (solvers/statics.hpp) from the model's initial state, the statics row written to
// the result files and the caller's recorders; on failure or interruption the last
// converged increment goes to statics_partial.* (and the caller's recorders) before the
// error propagates.
#pragma once

#include "seaflex/analysis/analysis_options.hpp"
#include "seaflex/io/model_loader.hpp"

namespace seaflex::analysis {

/// The equilibrium state. Throws SolverError (no convergence), Interrupted (a signal:
/// after the increment it ends, or after statics complete and written), OutputError.
State run_statics(const io::Model& model, const AnalysisOutput& output,
                  const AnalysisHooks& hooks = {});

/// One row of the channels at state into each recorder: begin, record, flush.
void write_row(const std::vector<Recorder*>& recorders, const ChannelList& channels,
               const State& state);

}  // namespace seaflex::analysis
