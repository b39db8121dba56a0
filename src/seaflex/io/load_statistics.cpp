// The model's `statistics` section (docs/model-format.md section "statistics"): the start
// of the analysed part of a run, the storm duration and exceedance probability of the
// extremes, the blocks of the Gumbel fit and the k of the range graphs' mean +- k sigma.
#include <fmt/format.h>

#include "seaflex/io/load_context.hpp"

namespace seaflex::io {

void load_statistics(const YAML::Node& node, LoadContext& ctx) {
  MapReader r(ctx.diag, node, "statistics");
  if (!r.valid()) return;
  StatisticsSettings s;
  if (const auto v = r.number("start", Need::kOptional, NumberRule::nonnegative("s"))) {
    s.start = *v;
    const auto& d = ctx.model.dynamics;
    if (d && s.start >= d->duration)
      r.error("start", fmt::format("{:g} s is at or beyond the end of the run (dynamics.duration "
                                   "= {:g} s): no rows would be analysed",
                                   s.start, d->duration));
  }
  if (const auto v = r.number("storm_duration", Need::kOptional, NumberRule::positive("s")))
    s.storm_duration = *v;
  NumberRule probability{0.0, 1.0, true, ""};
  if (const auto v = r.number("exceedance_probability", Need::kOptional, probability)) {
    if (*v >= 1.0) r.error("exceedance_probability", fmt::format("must be below 1, got {:g}", *v));
    s.exceedance_probability = *v;
  }
  if (const auto v = r.integer("blocks", Need::kOptional, 2, 100000)) s.blocks = *v;
  if (const auto v = r.number("k", Need::kOptional, NumberRule::positive(""))) s.k = *v;
  r.finish();
  ctx.model.statistics = s;
}

}  // namespace seaflex::io
