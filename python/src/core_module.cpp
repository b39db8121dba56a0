// seaflex._core: the pybind11 extension under the Python package seaflex (python/seaflex/,
// docs/python.md). It loads models with the command line's loader and runs them with the
// command line's analyses (src/seaflex/analysis/), recording in memory; the package's
// pure-Python layer turns the outcome into results and exceptions. Errors do not cross as
// C++ exceptions: each call returns (value, kind, message[, python exception]) with kind
// one of "", "input", "model", "solver", "output", "interrupted", "error", so that the
// Python layer can attach the results computed up to a failure to its exception.
// Runs release the GIL; the progress hook takes it back at every output row, calls the
// Python callback and checks for signals (KeyboardInterrupt), and stops the run after its
// current step (core/interrupt.hpp) when either raised.
#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <yaml-cpp/yaml.h>

#include <atomic>
#include <csignal>
#include <cstdlib>
#include <memory>
#include <optional>
#include <regex>
#include <thread>

#include "seaflex/analysis/dynamics_analysis.hpp"
#include "seaflex/analysis/memory_recorder.hpp"
#include "seaflex/analysis/model_summary.hpp"
#include "seaflex/analysis/result_files.hpp"
#include "seaflex/analysis/statics_analysis.hpp"
#include "seaflex/core/errors.hpp"
#include "seaflex/core/input_file.hpp"
#include "seaflex/core/interrupt.hpp"
#include "seaflex/core/output_file.hpp"
#include "seaflex/core/parallel.hpp"
#include "seaflex/io/model_loader.hpp"
#include "seaflex/io/output_selection.hpp"
#include "seaflex/io/yaml_reader.hpp"
#include "seaflex/post/mode_shapes.hpp"
#include "seaflex/post/statistics.hpp"
#include "seaflex/solvers/modal.hpp"

namespace py = pybind11;
using namespace seaflex;

namespace {

// analyses running now (in any Python thread): the thread count must not change under them
std::atomic<int> g_running{0};
// a loaded model, shared by the results that refer to its beams; busy while an analysis
// runs on it (its system's workspaces serve one analysis at a time)
struct CoreModel {
  io::Model model;
  std::atomic<bool> busy{false};
};

// the warning of statics that found an unstable equilibrium, into this call's own list
// (returned with its results: another thread may run the same model once this one is done)
void keep_stability_warning(const io::Model& model, std::vector<std::string>& warnings,
                            analysis::AnalysisHooks& hooks) {
  hooks.statics_done = [&model, &warnings](const StaticsReport& rep, const std::string&) {
    if (std::string w = describe_instability(*model.system, rep.stability); !w.empty())
      warnings.push_back("statics: " + w);
  };
}

// an analysis running on a model (with the GIL released)
class Running {
 public:
  explicit Running(CoreModel& core) : core_(core) {
    if (core_.busy.exchange(true))
      throw std::logic_error(
          "this model is running an analysis in another thread; run a copy (model.copy())");
    ++g_running;
  }
  ~Running() {
    --g_running;
    core_.busy = false;
  }
  Running(const Running&) = delete;
  Running& operator=(const Running&) = delete;

 private:
  CoreModel& core_;
};

using Recorded = analysis::MemoryRecorder;

// (kind, message) of the exception in flight, as the command line reports it (its exit code
// in the comment)
std::pair<std::string, std::string> classify() {
  try {
    throw;
  } catch (const InputError& e) {  // 2
    return {"input", e.what()};
  } catch (const ModelError& e) {  // 2
    return {"model", e.what()};
  } catch (const SolverError& e) {  // 3
    return {"solver", e.what()};
  } catch (const OutputError& e) {  // 3
    return {"output", e.what()};
  } catch (const Interrupted& e) {  // 128 + signal
    return {"interrupted", e.what()};
  } catch (const std::logic_error& e) {  // a misuse of the Python API
    return {"usage", e.what()};
  } catch (const std::exception& e) {  // 2
    return {"error", e.what()};
  }
}

// YAML (the loader's parser) to Python: mappings to dicts in file order, sequences to
// lists, plain scalars resolved as the YAML 1.2 core schema does (null, bool, int, float),
// quoted scalars to str
const std::regex kInt(R"([-+]?[0-9]+)");
const std::regex kFloat(R"([-+]?(\.[0-9]+|[0-9]+(\.[0-9]*)?)([eE][-+]?[0-9]+)?)");
const std::regex kInf(R"([-+]?\.(inf|Inf|INF))");
const std::regex kNan(R"(\.(nan|NaN|NAN))");

py::object to_python(const YAML::Node& node) {
  switch (node.Type()) {
    case YAML::NodeType::Map: {
      py::dict d;
      for (const auto& kv : node) d[py::str(kv.first.Scalar())] = to_python(kv.second);
      return d;
    }
    case YAML::NodeType::Sequence: {
      py::list l;
      for (const auto& item : node) l.append(to_python(item));
      return l;
    }
    case YAML::NodeType::Scalar: {
      const std::string& s = node.Scalar();
      if (node.Tag() != "?") return py::str(s);  // quoted (tag "!") or explicitly tagged
      if (s == "null" || s == "Null" || s == "NULL" || s == "~" || s.empty()) return py::none();
      if (s == "true" || s == "True" || s == "TRUE") return py::bool_(true);
      if (s == "false" || s == "False" || s == "FALSE") return py::bool_(false);
      if (std::regex_match(s, kInt))
        return py::reinterpret_steal<py::object>(PyLong_FromString(s.c_str(), nullptr, 10));
      if (std::regex_match(s, kFloat)) return py::float_(std::strtod(s.c_str(), nullptr));
      if (std::regex_match(s, kInf)) return py::float_(s[0] == '-' ? -INFINITY : INFINITY);
      if (std::regex_match(s, kNan)) return py::float_(NAN);
      return py::str(s);
    }
    default:
      return py::none();
  }
}

// a view of v (no copy) kept alive by owner
py::array view(const std::vector<double>& v, py::handle owner) {
  py::array a(py::dtype::of<double>(), {static_cast<py::ssize_t>(v.size())}, {sizeof(double)},
              v.data(), owner);
  py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return a;
}

// the beams whose results along the length are kept at every row: those the files hold
// (output.beam_results: all), unless the caller asked for the channels only
std::vector<post::BeamResults> output_beam_results(const io::Model& model, bool keep) {
  std::vector<post::BeamResults> list;
  if (!keep || model.output.beam_results != io::OutputSettings::BeamResults::kAll) return list;
  for (const AncfBeam* b : io::output_beams(model))
    list.emplace_back(*b, io::pipe_pressure(model, *b), model.output.beam_gauss_points);
  return list;
}

py::tuple load(const std::string& text, const std::string& name) {
  try {
    auto core = std::make_shared<CoreModel>();
    core->model = io::load_model_text(text, name);
    return py::make_tuple(core, "", "");
  } catch (...) {
    const auto [kind, message] = classify();
    return py::make_tuple(py::none(), kind, message);
  }
}

// the file's text as the command line reads it (a regular file of bounded size)
py::tuple read_model_file(const std::string& path) {
  try {
    return py::make_tuple(read_input_file(path, "model file", kMaxModelFileBytes), "", "");
  } catch (...) {
    const auto [kind, message] = classify();
    return py::make_tuple(py::none(), kind, message);
  }
}

py::object yaml_to_python(const std::string& text, const std::string& name) {
  return to_python(io::parse_document(text, name));
}

// The progress hook of a run with the GIL released: at every output row (statics: every
// increment) it takes the GIL, calls progress(t, duration), checks for signals, and on an
// exception from either keeps it and stops the analysis after its current step.
struct PythonHook {
  py::object progress;
  std::optional<py::error_already_set> pending;

  void operator()(double t, double duration) {
    py::gil_scoped_acquire acquire;
    if (pending) return;
    try {
      if (!progress.is_none()) progress(t, duration);
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    } catch (py::error_already_set& e) {
      pending.emplace(std::move(e));
      set_interrupt_signal(SIGINT);
    }
  }
  // the kept Python exception (or None); clears the stop request
  py::object take() {
    if (!pending) return py::none();
    set_interrupt_signal(0);
    py::object value = py::reinterpret_borrow<py::object>(pending->value());
    pending.reset();
    return value;
  }
};

// statics (and their files in output_dir, when given): (recorded, kind, message, exception)
py::tuple statics(std::shared_ptr<CoreModel> core, std::optional<std::string> output_dir,
                  py::object progress, bool beams) {
  const io::Model& model = core->model;
  auto recorded = std::make_shared<Recorded>(output_beam_results(model, beams), 1);
  PythonHook hook{std::move(progress), {}};
  std::string kind, message;
  std::vector<std::string> warnings;
  {
    py::gil_scoped_release release;
    try {
      const Running running(*core);
      analysis::AnalysisOutput output;
      if (output_dir) {
        output.dir = *output_dir;
        analysis::make_output_dir(*output.dir);
        analysis::clear_results(model, *output.dir);
      }
      output.statics.push_back(recorded.get());
      analysis::AnalysisHooks hooks;
      hooks.statics_increment = [&](double factor, int, const StaticsReport&) {
        hook(factor, 1.0);
      };
      keep_stability_warning(model, warnings, hooks);
      analysis::run_statics(model, output, hooks);
    } catch (...) {
      std::tie(kind, message) = classify();
    }
  }
  py::object exc = hook.take();
  return py::make_tuple(recorded, kind, message, exc, warnings);
}

py::dict report_dict(const SimulationReport& r) {
  py::dict d;
  d["steps"] = r.steps;
  d["rejected_steps"] = r.rejected_steps;
  d["floor_steps_above_tolerance"] = r.floor_steps_above_tolerance;
  d["iterations"] = r.iterations;
  d["rows"] = r.rows;
  d["end_time"] = r.end_time;
  d["max_constraint_violation"] = r.max_constraint_violation;
  d["min_step"] = r.min_step;
  return d;
}

// a run (and its files in output_dir, when given): (statics recorded or None, recorded,
// report or None, kind, message, exception)
py::tuple run(std::shared_ptr<CoreModel> core, std::optional<std::string> output_dir,
              py::object progress, bool beams) {
  const io::Model& model = core->model;
  long rows = 0;
  if (model.dynamics) {
    const auto& d = *model.dynamics;
    const double interval = d.output_interval > 0 ? d.output_interval : d.time_step;
    rows = std::lround(d.duration / interval) + 1;
  }
  std::shared_ptr<Recorded> statics_recorded;
  if (model.dynamics && model.dynamics->start_from_statics)
    statics_recorded = std::make_shared<Recorded>(output_beam_results(model, beams), 1);
  auto recorded = std::make_shared<Recorded>(output_beam_results(model, beams), rows);
  PythonHook hook{std::move(progress), {}};
  std::string kind, message;
  std::optional<analysis::RunSummary> summary;
  std::vector<std::string> warnings;
  {
    py::gil_scoped_release release;
    try {
      const Running running(*core);
      analysis::AnalysisOutput output;
      if (output_dir) {
        output.dir = *output_dir;
        analysis::make_output_dir(*output.dir);
        analysis::clear_results(model, *output.dir);
      }
      if (statics_recorded) output.statics.push_back(statics_recorded.get());
      output.timeseries.push_back(recorded.get());
      analysis::AnalysisHooks hooks;
      hooks.statics_increment = [&](double, int, const StaticsReport&) {
        hook(0.0, model.dynamics->duration);
      };
      hooks.progress = [&](double t, double duration) { hook(t, duration); };
      keep_stability_warning(model, warnings, hooks);
      summary = analysis::run_dynamics(model, output, hooks);
    } catch (...) {
      std::tie(kind, message) = classify();
    }
  }
  py::object exc = hook.take();
  return py::make_tuple(statics_recorded ? py::cast(statics_recorded) : py::none(), recorded,
                        summary ? py::object(report_dict(summary->report)) : py::none(), kind,
                        message, exc, warnings);
}

// natural frequencies about statics (or the initial state): (dict, kind, message, exception)
py::tuple modes(std::shared_ptr<CoreModel> core, int count, bool about_initial) {
  const io::Model& model = core->model;
  PythonHook hook{py::none(), {}};
  std::string kind, message;
  std::optional<ModalResult> result;
  State state;
  std::vector<std::string> warnings;
  {
    py::gil_scoped_release release;
    try {
      const Running running(*core);
      analysis::AnalysisHooks hooks;
      hooks.statics_increment = [&](double factor, int, const StaticsReport&) {
        hook(factor, 1.0);
      };
      keep_stability_warning(model, warnings, hooks);
      state = about_initial ? model.system->initial_state()
                            : analysis::run_statics(model, analysis::AnalysisOutput{}, hooks);
      result = solve_modes(*model.system, state, count);
      if (std::string w = describe_unstable_modes(result->unstable, result->lowest_omega2);
          !w.empty())
        warnings.push_back("modes: " + w);
    } catch (...) {
      std::tie(kind, message) = classify();
    }
  }
  py::object exc = hook.take();
  if (!result) return py::make_tuple(py::none(), kind, message, exc, warnings);
  const ModalResult& m = *result;
  const auto n = static_cast<py::ssize_t>(m.omega.size());
  py::array_t<double> f(n), period(n), omega(n), share(n);
  py::list dominant;
  py::array_t<double, py::array::f_style> shapes({m.shapes.rows(), m.shapes.cols()});
  std::copy(m.shapes.data(), m.shapes.data() + m.shapes.size(), shapes.mutable_data());
  for (py::ssize_t k = 0; k < n; ++k) {
    f.mutable_at(k) = m.frequency_hz[k];
    period.mutable_at(k) = m.frequency_hz[k] > 0 ? 1.0 / m.frequency_hz[k] : INFINITY;
    omega.mutable_at(k) = m.omega[k];
    const auto dom = post::dominant_coordinate(m.shapes.col(k), m.mass_shapes.col(k));
    dominant.append(model.system->coordinate_name(dom.index));
    share.mutable_at(k) = dom.share;
  }
  py::list coordinates;
  for (Index i = 0; i < model.system->num_coordinates(); ++i)
    coordinates.append(model.system->coordinate_name(i));
  py::dict d;
  d["unstable"] = m.unstable;
  d["frequency_hz"] = f;
  d["period_s"] = period;
  d["omega_rad_s"] = omega;
  d["dominant_coordinate"] = dominant;
  d["energy_share"] = share;
  d["shapes"] = shapes;
  d["coordinates"] = coordinates;
  return py::make_tuple(d, kind, message, exc, warnings);
}

// the statistics of one record (post/statistics.hpp) over the rows from from_row on, as
// the statistics recorder accumulates them for statistics.csv
py::dict record_statistics(py::array_t<double, py::array::forcecast> t,
                           py::array_t<double, py::array::forcecast> x, py::ssize_t from_row) {
  if (t.ndim() != 1 || x.ndim() != 1 || t.shape(0) != x.shape(0))
    throw py::value_error("time and values must be 1-d arrays of the same length");
  post::StatisticsAccumulator a;
  const auto tv = t.unchecked<1>();
  const auto xv = x.unchecked<1>();
  for (py::ssize_t i = std::max<py::ssize_t>(0, from_row); i < t.shape(0); ++i) a.add(tv(i), xv(i));
  const post::RecordStatistics r = a.result();
  py::dict d;
  d["count"] = r.count;
  d["duration"] = r.duration;
  d["min"] = r.min;
  d["max"] = r.max;
  d["mean"] = r.mean;
  d["std"] = r.std;
  d["skewness"] = r.skewness;
  d["kurtosis"] = r.kurtosis;
  d["up_crossings"] = r.up_crossings;
  d["period"] = r.period;
  d["peaks"] = r.peaks;
  return d;
}

}  // namespace

PYBIND11_MODULE(_core, m) {
  m.doc() = "seaflex's C++ engine (use the package seaflex, not this module)";
  py::class_<CoreModel, std::shared_ptr<CoreModel>>(m, "CoreModel")
      .def("summary", [](const CoreModel& c) { return analysis::model_summary(c.model); })
      .def_property_readonly("warnings", [](const CoreModel& c) { return c.model.warnings; })
      .def_property_readonly("file", [](const CoreModel& c) { return c.model.file; })
      .def_property_readonly("channels",
                             [](const CoreModel& c) {
                               std::vector<std::string> names;
                               for (const auto& ch : io::output_channels(c.model))
                                 names.push_back(ch.name);
                               return names;
                             })
      .def_property_readonly("output_interval",
                             [](const CoreModel& c) {
                               if (!c.model.dynamics) return 0.0;
                               const auto& d = *c.model.dynamics;
                               return d.output_interval > 0 ? d.output_interval : d.time_step;
                             })
      .def_property_readonly("has_dynamics",
                             [](const CoreModel& c) { return c.model.dynamics.has_value(); })
      .def("describe_files",
           [](const CoreModel& c, const std::string& dir, const std::string& stem) {
             return analysis::ResultFiles::describe(c.model, dir, stem);
           });
  py::class_<Recorded, std::shared_ptr<Recorded>>(m, "Recorded")
      .def_property_readonly("channels", &Recorded::channels)
      .def_property_readonly("rows", &Recorded::rows)
      .def_property_readonly(
          "time", [](py::object self) { return view(self.cast<const Recorded&>().time(), self); })
      .def("column",
           [](py::object self, std::size_t k) {
             return view(self.cast<const Recorded&>().column(k), self);
           })
      .def_property_readonly("beam_names",
                             [](const Recorded& r) {
                               std::vector<std::string> names;
                               for (const auto& b : r.beams()) names.push_back(b.name);
                               return names;
                             })
      .def_property_readonly_static("beam_quantities",
                                    [](py::object) {
                                      std::vector<std::string> names;
                                      for (const auto& q : post::beam_quantities())
                                        names.emplace_back(q.name);
                                      return names;
                                    })
      .def("beam_stations",
           [](const Recorded& r, std::size_t k) {
             const auto& st = r.beams().at(k).results.stations();
             py::dict d;
             std::vector<double> s, xi;
             std::vector<int> element, node;
             for (const auto& p : st) {
               s.push_back(p.s);
               xi.push_back(p.xi);
               element.push_back(p.element);
               node.push_back(p.node);
             }
             d["s"] = py::array(py::cast(s));
             d["xi"] = py::array(py::cast(xi));
             d["element"] = py::array(py::cast(element));
             d["node"] = py::array(py::cast(node));
             return d;
           })
      // quantity q of beam k: (rows, stations), a strided view of the recorded values
      .def("beam_values", [](py::object self, std::size_t k, std::size_t q) {
        const Recorded& r = self.cast<const Recorded&>();
        const auto& b = r.beams().at(k);
        const auto stations = static_cast<py::ssize_t>(b.results.num_stations());
        const py::ssize_t count = post::kBeamQuantityCount;
        if (q >= static_cast<std::size_t>(count)) throw py::index_error("no such quantity");
        py::array a(py::dtype::of<double>(), {static_cast<py::ssize_t>(r.rows()), stations},
                    {static_cast<py::ssize_t>(sizeof(double)) * count * stations,
                     static_cast<py::ssize_t>(sizeof(double))},
                    b.values.data() + static_cast<py::ssize_t>(q) * stations, self);
        py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
        return a;
      });
  m.def("set_threads", [](int n) {
    if (g_running > 0)
      throw py::value_error("the thread count cannot change while an analysis runs");
    const int hw = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    if (n < 1 || n > hw)
      throw py::value_error(fmt::format(
          "threads must be a whole number from 1 to {} (the hardware threads of this machine), "
          "got {}",
          hw, n));
    set_threads(n);
  });
  m.def("threads", [] { return threads(); });
  m.def("load", &load, py::arg("text"), py::arg("name"));
  m.def("read_model_file", &read_model_file, py::arg("path"));
  m.def("yaml_to_python", &yaml_to_python, py::arg("text"), py::arg("name"));
  m.def("suggestion", [](const std::string& name, const std::vector<std::string>& candidates) {
    return io::suggestion(name, candidates);
  });
  m.def("statics", &statics, py::arg("model"), py::arg("output_dir"), py::arg("progress"),
        py::arg("beams"));
  m.def("run", &run, py::arg("model"), py::arg("output_dir"), py::arg("progress"),
        py::arg("beams"));
  m.def("record_statistics", &record_statistics, py::arg("time"), py::arg("values"),
        py::arg("from_row"));
  m.def("modes", &modes, py::arg("model"), py::arg("count"), py::arg("about_initial"));
}
