// Reads a YAML model file (format: docs/model-format.md) into a finalized System plus
// the analysis settings. Every problem in the file is reported at once, as an
// InputError naming file, line, column and key.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "seaflex/hydro/ocean.hpp"
#include "seaflex/hydro/seabed.hpp"
#include "seaflex/integrators/integrator.hpp"
#include "seaflex/io/design_settings.hpp"
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
  bool adaptive = false;                                          ///< step_control: adaptive
  double min_time_step = 0.0;                                     ///< s; 0: time_step / 1024
  double error_tolerance = SimulationSettings{}.error_tolerance;  ///< adaptive
  std::function<std::unique_ptr<Integrator>()> make_integrator;
  int line = 0;  ///< line of the dynamics section, for messages

  /// The time loop's settings.
  SimulationSettings simulation() const {
    SimulationSettings s{duration, time_step, output_interval};
    s.step_control = adaptive ? StepControl::kAdaptive : StepControl::kFixed;
    s.min_time_step = min_time_step;
    s.error_tolerance = error_tolerance;
    return s;
  }
};

/// Which files `run` and `statics` write (docs/results-format.md).
enum class OutputFormat { kCsv, kHdf5, kBoth };

/// The model's `output` section (docs/model-format.md section 14).
struct OutputSettings {
  OutputFormat format = OutputFormat::kCsv;
  /// Channel name patterns (`*` any characters, `?` one); empty: every channel.
  std::vector<std::string> channels;
  /// Bodies whose channels, beam results and positions are written; empty: every body.
  std::vector<std::string> bodies;
  /// Beam results along the length: per output row and envelopes, or envelopes only.
  enum class BeamResults { kAll, kEnvelope, kNone } beam_results = BeamResults::kAll;
  /// The envelopes' minimum and maximum over every accepted step (true, the default) or
  /// over the output rows only (false); their mean is over the rows either way.
  bool envelope_steps = true;
  /// Result stations per element between the nodes (Gauss-Legendre points).
  int beam_gauss_points = 2;
  /// ParaView time series (vtk/ directory).
  bool vtk = false;
  /// Optional channels (io/optional_channels.hpp), written after all the others: beam
  /// node slopes r', support reactions, energies of each body, rigid-body angular
  /// velocity in body axes.
  bool node_slopes = false;
  bool support_reactions = false;
  bool energies = false;
  bool body_angular_velocity = false;
};

/// The model's `statistics` section (docs/model-format.md): statistics, extremes and
/// range graphs of a run (post/statistics.hpp, post/extremes.hpp).
struct StatisticsSettings {
  double start = 0.0;                   ///< s; rows before it (the build-up) are left out
  double storm_duration = 0.0;          ///< s; 0: the analysed duration
  double exceedance_probability = 0.1;  ///< of the storm maximum, for the extremes
  int blocks = 10;                      ///< blocks of the Gumbel fit of block maxima
  double k = 3.0;                       ///< range graphs: mean +- k sigma
};

struct Model {
  std::string file;
  std::string title;
  std::unique_ptr<System> system;
  Vec3 gravity = Vec3::Zero();
  /// The sea (environment.water, waves, current); null when the model has no water.
  std::shared_ptr<const hydro::Ocean> ocean;
  /// The seabed (environment.seabed); null without one.
  std::shared_ptr<const hydro::Seabed> seabed;
  /// Notes for the user that do not stop the run (a wave frequency outside a BEM range).
  std::vector<std::string> warnings;
  /// Wave elevation outputs: channel name and the point (x, y) where it is taken.
  std::vector<std::pair<std::string, Vec3>> wave_probes;
  StaticsSettings statics;
  std::optional<DynamicsSettings> dynamics;
  OutputSettings output;
  /// Statistics of a run; none without a statistics section.
  std::optional<StatisticsSettings> statistics;
  std::optional<FatigueSettings> fatigue;       ///< the fatigue section
  std::optional<CodeCheckSettings> code_check;  ///< the code_check section
};

/// The system's channels followed by the model's own (wave elevation probes), then the
/// optional channels that the output section asks for.
ChannelList model_channels(const Model& model);

/// Loads and validates a model file. Throws InputError listing every problem.
Model load_model_file(const std::string& path);
/// Same from text; name stands for the file in messages.
Model load_model_text(const std::string& text, const std::string& name);

}  // namespace seaflex::io
