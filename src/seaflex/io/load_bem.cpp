// hydrodynamics.<body>.bem: a WAMIT-format BEM database (.1, .3, .hst) for a
// rigid body: infinite-frequency added mass, hydrostatic matrix, RAO wave
// excitation and Cummins radiation memory (thesis eq. 173). Format:
// docs/model-format.md section 11.
#include <fmt/format.h>

#include <filesystem>
#include <numbers>

#include "seaflex/forces/radiation_force.hpp"
#include "seaflex/forces/rao_excitation.hpp"
#include "seaflex/hydro/retardation.hpp"
#include "seaflex/hydro/wamit_reader.hpp"
#include "seaflex/io/load_context.hpp"

namespace seaflex::io {

void load_bem(MapReader& b, const RigidBody& body, HydroMatrixSet& set, LoadContext& ctx) {
  const hydro::Ocean& ocean = *ctx.model.ocean;
  const auto file = b.text("wamit", Need::kRequired);
  const double ulen =
      b.number("length_scale", Need::kOptional, NumberRule::positive("m")).value_or(1.0);
  const double g_bem =
      b.number("gravity", Need::kOptional, NumberRule::positive("m/s^2")).value_or(ocean.g());
  const auto radiation =
      b.choice("radiation", Need::kOptional, {"convolution", "state_space", "none"})
          .value_or("convolution");
  const double memory =
      b.number("memory", Need::kOptional, NumberRule::positive("s")).value_or(60.0);
  const double kdt =
      b.number("kernel_time_step", Need::kOptional, NumberRule::positive("s")).value_or(0.05);
  const bool excitation =
      b.choice("excitation", Need::kOptional, {"true", "false"}).value_or("true") == "true";
  const bool hydrostatics = b.has("displaced_volume");
  const auto volume = b.number("displaced_volume", Need::kOptional, NumberRule::positive("m^3"));
  const auto still = b.vec3("still_water_position", Need::kOptional, "m");
  if (memory < kdt) {
    b.error("memory",
            fmt::format("must be at least kernel_time_step ({} s), got {} s", kdt, memory));
    return;
  }
  // a convolution keeps every sample of K (6 x 6 doubles each) and computes each from the
  // whole damping table: a bound on both (the state-space fit samples K a bounded number of
  // times whatever the ratio, see StateSpaceRadiation::from_damping)
  constexpr double kMaxConvolutionSamples = 100000;
  if (radiation == "convolution" && memory / kdt > kMaxConvolutionSamples) {
    b.error("kernel_time_step",
            fmt::format("memory / kernel_time_step = {:.6g} kernel samples, more than the limit "
                        "of {:g} for radiation: convolution; use a kernel_time_step of at least "
                        "{:.3g} s, a shorter memory, or radiation: state_space",
                        memory / kdt, kMaxConvolutionSamples, memory / kMaxConvolutionSamples));
    return;
  }
  if (!file) return;
  std::filesystem::path stem(*file);
  if (stem.is_relative()) stem = std::filesystem::path(ctx.diag.file()).parent_path() / stem;
  std::shared_ptr<hydro::HydroDatabase> db;
  try {
    db = std::make_shared<hydro::HydroDatabase>(
        hydro::read_wamit(stem.string(), hydro::WamitUnits{ocean.rho(), g_bem, ulen}));
  } catch (const InputError& e) {
    for (const auto& d : e.diagnostics())
      b.error("wamit", d.line > 0 ? fmt::format("{}:{}: {}: {}", d.file, d.line, d.key, d.message)
                                  : fmt::format("{}: {}", d.file, d.message));
    return;
  }
  if (!db->has_added_mass_inf)
    b.error("wamit", fmt::format("{}.1 has no infinite-frequency rows (PER = 0): the Cummins "
                                 "equation needs A(inf)",
                                 stem.string()));
  else
    set.added_mass += db->added_mass_inf;
  if (hydrostatics) {
    if (!db->has_hydrostatics) {
      b.error("displaced_volume", fmt::format("needs {}.hst (the hydrostatic matrix), which "
                                              "was not found",
                                              stem.string()));
    } else {
      set.has_stiffness = true;
      set.stiffness = db->hydrostatic_stiffness;
      set.displaced_volume = volume.value_or(0.0);
      set.still_water_position = still.value_or(Vec3::Zero());
    }
  }
  const Vec3 rest = still.value_or(Vec3::Zero());
  if (excitation && ocean.has_waves()) {
    if (!db->has_excitation) {
      b.error("wamit", fmt::format("{}.3 (excitation RAOs) was not found; give excitation: "
                                   "false to run without wave excitation",
                                   stem.string()));
    } else {
      bool heading_warned = false;
      for (const auto& c : ocean.waves().components()) {
        bool clamped = false;
        db->excitation_at(c.omega, c.direction - set.heading, nullptr, &clamped);
        if (clamped && !heading_warned) {
          heading_warned = true;
          ctx.model.warnings.push_back(fmt::format(
              "{}:{}:{}: {}: a wave heading of {:.4g} deg relative to the body lies outside the "
              "headings of {}; the RAO of the nearest tabulated heading is used",
              ctx.diag.file(), b.mark().line + 1, b.mark().column + 1, b.path(),
              (c.direction - set.heading) * 180.0 / std::numbers::pi, stem.string()));
        }
      }
      for (const auto& c : ocean.waves().components()) {
        if (c.omega < db->omega.front() || c.omega > db->omega.back()) {
          ctx.model.warnings.push_back(fmt::format(
              "{}:{}:{}: {}: a wave frequency {:.4g} rad/s lies outside the BEM range [{:.4g}, "
              "{:.4g}] rad/s of {}; the RAO of the nearest tabulated frequency is used",
              ctx.diag.file(), b.mark().line + 1, b.mark().column + 1, b.path(), c.omega,
              db->omega.front(), db->omega.back(), stem.string()));
          break;
        }
      }
      ctx.system.add_force(
          std::make_unique<RaoExcitation>(fmt::format("{}.excitation", body.name()), body, db,
                                          ctx.model.ocean, set.reference, rest));
    }
  }
  if (radiation != "none") {
    const std::string name = fmt::format("{}.radiation", body.name());
    if (radiation == "convolution")
      ctx.system.add_force(std::make_unique<RadiationForce>(
          name, body, set.reference,
          hydro::ConvolutionRadiation(hydro::RetardationKernel::from_damping(*db, kdt, memory),
                                      memory)));
    else
      ctx.system.add_force(std::make_unique<RadiationForce>(
          name, body, set.reference,
          hydro::StateSpaceRadiation::from_damping(*db, kdt, memory, {})));
  }
}

}  // namespace seaflex::io
