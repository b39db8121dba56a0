#include "seaflex/analysis/bench_run.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "seaflex/core/errors.hpp"
#include "seaflex/hydro/kinematics_timer.hpp"

namespace seaflex::analysis {

BenchReport bench_dynamics(const io::Model& model, double duration, const std::string& file) {
  using Clock = std::chrono::steady_clock;
  const auto seconds_since = [](Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
  };
  if (!model.dynamics)
    throw InputError({Diagnostic{
        file, 0, 0, "dynamics", "'seaflex bench' needs a dynamics section (time_step, duration)"}});
  io::DynamicsSettings d = *model.dynamics;
  if (duration / d.time_step > 2e9)  // the loader's limit on dynamics.duration
    throw InputError({Diagnostic{
        file, 0, 0, "--duration",
        fmt::format("{:g} s at a time step of {:g} s is {:.3g} steps, more than the limit of 2e9",
                    duration, d.time_step, duration / d.time_step)}});
  if (duration > 0.0)
    d.duration = std::max(d.time_step, std::round(duration / d.time_step) * d.time_step);
  BenchReport report;
  report.duration = d.duration;
  State state = model.system->initial_state();
  if (d.start_from_statics) {
    const auto t0 = Clock::now();
    report.statics = solve_statics(*model.system, state, model.statics);
    report.statics_wall_s = seconds_since(t0);
  }
  auto integrator = d.make_integrator();
  Simulation sim(*model.system, io::model_channels(model), *integrator, d.simulation());
  namespace kt = hydro::kinematics_timer;
  kt::reset();
  kt::enable(true);
  const auto t0 = Clock::now();
  try {
    report.run = sim.run(state);
  } catch (...) {
    kt::enable(false);
    throw;
  }
  report.wall_s = seconds_since(t0);
  kt::enable(false);
  report.wave_kinematics_s = kt::seconds();
  report.stats = integrator->stats();
  report.integrator = integrator->name();
  return report;
}

}  // namespace seaflex::analysis
