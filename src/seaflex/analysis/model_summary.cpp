#include "seaflex/analysis/model_summary.hpp"

#include <fmt/format.h>

#include <cmath>
#include <iterator>

#include "seaflex/io/output_selection.hpp"

namespace seaflex::analysis {

std::string model_summary(const io::Model& model) {
  std::string text;
  auto out = std::back_inserter(text);
  const System& sys = *model.system;
  fmt::format_to(out, "model: {}{}\n", model.file,
                 model.title.empty() ? "" : " (" + model.title + ")");
  fmt::format_to(out, "bodies: {}\n", sys.bodies().size());
  for (const auto& b : sys.bodies())
    fmt::format_to(out, "  {} [{}]: {}\n", b->name(), b->kind(), b->summary());
  fmt::format_to(out, "constraints: {} ({} rows)\n", sys.constraints().size(),
                 sys.num_constraints());
  for (const auto& c : sys.constraints()) {
    std::string rows;
    for (Index r = 0; r < c->num_rows(); ++r) {
      // row names read "<constraint>: <label>"; show the label when they do
      const std::string row = c->row_name(r), prefix = c->name() + ": ";
      rows += (r ? ", " : "") + (row.starts_with(prefix) ? row.substr(prefix.size()) : row);
    }
    fmt::format_to(out, "  {}: {}\n", c->name(), rows);
  }
  fmt::format_to(out, "forces: {}\n", sys.forces().size());
  for (const auto& f : sys.forces()) fmt::format_to(out, "  {}\n", f->name());
  fmt::format_to(out, "gravity: ({:g}, {:g}, {:g}) m/s^2\n", model.gravity.x(), model.gravity.y(),
                 model.gravity.z());
  // the channels written: those the output section selects
  const std::size_t written = io::output_channels(model).size(),
                    all = io::model_channels(model).size();
  fmt::format_to(out, "coordinates: {}, constraint rows: {}, output channels: {}{}\n",
                 sys.num_coordinates(), sys.num_constraints(), written,
                 written < all ? fmt::format(" (of {}, as the output section selects)", all) : "");
  fmt::format_to(
      out,
      "statics: {} load step(s), tolerance {:g}, max {} iterations per step, loads at t = {:g} s\n",
      model.statics.load_steps, model.statics.tolerance, model.statics.max_iterations,
      model.statics.time);
  if (model.dynamics) {
    const auto& d = *model.dynamics;
    fmt::format_to(
        out,
        "dynamics: {}, time step {:g} s{}, duration {:g} s ({} steps), output every {:g} s, "
        "start from {}\n",
        d.integrator, d.time_step,
        d.adaptive ? fmt::format(" (adaptive, down to {:g} s)",
                                 d.min_time_step > 0 ? d.min_time_step : d.time_step / 1024)
                   : "",
        d.duration, std::lround(d.duration / d.time_step), d.output_interval,
        d.start_from_statics ? "static equilibrium" : "the model's initial state");
  } else {
    fmt::format_to(out, "dynamics: none (add a dynamics section to use 'seaflex run')\n");
  }
  return text;
}

}  // namespace seaflex::analysis
