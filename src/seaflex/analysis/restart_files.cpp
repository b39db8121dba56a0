#include "seaflex/analysis/restart_files.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "seaflex/core/checkpoint.hpp"
#include "seaflex/core/errors.hpp"
#include "seaflex/core/input_file.hpp"
#include "seaflex/io/model_inputs.hpp"

namespace fs = std::filesystem;

namespace seaflex::analysis {

namespace {

// Restart files: paths as hex (a path with blanks stays one word).
std::string to_hex(const std::string& text) {
  std::string out;
  for (unsigned char c : text) out += fmt::format("{:02x}", c);
  return out;
}
// the text of `key`, written by to_hex; a located error for anything else
std::string from_hex(const CheckpointReader& in, const std::string& key) {
  const std::string hex = in.text(key);
  const auto digit = [](char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    return -1;
  };
  std::string out;
  for (std::size_t i = 0; i + 1 < hex.size(); i += 2) {
    const int hi = digit(hex[i]), lo = digit(hex[i + 1]);
    if (hi < 0 || lo < 0 || (hi == 0 && lo == 0)) break;
    out += static_cast<char>(hi * 16 + lo);
  }
  if (out.size() * 2 != hex.size() || out.empty())
    in.fail(key, "not a file name written by seaflex (pairs of lowercase hex digits)");
  return out;
}

// The files a checkpoint holds the hash of: the model, then every file it reads.
std::vector<std::pair<std::string, std::string>> input_hashes(const std::string& model) {
  std::vector<std::pair<std::string, std::string>> list;
  for (const auto& f : io::model_input_files(model))
    list.emplace_back(f, io::input_file_hash(f, "input file"));
  return list;
}

}  // namespace

void check_checkpointable(const io::Model& model, const std::string& file) {
  for (const auto& f : model.system->forces())
    if (f->has_memory())
      throw InputError({Diagnostic{file, 0, 0, "--checkpoint-every",
                                   fmt::format("restart files do not hold the memory of '{}' "
                                               "(radiation) yet; run without checkpoints",
                                               f->name())}});
  if (model.fatigue)
    throw InputError({Diagnostic{file, 0, 0, "--checkpoint-every",
                                 "restart files do not hold the rainflow counters of the fatigue "
                                 "section yet; run without checkpoints"}});
  if (model.output.format != io::OutputFormat::kCsv || model.output.vtk)
    throw InputError({Diagnostic{file, 0, 0, "--checkpoint-every",
                                 "restart files continue CSV results only; use --format csv "
                                 "and no VTK output with checkpoints"}});
}

long checkpoint_rows(const io::DynamicsSettings& d, double seconds, const std::string& file) {
  const double interval =
      d.simulation().output_interval > 0.0 ? d.simulation().output_interval : d.time_step;
  const double rows = seconds / interval;
  if (!(rows >= 1.0 - 1e-9) || std::abs(rows - std::round(rows)) > 1e-6 * rows)
    throw InputError(
        {Diagnostic{file, 0, 0, "--checkpoint-every",
                    fmt::format("must be a whole number of output intervals ({:g} s), got {:g} s",
                                interval, seconds)}});
  if (seconds > d.duration)
    throw InputError(
        {Diagnostic{file, 0, 0, "--checkpoint-every",
                    fmt::format("must not exceed the run's duration ({:g} s), got {:g} s",
                                d.duration, seconds)}});
  return std::lround(rows);
}

void enable_checkpoints(DynamicsRun& run, const std::string& file, const fs::path& dir, long rows,
                        std::function<double()> wall_s) {
  Integrator& integrator = run.integrator();
  ResultFiles& outputs = *run.files();
  const std::string model_path = fs::absolute(file).string();
  const std::string hash = io::input_file_hash(file, "model");
  const auto inputs = input_hashes(file);  // WAMIT files, tables: a resume needs the same
  run.simulation().set_checkpoint(
      rows, [=, &integrator, &outputs](const State& state, const SimulationPosition& pos) {
        CheckpointWriter w;
        w.put("format", std::string("seaflex-checkpoint-1"));
        w.put("model", to_hex(model_path));
        w.put("model_hash", hash);
        w.put("inputs", static_cast<long>(inputs.size()));
        for (std::size_t k = 0; k < inputs.size(); ++k) {
          w.put(fmt::format("input{}.file", k), to_hex(inputs[k].first));
          w.put(fmt::format("input{}.hash", k), inputs[k].second);
        }
        w.put("checkpoint_rows", rows);
        w.put("wall_s", wall_s ? wall_s() : 0.0);  // the whole run's, so far
        pos.save(w);
        w.put("state.t", state.t);
        w.put("state.q", state.q);
        w.put("state.v", state.v);
        w.put("state.lambda", state.lambda);
        w.put("state.z", state.z);
        if (!integrator.save(w) || !outputs.save_all(w))
          throw std::runtime_error("this run cannot be checkpointed");
        w.write((dir / "checkpoint.txt").string());
      });
}

std::unique_ptr<ResumedRun> read_checkpoint(
    const fs::path& dir, const std::function<io::Model(const std::string&)>& load) {
  const std::string path = (dir / "checkpoint.txt").string();
  const CheckpointReader in(path);
  const std::string file = from_hex(in, "model");
  {
    // a regular file of bounded size (not /dev/zero, a FIFO or a directory), unchanged
    std::error_code ec;
    const auto st = fs::status(file, ec);
    if (!fs::exists(st))
      in.fail("model",
              fmt::format("the model file {} is gone: a restart needs the same model", file));
    if (!fs::is_regular_file(st))
      in.fail("model", fmt::format("{} is not a regular file (a directory, device or pipe is not "
                                   "a model)",
                                   file));
    if (fs::file_size(file, ec) > io::kMaxInputFileBytes || ec)
      in.fail("model", fmt::format("{} has more than {} bytes", file, io::kMaxInputFileBytes));
    if (io::input_file_hash(file, "model") != in.text("model_hash"))
      in.fail("model", fmt::format("the model file {} changed since the checkpoint (or is gone): "
                                   "a restart needs the same model",
                                   file));
  }
  // every file the model reads, as at the checkpoint (a checkpoint of an older seaflex
  // without the list is refused: it could not tell)
  const long inputs = in.integer("inputs", 0, 100000);
  std::vector<std::string> recorded;
  for (long k = 0; k < inputs; ++k) {
    const std::string key = fmt::format("input{}.file", k);
    const std::string f = from_hex(in, key);
    const std::string hash = io::input_file_hash(f, key);
    if (hash != in.text(fmt::format("input{}.hash", k)))
      in.fail(key, fmt::format("the input file {} {} since the checkpoint: a restart needs the "
                               "same inputs",
                               f, hash == "absent" ? "is gone" : "changed"));
    recorded.push_back(f);
  }
  if (const auto now = io::model_input_files(file); now != recorded)
    for (const auto& f : now)
      if (std::find(recorded.begin(), recorded.end(), f) == recorded.end())
        in.fail("inputs", fmt::format("the model reads {}, which was not there at the checkpoint: "
                                      "a restart needs the same inputs",
                                      f));
  auto resumed = std::make_unique<ResumedRun>();
  resumed->file = file;
  resumed->model = load(file);
  const io::Model& model = resumed->model;
  if (!model.dynamics)
    throw InputError({Diagnostic{file, 0, 0, "dynamics", "the model has no dynamics section"}});
  check_checkpointable(model, file);
  const auto& d = *model.dynamics;
  // the time loop's position: bounded, so that a damaged file cannot run for ever
  const long nominal = std::lround(d.duration / d.time_step);
  in.integer("sim.ticks", 0, nominal << 20);  // at most 2^20 ticks per step (adaptive)
  in.integer("sim.level", 0, 20);
  in.integer("sim.successes", 0);
  in.integer("sim.rows", 1, nominal + 1);
  for (const char* key : {"sim.t0", "sim.scale", "state.t", "sim.min_step"}) in.finite(key);
  for (const char* key : {"sim.steps", "sim.rejected_steps", "sim.iterations"}) in.integer(key, 0);
  resumed->checkpoint_rows = in.integer("checkpoint_rows", 1, nominal);
  AnalysisOutput output;
  output.dir = dir;
  resumed->run = std::make_unique<DynamicsRun>(model, output, /*resume=*/true);
  DynamicsRun& run = *resumed->run;
  run.files()->restore_all(in);
  // the state: every vector the size this model needs
  const State initial = model.system->initial_state();
  State& state = resumed->state;
  state = initial;
  state.t = in.finite("state.t");
  state.q = in.vector("state.q", initial.q.size());
  state.v = in.vector("state.v", initial.v.size());
  state.lambda = in.vector("state.lambda", initial.lambda.size());
  state.z = in.vector("state.z", initial.z.size());
  try {
    run.integrator().restore(*model.system, in);
  } catch (const std::invalid_argument& e) {
    in.fail("", e.what());
  }
  resumed->position = SimulationPosition::load(in);
  resumed->wall_s = in.has("wall_s") ? in.finite("wall_s") : 0.0;
  return resumed;
}

}  // namespace seaflex::analysis
