#include "seaflex/simulation/simulation.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "seaflex/core/errors.hpp"

namespace seaflex {

namespace {
// Coordinate with the largest |v| (or the first non-finite q or v): the likeliest culprit.
Index worst_coordinate(const State& s) {
  for (Index i = 0; i < s.q.size(); ++i)
    if (!std::isfinite(s.q[i]) || !std::isfinite(s.v[i])) return i;
  Index worst = 0;
  if (s.v.size() > 0) s.v.cwiseAbs().maxCoeff(&worst);
  return worst;
}
}  // namespace

Simulation::Simulation(Dae& dae, ChannelList channels, Integrator& integrator,
                       SimulationSettings settings)
    : dae_(dae), channels_(std::move(channels)), integrator_(integrator), settings_(settings) {
  if (!(settings_.time_step > 0.0) || !(settings_.duration > 0.0))
    throw std::invalid_argument("Simulation: time step and duration must be positive");
  every_ = std::max(1L, std::lround(settings_.output_interval / settings_.time_step));
  row_.resize(channels_.size());
}

void Simulation::record(State& state) {
  if (dae_.num_constraints() > 0) integrator_.update_multipliers(dae_, state);  // reactions
  for (std::size_t i = 0; i < channels_.size(); ++i) row_[i] = channels_[i].value(state);
  for (Recorder* r : recorders_) r->record(state.t, row_);
  ++rows_;
}

SimulationReport Simulation::run(State& state) {
  std::vector<std::string> names;
  for (const auto& c : channels_) names.push_back(c.name);
  for (Recorder* r : recorders_) r->begin(names);

  const double t0 = state.t;
  const long steps = std::lround(settings_.duration / settings_.time_step);
  SimulationReport report;
  dae_.start(state);
  record(state);
  // state scale for the divergence test
  const double scale = std::max(1.0, state.q.lpNorm<Eigen::Infinity>());
  try {
    for (long k = 1; k <= steps; ++k) {
      const StepReport step = integrator_.step(dae_, state, settings_.time_step);
      state.t = t0 + static_cast<double>(k) * settings_.time_step;  // no drift in t
      report.steps = k;
      report.max_constraint_violation = std::max(report.max_constraint_violation, step.residual);
      if (!step.ok)
        throw SolverError(fmt::format("t = {:.6g} s: {} step failed: {}", state.t,
                                      integrator_.name(), step.message),
                          state.t);
      if (!state.q.allFinite() || !state.v.allFinite() ||
          state.q.lpNorm<Eigen::Infinity>() > 1e6 * scale) {
        const Index worst = worst_coordinate(state);
        throw SolverError(
            fmt::format("t = {:.6g} s: the solution diverged ({} at {} = {:.6g}, velocity "
                        "{:.6g}); the time step {:.3g} s is likely above the stability limit "
                        "of {} for this model (stiff elements, short elements) or a body is "
                        "unconstrained",
                        state.t, state.q.allFinite() && state.v.allFinite() ? "runaway" : "NaN/Inf",
                        dae_.coordinate_name(worst), state.q[worst], state.v[worst],
                        settings_.time_step, integrator_.name()),
            state.t);
      }
      dae_.accept_step(state);
      if (k % every_ == 0 || k == steps) {
        record(state);
        if (progress_) progress_(state.t - t0, settings_.duration);
      }
    }
  } catch (...) {
    for (Recorder* r : recorders_) r->flush();
    throw;
  }
  for (Recorder* r : recorders_) r->flush();
  report.rows = rows_;
  report.end_time = state.t;
  return report;
}

}  // namespace seaflex
