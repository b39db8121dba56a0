// The model's `output` section: file format, channel patterns, bodies, beam results and
// the ParaView time series (docs/model-format.md section 14).
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

#include "seaflex/io/load_context.hpp"
#include "seaflex/io/output_selection.hpp"

namespace seaflex::io {

namespace {

// a list of scalars at key; each entry with its mark and key path
std::vector<std::tuple<std::string, YAML::Mark, std::string>> read_names(MapReader& r,
                                                                         std::string_view key,
                                                                         std::string_view what) {
  std::vector<std::tuple<std::string, YAML::Mark, std::string>> out;
  const YAML::Node n = r.get(key);
  if (!n.IsDefined()) return out;
  if (!n.IsSequence() || n.size() == 0) {
    r.error(key, fmt::format("expected a non-empty list of {}, got {}", what,
                             n.IsSequence() ? "an empty list" : describe(n)));
    return out;
  }
  for (std::size_t i = 0; i < n.size(); ++i) {
    const std::string path = fmt::format("{}[{}]", r.key_path(key), i);
    if (!n[i].IsScalar() || n[i].Scalar().empty()) {
      r.diagnostics().error(n[i].Mark(), path,
                            fmt::format("expected {}, got {}", what, describe(n[i])));
      continue;
    }
    out.emplace_back(n[i].Scalar(), n[i].Mark(), path);
  }
  return out;
}

}  // namespace

void load_output(const YAML::Node& node, LoadContext& ctx) {
  MapReader r(ctx.diag, node, "output");
  if (!r.valid()) return;
  OutputSettings& out = ctx.model.output;
  if (const auto f = r.choice("format", Need::kOptional, {"csv", "hdf5", "both"}))
    out.format = *f == "csv"    ? OutputFormat::kCsv
                 : *f == "hdf5" ? OutputFormat::kHdf5
                                : OutputFormat::kBoth;
  for (auto& [pattern, mark, path] : read_names(r, "channels", "channel names or patterns")) {
    out.channels.push_back(pattern);
    ctx.output_patterns.emplace_back(mark, path);
  }
  std::vector<std::string> names;
  for (const auto& b : ctx.system.bodies()) names.push_back(b->name());
  for (auto& [body, mark, path] : read_names(r, "bodies", "body names")) {
    const bool failed = std::find(ctx.failed_bodies.begin(), ctx.failed_bodies.end(), body) !=
                        ctx.failed_bodies.end();
    if (!failed && !ctx.system.find_body(body))
      ctx.diag.error(mark, path,
                     fmt::format("no body named '{}'; {}", body, suggestion(body, names)));
    else if (std::find(out.bodies.begin(), out.bodies.end(), body) != out.bodies.end())
      ctx.diag.error(mark, path, fmt::format("body '{}' is listed twice", body));
    else
      out.bodies.push_back(body);
  }
  if (const auto b = r.choice("beam_results", Need::kOptional, {"all", "envelope", "none"}))
    out.beam_results = *b == "all"        ? OutputSettings::BeamResults::kAll
                       : *b == "envelope" ? OutputSettings::BeamResults::kEnvelope
                                          : OutputSettings::BeamResults::kNone;
  if (r.has("envelope_sampling")) {
    out.envelope_steps =
        r.choice("envelope_sampling", Need::kRequired, {"rows", "steps"}) == "steps";
    if (out.envelope_steps && out.beam_results == OutputSettings::BeamResults::kNone)
      r.error("envelope_sampling",
              "'steps' samples the beams' envelopes, which beam_results: none leaves out; "
              "use beam_results: envelope or all, or remove envelope_sampling");
  }
  out.beam_gauss_points = r.integer("beam_gauss_points", Need::kOptional, 0, 10).value_or(2);
  if (r.has("vtk")) out.vtk = r.choice("vtk", Need::kRequired, {"true", "false"}) == "true";
  // optional channels (io/optional_channels.hpp)
  for (auto [key, flag] : {std::pair{"node_slopes", &out.node_slopes},
                           std::pair{"support_reactions", &out.support_reactions},
                           std::pair{"energies", &out.energies},
                           std::pair{"body_angular_velocity", &out.body_angular_velocity}})
    if (r.has(key)) *flag = r.choice(key, Need::kRequired, {"true", "false"}) == "true";
  r.finish();
}

void check_output(LoadContext& ctx) {
  if (ctx.output_patterns.empty()) return;
  const ChannelList channels = model_channels(ctx.model);
  const auto& patterns = ctx.model.output.channels;
  for (std::size_t i = 0; i < patterns.size() && i < ctx.output_patterns.size(); ++i) {
    const bool any = std::any_of(channels.begin(), channels.end(),
                                 [&](const Channel& c) { return glob_match(patterns[i], c.name); });
    if (any) continue;
    std::vector<std::string> names;
    for (const auto& c : channels) names.push_back(c.name);
    const std::string close = closest_match(patterns[i], names);
    const auto& [mark, path] = ctx.output_patterns[i];
    ctx.diag.error(mark, path,
                   close.empty()
                       ? fmt::format("'{}' matches no channel of the model; channels are named "
                                     "like {} (see 'seaflex check' and docs/model-format.md)",
                                     patterns[i], names.empty() ? "beam.n0.x" : names.front())
                       : fmt::format("'{}' matches no channel of the model; did you mean '{}'?",
                                     patterns[i], close));
  }
}

}  // namespace seaflex::io
