#include "seaflex/io/design_recorders.hpp"

#include <fmt/format.h>

#include "seaflex/io/output_selection.hpp"

namespace seaflex::io {

namespace {
std::vector<post::BeamResults> results(const Model& model, const std::vector<std::string>& names) {
  std::vector<post::BeamResults> list;
  for (const auto& name : names) {
    const auto* beam = dynamic_cast<const AncfBeam*>(model.system->find_body(name));
    list.emplace_back(*beam, pipe_pressure(model, *beam), model.output.beam_gauss_points);
  }
  return list;
}
}  // namespace

DesignRecorders::DesignRecorders(const Model& model, const std::filesystem::path& dir,
                                 const std::string& prefix, bool dynamic) {
  if (model.fatigue && dynamic)
    fatigue_ = std::make_unique<FatigueRecorder>(dir, prefix, results(model, model.fatigue->beams),
                                                 *model.fatigue);
  if (model.code_check)
    code_check_ = std::make_unique<CodeCheckRecorder>(
        dir, prefix, results(model, model.code_check->beams), *model.code_check);
}

std::vector<Recorder*> DesignRecorders::recorders() {
  std::vector<Recorder*> list;
  if (fatigue_) list.push_back(fatigue_.get());
  if (code_check_) list.push_back(code_check_.get());
  return list;
}

std::string DesignRecorders::summary() const {
  std::string out;
  if (const auto sum = fatigue_ ? fatigue_->summary() : std::nullopt) {
    const FatigueSummary& s = *sum;
    out += fmt::format(
        "fatigue: damage {:.4g} in {:g} s, shortest life {:.4g} years at {} s = {:.4g} m "
        "(point {})\n",
        s.damage, s.exposure, s.life_years, s.beam, s.s, s.point);
  }
  if (code_check_)
    for (const auto& s : code_check_->summary())
      if (!s.beam.empty())
        out += fmt::format(
            "code check {}: governing utilisation {:.4g} at {} s = {:.4g} m, t = {:g} s\n",
            s.standard, s.utilisation, s.beam, s.s, s.time);
  return out;
}

std::vector<std::filesystem::path> DesignRecorders::files(const Model& model,
                                                          const std::filesystem::path& dir) {
  std::vector<std::filesystem::path> out;
  for (const auto& b : model.system->bodies()) {
    if (!dynamic_cast<const AncfBeam*>(b.get())) continue;
    for (const char* prefix : {"", "statics.", "statics_partial."}) {
      for (const auto& f : FatigueRecorder::files(dir, prefix, b->name())) out.push_back(f);
      out.push_back(CodeCheckRecorder::file(dir, prefix, b->name()));
    }
  }
  return out;
}

}  // namespace seaflex::io
