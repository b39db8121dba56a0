// Attachments on a line, in the `loads` list (forces/beam_attachment.hpp):
//   type: clump             one clump weight or point buoy at an arc length
//   type: buoyancy_modules  `count` modules (or one per `spacing` m) over [from, to],
//                           smeared over the range (default) or each a point at the centre
//                           of its equal share of the range (distribution: discrete)
// Format: docs/model-format.md section 10.6.
#include <fmt/format.h>

#include <cmath>

#include "seaflex/forces/beam_attachment.hpp"
#include "seaflex/io/load_context.hpp"

namespace seaflex::io {

namespace {

constexpr int kMaxModules = 10000;  // per entry: each a matrix block when discrete

// mass, volume (at least one of them > 0), cd, drag_area, ca
std::optional<AttachmentProperties> read_attachment(MapReader& r) {
  AttachmentProperties p;
  const auto mass = r.number("mass", Need::kOptional, NumberRule::nonnegative("kg"));
  const auto volume = r.number("volume", Need::kOptional, NumberRule::nonnegative("m^3"));
  const NumberRule coefficient = NumberRule::range(0.0, 10.0, "");
  p.cd = r.number("cd", Need::kOptional, coefficient).value_or(0.0);
  p.drag_area =
      r.number("drag_area", Need::kOptional, NumberRule::nonnegative("m^2")).value_or(0.0);
  p.ca = r.number("ca", Need::kOptional, coefficient).value_or(0.0);
  if (p.cd > 0.0 && !r.has("drag_area")) {
    r.error("drag_area", "required with cd: the area (m^2) the drag coefficient refers to");
    return std::nullopt;
  }
  if (!r.has("mass") && !r.has("volume")) {
    r.error("mass", "give the attachment's mass (kg) and/or displaced volume (m^3)");
    return std::nullopt;
  }
  if ((r.has("mass") && !mass) || (r.has("volume") && !volume)) return std::nullopt;
  p.mass = mass.value_or(0.0);
  p.volume = volume.value_or(0.0);
  if (!(p.mass > 0.0) && !(p.volume > 0.0)) {
    r.error("mass", "and volume are both 0: the attachment would do nothing");
    return std::nullopt;
  }
  return p;
}

std::unique_ptr<Force> make(const std::string& name, const AncfBeam& beam, std::vector<double> arcs,
                            const AttachmentProperties& p, const LoadContext& ctx) {
  return std::make_unique<BeamAttachment>(name, beam, std::move(arcs), p, ctx.model.gravity,
                                          ctx.model.ocean);
}

}  // namespace

std::unique_ptr<Force> build_clump(MapReader& r, const std::string& name, LoadContext& ctx) {
  const AncfBeam* beam = ctx.beam_ref(r, "body");
  std::optional<double> s;
  if (beam)
    s = r.number("arc_length", Need::kRequired, NumberRule::range(0.0, beam->length(), "m"));
  else
    r.has("arc_length");
  const auto p = read_attachment(r);
  if (!beam || !s || !p) return nullptr;
  return make(name, *beam, {*s}, *p, ctx);
}

std::unique_ptr<Force> build_buoyancy_modules(MapReader& r, const std::string& name,
                                              LoadContext& ctx) {
  const AncfBeam* beam = ctx.beam_ref(r, "body");
  std::optional<double> from, to;
  if (beam) {
    const NumberRule on_line = NumberRule::range(0.0, beam->length(), "m");
    from = r.number("from", Need::kRequired, on_line);
    to = r.number("to", Need::kRequired, on_line);
  } else {
    r.has("from");
    r.has("to");
  }
  const bool by_count = r.has("count"), by_spacing = r.has("spacing");
  std::optional<int> count;
  if (by_count && by_spacing) {
    r.error("spacing", "give either count or spacing, not both");
  } else if (by_count) {
    count = r.integer("count", Need::kRequired, 1, kMaxModules);
  } else {
    const auto spacing = r.number("spacing", Need::kRequired, NumberRule::positive("m"));
    if (spacing && from && to && *to > *from) {
      const double n = std::round((*to - *from) / *spacing);
      if (n > kMaxModules)
        r.error("spacing", fmt::format("{:g} m makes {:g} modules, more than the limit of {}",
                                       *spacing, n, kMaxModules));
      else
        count = static_cast<int>(std::max(1.0, n));
    }
  }
  const auto distribution =
      r.choice("distribution", Need::kOptional, {"smeared", "discrete"}).value_or("smeared");
  const auto p = read_attachment(r);
  if (from && to && !(*to > *from)) {
    r.error("to", fmt::format("{:g} m is not after from ({:g} m)", *to, *from));
    return nullptr;
  }
  if (!beam || !from || !to || !count || !p) return nullptr;
  if (distribution == "smeared")
    return BeamAttachment::smeared(name, *beam, *from, *to, *count, *p, ctx.model.gravity,
                                   ctx.model.ocean);
  std::vector<double> arcs;
  const double share = (*to - *from) / *count;
  for (int i = 0; i < *count; ++i) arcs.push_back(*from + (i + 0.5) * share);
  return make(name, *beam, std::move(arcs), *p, ctx);
}

}  // namespace seaflex::io
