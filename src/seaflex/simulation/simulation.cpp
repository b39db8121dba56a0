#include "seaflex/simulation/simulation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "seaflex/core/errors.hpp"
#include "seaflex/core/interrupt.hpp"
#include "seaflex/simulation/growth_monitor.hpp"

namespace seaflex {

namespace {
// fixed steps: the largest estimated local error of a step, relative to 1 + |q_i|, that a
// run accepts (see loop())
constexpr double kFixedStepErrorLimit = 0.01;
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
  if (settings_.step_control == StepControl::kAdaptive) {
    const double h_min =
        settings_.min_time_step > 0.0 ? settings_.min_time_step : settings_.time_step / 1024.0;
    if (!(h_min <= settings_.time_step))
      throw std::invalid_argument("Simulation: min_time_step exceeds the time step");
    levels_ = std::clamp(static_cast<int>(std::ceil(std::log2(settings_.time_step / h_min) - 1e-9)),
                         0, 20);
    if (!(settings_.error_tolerance > 0.0))
      throw std::invalid_argument("Simulation: error_tolerance must be positive");
  }
  row_.resize(channels_.size());
}

void Simulation::record(State& state) {
  if (dae_.num_constraints() > 0) integrator_.update_multipliers(dae_, state);  // reactions
  {
    const ChannelRow row;  // the state does not change while the row's channels are read
    for (std::size_t i = 0; i < channels_.size(); ++i) row_[i] = channels_[i].value(state);
  }
  for (Recorder* r : recorders_) r->record(state, row_);
  ++rows_;
}

double Simulation::error_norm(const State& state, Index& worst) const {
  // Hairer, Norsett & Wanner, Solving ODEs I, sec. II.4, eq. (4.10), max norm, with
  // Atol = Rtol = error_tolerance
  const VecX& e = integrator_.local_error();
  double err = 0.0;
  worst = 0;
  for (Index i = 0; i < e.size(); ++i) {
    const double sc =
        settings_.error_tolerance * (1.0 + std::max(std::abs(saved_.q[i]), std::abs(state.q[i])));
    const double r = std::abs(e[i]) / sc;
    if (!(r <= err)) {  // NaN counts as the worst
      err = r;
      worst = i;
    }
  }
  return err;
}

void SimulationPosition::save(CheckpointWriter& out) const {
  out.put("sim.t0", t0);
  out.put("sim.ticks", ticks);
  out.put("sim.level", static_cast<long>(level));
  out.put("sim.successes", static_cast<long>(successes));
  out.put("sim.rows", rows);
  out.put("sim.scale", scale);
  out.put("sim.steps", report.steps);
  out.put("sim.rejected_steps", report.rejected_steps);
  out.put("sim.inaccurate_steps", report.inaccurate_steps);
  out.put("sim.floor_steps_above_tolerance", report.floor_steps_above_tolerance);
  out.put("sim.floor_worst_error", report.floor_worst_error);
  out.put("sim.iterations", report.iterations);
  out.put("sim.max_constraint_violation", report.max_constraint_violation);
  out.put("sim.min_step", report.min_step);
}

SimulationPosition SimulationPosition::load(const CheckpointReader& in) {
  SimulationPosition p;
  p.t0 = in.number("sim.t0");
  p.ticks = in.integer("sim.ticks");
  p.level = static_cast<int>(in.integer("sim.level"));
  p.successes = static_cast<int>(in.integer("sim.successes"));
  p.rows = in.integer("sim.rows");
  p.scale = in.number("sim.scale");
  p.report.steps = in.integer("sim.steps");
  p.report.rejected_steps = in.integer("sim.rejected_steps");
  // absent from checkpoints written before issue 22
  if (in.has("sim.inaccurate_steps"))
    p.report.inaccurate_steps = in.integer("sim.inaccurate_steps");
  // absent from checkpoints written before 2026-11-27
  if (in.has("sim.floor_steps_above_tolerance")) {
    p.report.floor_steps_above_tolerance = in.integer("sim.floor_steps_above_tolerance");
    p.report.floor_worst_error = in.number("sim.floor_worst_error");
  }
  p.report.iterations = in.integer("sim.iterations");
  p.report.max_constraint_violation = in.number("sim.max_constraint_violation");
  p.report.min_step = in.number("sim.min_step");
  return p;
}

SimulationReport Simulation::run(State& state) {
  SimulationPosition pos;
  pos.t0 = state.t;
  pos.scale = std::max(1.0, state.q.lpNorm<Eigen::Infinity>());
  pos.report.min_step = settings_.time_step;
  return loop(state, pos, true);
}

SimulationReport Simulation::resume(State& state, const SimulationPosition& position) {
  return loop(state, position, false);
}

SimulationReport Simulation::loop(State& state, SimulationPosition pos, bool fresh) {
  std::vector<std::string> names;
  for (const auto& c : channels_) names.push_back(c.name);
  for (Recorder* r : recorders_) r->begin(names);

  const double t0 = pos.t0;
  const long nominal = std::lround(settings_.duration / settings_.time_step);
  // time in ticks of h / 2^levels: a step at level l is 2^(levels - l) ticks
  const long per_step = 1L << levels_;
  const long total = nominal * per_step, out_ticks = every_ * per_step;
  const double tick = settings_.time_step / static_cast<double>(per_step);
  const bool adaptive = settings_.step_control == StepControl::kAdaptive;
  // adaptive: the order p of the integrator's local error estimate (0: none, only failed
  // steps are retried)
  const int order = adaptive ? integrator_.local_error_order() : 0;
  // largest step-size factor f = 0.9 err^(-1/p) from the last accepted step
  double factor = 0.0;
  SimulationReport& report = pos.report;
  rows_ = pos.rows;
  const double scale = pos.scale;  // for the divergence test
  GrowthMonitor growth;            // unbounded growth while still finite (growth_monitor.hpp)
  try {
    if (fresh) {
      dae_.start(state);
      integrator_.start(dae_, state);
      state.static_residual = VecX();  // used by the start only (model/state.hpp)
      record(state);
    }
    long& ticks = pos.ticks;
    int& level = pos.level;
    int& successes = pos.successes;
    while (ticks < total) {
      const long step_ticks = per_step >> level;
      const double h = static_cast<double>(step_ticks) * tick;
      if (adaptive) saved_ = state;
      const StepReport step = integrator_.step(dae_, state, h);
      ++steps_taken_;
      const double t_new = t0 + static_cast<double>(ticks + step_ticks) * tick;  // no drift
      std::string failure;
      if (!step.ok) {
        failure = fmt::format("t = {:.6g} s: {} step failed: {}", t_new, integrator_.name(),
                              step.message);
      } else if (!state.q.allFinite() || !state.v.allFinite() ||
                 state.q.lpNorm<Eigen::Infinity>() > 1e6 * scale) {
        const Index worst = worst_coordinate(state);
        failure = fmt::format(
            "t = {:.6g} s: the solution diverged ({} at {} = {:.6g}, velocity {:.6g}); the time "
            "step {:.3g} s is likely above the stability limit of {} for this model (stiff "
            "elements, short elements) or a body is unconstrained",
            t_new, state.q.allFinite() && state.v.allFinite() ? "runaway" : "NaN/Inf",
            dae_.coordinate_name(worst), state.q[worst], state.v[worst], h, integrator_.name());
      } else if (const auto g = growth.observe(state.v.norm())) {
        failure = fmt::format(
            "t = {:.6g} s: the solution grows without bound (the velocity norm grew by a factor "
            "{:.3g} per step over the last {} steps, now {:.3g}, largest at {}); the time step "
            "{:.3g} s is likely above the stability limit of {} for this model",
            t_new, *g, GrowthMonitor::kWindows * GrowthMonitor::kWindow, state.v.norm(),
            dae_.coordinate_name(worst_coordinate(state)), h, integrator_.name());
        if (integrator_.name() == "rk4") {
          // RK4 is stable for omega h < 2 sqrt(2); the growth per step tells which omega h
          const double wh = GrowthMonitor::rk4_omega_h(*g);
          failure += fmt::format(
              ": rk4 is stable for omega h < 2.83, and this growth is that of a mode of omega = "
              "{:.3g} rad/s ({:.3g} Hz, omega h = {:.3g}); use time_step < {:.3g} s or "
              "integrator: generalized_alpha",
              wh / h, wh / h / (2.0 * std::numbers::pi), wh, 2.0 * std::sqrt(2.0) * h / wh);
        }
      }
      // the step's accuracy: the local error estimate against the tolerance (file header)
      int shrink = 1;            // halvings for a retry
      bool inaccurate = false;   // rejected by the error estimate
      double floor_error = 0.0;  // the error estimate of a step taken above it at the floor
      // fixed steps: a step whose own error estimate is a sizeable part of the motion (an
      // impact taken in one step) is wrong, however well Newton converged. Not for RK4: a
      // step that long is far above its stability limit, which the divergence test and the
      // growth monitor report with their own advice.
      if (failure.empty() && !adaptive && integrator_.local_error_order() > 0 &&
          integrator_.name() != "rk4") {
        const VecX& e = integrator_.local_error();
        double worst_ratio = 0.0;
        Index worst = 0;
        for (Index i = 0; i < e.size(); ++i) {
          const double r = std::abs(e[i]) / (1.0 + std::abs(state.q[i]));
          if (!(r <= worst_ratio)) {
            worst_ratio = r;
            worst = i;
          }
        }
        if (!(worst_ratio <= kFixedStepErrorLimit))
          failure = fmt::format(
              "t = {:.6g} s: the step is far too long for the motion: its estimated local error "
              "is {:.3g} at {} = {:.6g} (more than {:g} x (1 + |q|)); an impact, a line going "
              "taut or slack, or a sudden load within one step; try step_control: adaptive or a "
              "shorter time_step",
              t_new, e[worst], dae_.coordinate_name(worst), state.q[worst], kFixedStepErrorLimit);
      }
      if (failure.empty() && order > 0) {
        Index worst = 0;
        const double err = error_norm(state, worst);
        // Hairer, Norsett & Wanner, Solving ODEs I, sec. II.4, eq. (4.13): fac = 0.9
        factor = err > 0.0 ? 0.9 * std::pow(err, -1.0 / order) : 1e300;
        // at the smallest step a step above the tolerance is still taken unless it is as wrong
        // as the fixed-step check allows (kFixedStepErrorLimit): a sudden load on a model out of
        // equilibrium (a riser started straight) excites modes no step resolves, which
        // generalized-alpha damps and the estimate still sees
        const bool at_floor = level >= levels_;
        floor_error = at_floor && !(err <= 1.0) ? err : 0.0;
        if (!(err <= 1.0) &&
            !(at_floor && err * settings_.error_tolerance <= kFixedStepErrorLimit)) {
          inaccurate = true;
          shrink = std::isfinite(factor) && factor > 0.0
                       ? std::clamp(static_cast<int>(std::ceil(-std::log2(factor))), 1, 4)
                       : 4;
          failure = fmt::format(
              "t = {:.6g} s: the estimated local error of the step, {:.3g} at {}, exceeds "
              "error_tolerance x (1 + |q|) = {:.3g} (error_tolerance {:g}): the motion changes "
              "too fast for the step (an impact, a line going taut){}",
              t_new, integrator_.local_error()[worst], dae_.coordinate_name(worst),
              settings_.error_tolerance *
                  (1.0 + std::max(std::abs(saved_.q[worst]), std::abs(state.q[worst]))),
              settings_.error_tolerance,
              at_floor ? fmt::format(", and at the smallest step it exceeds {:g} x (1 + |q|); "
                                     "lower min_time_step",
                                     kFixedStepErrorLimit)
                       : std::string());
        }
      }
      if (!failure.empty()) {
        if (adaptive && level < levels_) {         // retry from the saved state with h / 2^shrink
          if (step.ok) integrator_.reject_step();  // the integrator took the step: undo it
          state = saved_;
          growth.reset();
          level = std::min(levels_, level + shrink);
          successes = 0;
          ++report.rejected_steps;
          if (step.ok && inaccurate) ++report.inaccurate_steps;
          continue;
        }
        if (adaptive) failure += fmt::format(" (at the smallest time step, {:.3g} s)", h);
        throw SolverError(failure, t_new);
      }
      state.t = t_new;
      ticks += step_ticks;
      ++report.steps;
      if (floor_error > 0.0) {  // accepted at the smallest step above the tolerance: reported
        ++report.floor_steps_above_tolerance;
        report.floor_worst_error = std::max(report.floor_worst_error, floor_error);
      }
      report.iterations += step.iterations;
      report.min_step = std::min(report.min_step, h);
      report.max_constraint_violation = std::max(report.max_constraint_violation, step.residual);
      dae_.accept_step(state);
      // grow back once four steps passed, the error estimate allows a doubled step and the
      // doubled step stays on its own grid
      if (level > 0 && ++successes >= 4 && (order == 0 || factor >= 2.0) &&
          ticks % (step_ticks * 2) == 0) {
        --level;
        successes = 0;
      }
      if (ticks % out_ticks != 0 && ticks != total) {
        for (Recorder* r : recorders_) r->observe_step(state);  // between rows
      } else {
        record(state);
        if (progress_) progress_(state.t - t0, settings_.duration);
        if (checkpoint_ && checkpoint_every_ > 0 && (rows_ - 1) % checkpoint_every_ == 0 &&
            ticks < total) {
          pos.rows = rows_;
          checkpoint_(state, pos);
        }
      }
      // SIGINT/SIGTERM: stop after the completed step (the catch below flushes)
      if (const int sig = interrupt_signal(); sig != 0 && ticks < total)
        throw Interrupted(sig, state.t);
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
