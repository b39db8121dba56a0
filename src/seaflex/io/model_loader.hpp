// Reads a YAML model file (format: docs/model-format.md) into a finalized System plus
// the analysis settings. Every problem in the file is reported at once, as an
// InputError naming file, line, column and key.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "seaflex/hydro/ocean.hpp"
#include "seaflex/integrators/integrator.hpp"
#include "seaflex/simulation/simulation.hpp"
#include "seaflex/solvers/statics.hpp"
#include "seaflex/system/system.hpp"

namespace seaflex::io {

struct DynamicsSettings {
  std::string integrator;
  double time_step = 0.0;        ///< s
  double duration = 0.0;         ///< s
  double output_interval = 0.0;  ///< s, a whole number of steps
  bool start_from_statics = false;
  bool adaptive = false;       ///< step_control: adaptive
  double min_time_step = 0.0;  ///< s; 0: time_step / 1024
  std::function<std::unique_ptr<Integrator>()> make_integrator;
  int line = 0;  ///< line of the dynamics section, for messages

  /// The time loop's settings.
  SimulationSettings simulation() const {
    SimulationSettings s{duration, time_step, output_interval};
    s.step_control = adaptive ? StepControl::kAdaptive : StepControl::kFixed;
    s.min_time_step = min_time_step;
    return s;
  }
};

struct Model {
  std::string file;
  std::string title;
  std::unique_ptr<System> system;
  Vec3 gravity = Vec3::Zero();
  /// The sea (environment.water, waves, current); null when the model has no water.
  std::shared_ptr<const hydro::Ocean> ocean;
  /// Notes for the user that do not stop the run (a wave frequency outside a BEM range).
  std::vector<std::string> warnings;
  /// Wave elevation outputs: channel name and the point (x, y) where it is taken.
  std::vector<std::pair<std::string, Vec3>> wave_probes;
  StaticsSettings statics;
  std::optional<DynamicsSettings> dynamics;
};

/// The system's channels followed by the model's own (wave elevation probes).
ChannelList model_channels(const Model& model);

/// Loads and validates a model file. Throws InputError listing every problem.
Model load_model_file(const std::string& path);
/// Same from text; name stands for the file in messages.
Model load_model_text(const std::string& text, const std::string& name);

}  // namespace seaflex::io
