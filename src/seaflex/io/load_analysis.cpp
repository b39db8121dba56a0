// statics and dynamics sections: solver settings and the integrator registry.
#include <fmt/format.h>

#include <cmath>

#include "seaflex/integrators/generalized_alpha.hpp"
#include "seaflex/integrators/rk4_augmented.hpp"
#include "seaflex/io/load_context.hpp"

namespace seaflex::io {

namespace {

using IntegratorFactory = std::function<std::unique_ptr<Integrator>()>;

IntegratorFactory build_rk4(MapReader& r, LoadContext&) {
  const auto stab =
      r.choice("constraint_stabilization", Need::kOptional, {"projection", "baumgarte", "none"});
  const auto alpha = r.number("baumgarte_alpha", Need::kOptional, NumberRule::positive("1/s"));
  const auto beta = r.number("baumgarte_beta", Need::kOptional, NumberRule::positive("1/s"));
  Stabilization s = Stabilization::kProjection;
  if (stab == "baumgarte") s = Stabilization::kBaumgarte;
  if (stab == "none") s = Stabilization::kNone;
  if ((alpha || beta) && s != Stabilization::kBaumgarte)
    r.error(alpha ? "baumgarte_alpha" : "baumgarte_beta",
            "applies only with constraint_stabilization: baumgarte");
  const double a = alpha.value_or(5.0), b = beta.value_or(5.0);
  return [s, a, b]() { return std::make_unique<Rk4Augmented>(s, a, b); };
}

// generalized_alpha and hht: spectral radius, Newton mode and tolerance
IntegratorFactory build_alpha(MapReader& r, bool hht) {
  const double low = hht ? 0.5 : 0.0;
  const auto rho = r.number("rho_inf", Need::kOptional, NumberRule::range(low, 1.0, ""));
  const auto newton = r.choice("newton", Need::kOptional, {"modified", "full"});
  const auto iterations = r.integer("max_iterations", Need::kOptional, 1, 1000);
  const auto tol = r.number("tolerance", Need::kOptional, NumberRule::range(1e-15, 1e-2, ""));
  const auto solver = r.choice("linear_solver", Need::kOptional, {"klu", "sparselu", "umfpack"});
  const auto form = r.choice("constraint_form", Need::kOptional, {"index2", "index3"});
  const auto refresh = r.number("refresh_rate", Need::kOptional, NumberRule::range(0.01, 0.99, ""));
  const double rho_inf = rho.value_or(hht ? 0.9 : 0.8);
  GeneralizedAlphaSettings s = hht ? GeneralizedAlphaSettings::hht(rho_inf)
                                   : GeneralizedAlphaSettings::from_rho_inf(rho_inf);
  s.newton = newton == "full" ? NewtonMode::kFull : NewtonMode::kModified;
  if (iterations) s.max_iterations = *iterations;
  if (tol) s.tolerance = *tol;
  if (form == "index3") s.constraints = ConstraintLevel::kIndex3;
  if (refresh) s.refresh_rate = *refresh;
  if (solver) s.linear_solver = *KktSolver::parse(*solver);
  return [s]() { return std::make_unique<GeneralizedAlpha>(s); };
}

IntegratorFactory build_generalized_alpha(MapReader& r, LoadContext&) {
  return build_alpha(r, false);
}
IntegratorFactory build_hht(MapReader& r, LoadContext&) {
  return build_alpha(r, true);
}

// true when x is a whole multiple of h (to 1e-6 of a step)
bool whole_steps(double x, double h) {
  const double n = x / h;
  return std::abs(n - std::round(n)) <= 1e-6 * std::max(1.0, n) && std::round(n) >= 1.0;
}

}  // namespace

const std::map<std::string, IntegratorBuilder>& integrator_builders() {
  static const std::map<std::string, IntegratorBuilder> builders{
      {"rk4", build_rk4},
      {"generalized_alpha", build_generalized_alpha},
      {"hht", build_hht},
  };
  return builders;
}

void load_statics(const YAML::Node& node, LoadContext& ctx) {
  MapReader r(ctx.diag, node, "statics");
  if (!r.valid()) return;
  StaticsSettings& s = ctx.model.statics;
  if (const auto v = r.integer("load_steps", Need::kOptional, 1, 100000)) s.load_steps = *v;
  if (const auto v = r.integer("max_iterations", Need::kOptional, 1, 1000)) s.max_iterations = *v;
  if (const auto v = r.number("tolerance", Need::kOptional, NumberRule::range(1e-15, 1e-2, "")))
    s.tolerance = *v;
  if (const auto v = r.number("time", Need::kOptional, NumberRule::nonnegative("s"))) s.time = *v;
  if (const auto v = r.choice("linear_solver", Need::kOptional, {"klu", "sparselu", "umfpack"}))
    s.linear_solver = *KktSolver::parse(*v);
  if (const YAML::Node ls = r.get("line_search"); ls.IsDefined()) {
    if (ls.IsScalar() && (ls.Scalar() == "true" || ls.Scalar() == "false"))
      s.line_search = ls.Scalar() == "true";
    else
      r.error("line_search", fmt::format("expected true or false, got {}", describe(ls)));
  }
  r.finish();
}

void load_dynamics(const YAML::Node& node, LoadContext& ctx) {
  MapReader r(ctx.diag, node, "dynamics");
  if (!r.valid()) return;
  DynamicsSettings d;
  d.line = r.mark().line + 1;
  const auto integrator = r.choice("integrator", Need::kOptional, keys_of(integrator_builders()));
  d.integrator = integrator.value_or("rk4");
  const auto h = r.number("time_step", Need::kRequired, NumberRule::positive("s"));
  const auto T = r.number("duration", Need::kRequired, NumberRule::positive("s"));
  const auto out = r.number("output_interval", Need::kOptional, NumberRule::positive("s"));
  const auto start = r.choice("initial_state", Need::kOptional, {"model", "statics"});
  d.start_from_statics = start == "statics";
  const auto control = r.choice("step_control", Need::kOptional, {"fixed", "adaptive"});
  d.adaptive = control == "adaptive";
  const auto h_min = r.number("min_time_step", Need::kOptional, NumberRule::positive("s"));
  if (h_min && !d.adaptive) r.error("min_time_step", "applies only with step_control: adaptive");
  if (h_min && h && *h_min > *h)
    r.error("min_time_step",
            fmt::format("must not exceed time_step ({:g} s), got {:g} s", *h, *h_min));
  if (h_min && h && *h / *h_min > 1048576.0)
    r.error("min_time_step", fmt::format("at most 2^20 halvings of time_step ({:g} s) are "
                                         "allowed; got {:g} s",
                                         *h, *h_min));
  d.min_time_step = h_min.value_or(0.0);
  const auto err_tol =
      r.number("error_tolerance", Need::kOptional, NumberRule::range(1e-10, 0.1, ""));
  if (err_tol && !d.adaptive)
    r.error("error_tolerance", "applies only with step_control: adaptive");
  if (err_tol) d.error_tolerance = *err_tol;
  bool ok = h && T;
  if (h && T) {
    if (*T / *h > 2e9) {
      r.error("duration", fmt::format("{:g} s at a time step of {:g} s is {:.3g} steps, more than "
                                      "the limit of 2e9",
                                      *T, *h, *T / *h));
      ok = false;
    } else if (!whole_steps(*T, *h)) {
      r.error("duration",
              fmt::format("must be a whole number of time steps ({:g} s), got {:g} s", *h, *T));
      ok = false;
    }
  }
  if (h && out && !whole_steps(*out, *h)) {
    r.error("output_interval",
            fmt::format("must be a whole number of time steps ({:g} s), got {:g} s", *h, *out));
    ok = false;
  }
  if (integrator_builders().count(d.integrator))
    d.make_integrator = integrator_builders().at(d.integrator)(r, ctx);
  r.finish();
  if (!ok) return;
  d.time_step = *h;
  d.duration = *T;
  d.output_interval = out.value_or(*h);
  ctx.model.dynamics = std::move(d);
}

}  // namespace seaflex::io
