// libFuzzer harness of the checkpoint reader (issue 22). Any bytes as checkpoint.txt: the
// reader must parse them or throw InputError; then every accessor on every key, and what
// `seaflex resume` reads against a fixed model (the state's sizes, the time loop's
// position, generalized-alpha's memory, the beam envelopes and the statistics, whose files
// are then written), must return a value or throw InputError (generalized-alpha's restore
// may also refuse with std::invalid_argument, which resume reports located, or find its
// restored matrix singular: SolverError). Never a crash, an out-of-bounds read, a hang, a
// leak or a huge allocation. Seeds: a checkpoint of the model below
// (fuzz/corpus/checkpoint/).
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>

#include "seaflex/core/checkpoint.hpp"
#include "seaflex/core/errors.hpp"
#include "seaflex/core/output_file.hpp"
#include "seaflex/io/beam_csv_recorder.hpp"
#include "seaflex/io/model_loader.hpp"
#include "seaflex/io/output_selection.hpp"
#include "seaflex/io/statistics_recorder.hpp"
#include "seaflex/simulation/simulation.hpp"

namespace {

// fuzz/corpus/checkpoint/model.yaml
constexpr const char* kModel = R"(
environment: {gravity: 9.81}
bodies:
  beam: {type: ancf_beam, start: [0, 0, 0], end: [10, 0, 0], elements: 2, area: 0.01,
         second_moment: 8.33e-6, youngs_modulus: 210e9, density: 7850}
supports:
  - {body: beam, node: start, type: clamped}
dynamics: {integrator: generalized_alpha, time_step: 0.01, duration: 0.1, output_interval: 0.01,
           initial_state: model}
statistics: {blocks: 2}
)";

const seaflex::io::Model& model() {
  static const seaflex::io::Model m = seaflex::io::load_model_text(kModel, "model.yaml");
  return m;
}

const std::filesystem::path& directory() {
  static const std::filesystem::path dir = [] {
    auto d = std::filesystem::temp_directory_path() /
             ("seaflex_fuzz_checkpoint_" + std::to_string(::getpid()));
    std::filesystem::create_directories(d);
    return d;
  }();
  return dir;
}

std::vector<seaflex::post::BeamResults> beam_results(const seaflex::io::Model& m) {
  std::vector<seaflex::post::BeamResults> list;
  for (const seaflex::AncfBeam* b : seaflex::io::output_beams(m))
    list.emplace_back(*b, seaflex::io::pipe_pressure(m, *b), m.output.beam_gauss_points);
  return list;
}

template <class F>
void accessor(F&& f) {
  try {
    f();
  } catch (const seaflex::InputError&) {
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace seaflex;
  std::optional<CheckpointReader> in;
  try {
    in.emplace(std::string(reinterpret_cast<const char*>(data), size), "checkpoint.txt");
  } catch (const InputError&) {
    return 0;
  }
  for (const std::string& key : in->keys()) {
    accessor([&] { in->text(key); });
    accessor([&] { in->number(key); });
    accessor([&] { in->finite(key); });
    accessor([&] { in->integer(key, 0, 1000); });
    accessor([&] { in->vector(key); });
    accessor([&] { in->vector(key, 7); });
    accessor([&] { in->matrix(key); });
    accessor([&] { in->matrix(key, 3, 16); });
  }
  const io::Model& m = model();
  const State initial = m.system->initial_state();
  accessor([&] {
    in->vector("state.q", initial.q.size());
    in->vector("state.v", initial.v.size());
    in->vector("state.lambda", initial.lambda.size());
    SimulationPosition::load(*in);
  });
  accessor([&] {
    auto integrator = m.dynamics->make_integrator();
    try {
      integrator->restore(*m.system, *in);
    } catch (const std::invalid_argument&) {
    } catch (const SolverError&) {
    }
  });
  accessor([&] {
    io::BeamCsvRecorder beams(directory(), "", beam_results(m), /*per_row=*/false,
                              /*envelope=*/true, /*resume=*/true);
    beams.restore(*in, "recorder1");
    beams.flush();  // the envelope of the restored tables
  });
  accessor([&] {
    io::StatisticsRecorder stats(directory(), *m.statistics, m.dynamics->duration,
                                 m.dynamics->output_interval, beam_results(m));
    stats.restore(*in, "recorder2");
    std::vector<std::string> names;  // as the simulation does before its first step
    for (const auto& c : io::output_channels(m)) names.push_back(c.name);
    stats.begin(names);
    stats.flush();  // statistics and extremes of the restored accumulators
  });
  return 0;
}
