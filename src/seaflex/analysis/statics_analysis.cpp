#include "seaflex/analysis/statics_analysis.hpp"

#include <fmt/format.h>

#include "seaflex/analysis/result_files.hpp"
#include "seaflex/core/errors.hpp"
#include "seaflex/core/interrupt.hpp"
#include "seaflex/io/output_selection.hpp"

namespace seaflex::analysis {

namespace {

// the last converged increment into statics_partial.* and the caller's recorders
void keep_partial(const io::Model& model, const AnalysisOutput& output, const AnalysisHooks& hooks,
                  const State& state) {
  write_row(output.statics, io::output_channels(model), state);
  if (!output.dir) return;
  ResultFiles partial(model, *output.dir, "statics_partial", false);
  partial.write_row(io::output_channels(model), state);
  if (hooks.note)
    hooks.note(fmt::format("the last converged statics increment is in {}", partial.names()));
}

}  // namespace

void write_row(const std::vector<Recorder*>& recorders, const ChannelList& channels,
               const State& state) {
  if (recorders.empty()) return;
  std::vector<std::string> names;
  std::vector<double> values;
  for (const auto& c : channels) {
    names.push_back(c.name);
    values.push_back(c.value(state));
  }
  for (Recorder* r : recorders) {
    r->begin(names);
    r->record(state, values);
    r->flush();
  }
}

State run_statics(const io::Model& model, const AnalysisOutput& output,
                  const AnalysisHooks& hooks) {
  State state = model.system->initial_state();
  StaticsReport report;
  const ScopedInterruptPolling polling;  // a signal stops statics after its increment
  try {
    report = solve_statics(*model.system, state, model.statics, hooks.statics_increment);
  } catch (const SolverError&) {
    keep_partial(model, output, hooks, state);
    throw;
  } catch (const Interrupted&) {  // SIGINT/SIGTERM: keep the last converged increment
    keep_partial(model, output, hooks, state);
    throw;
  }
  std::string design_summary, names;
  if (output.dir) {
    ResultFiles files(model, *output.dir, "statics", false);
    files.write_row(io::output_channels(model), state);
    design_summary = files.design_summary();
    names = files.names();
  }
  write_row(output.statics, io::output_channels(model), state);
  if (hooks.statics_done) hooks.statics_done(report, design_summary);
  // a signal during the last increment: statics are complete and written; stop here
  if (const int sig = interrupt_signal(); sig != 0)
    throw Interrupted(sig, output.dir ? fmt::format("after statics (written to {})", names)
                                      : std::string("after statics"));
  return state;
}

}  // namespace seaflex::analysis
