// Code-check utilisation along beams during a run or at statics (the model's `code_check`
// section; formulas in post/code_check.hpp): at every output row after code_check.start and
// every result station, DNV-ST-F201 combined loading and API RP 2RD von Mises; the maximum
// over the rows and its time per station, written on flush as
// `<prefix><beam>.code_check.csv` (docs/results-format.md).
// Functional and environmental load effects: the functional part is the state of the
// first recorded row (the static equilibrium when the run starts from statics, or the
// statics result itself), the environmental part the difference from it:
//   M_d = gamma_C | gamma_F M_F + gamma_E (M(t) - M_F) |  (moment vectors),
//   T_ed = gamma_C (gamma_F T_F + gamma_E (T_eff(t) - T_F)).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "seaflex/io/design_settings.hpp"
#include "seaflex/post/beam_results.hpp"
#include "seaflex/simulation/recorder.hpp"

namespace seaflex::io {

struct CodeCheckSummary {
  std::string standard;  ///< "DNV-ST-F201" or "API RP 2RD"
  std::string beam;
  double s = 0.0;  ///< m
  double utilisation = 0.0;
  double time = 0.0;  ///< s
};

class CodeCheckRecorder : public Recorder {
 public:
  CodeCheckRecorder(const std::filesystem::path& dir, const std::string& prefix,
                    std::vector<post::BeamResults> beams, const CodeCheckSettings& settings);

  void begin(const std::vector<std::string>& channels) override;
  void record(const State& state, std::span<const double> values) override;
  void flush() override;
  /// Restart files: the functional load effects and the maxima so far.
  bool save(CheckpointWriter& out, const std::string& prefix) const override;
  void restore(const CheckpointReader& in, const std::string& prefix) override;

  /// The governing (largest) utilisation of each standard on the last flush.
  const std::vector<CodeCheckSummary>& summary() const { return summary_; }
  static std::filesystem::path file(const std::filesystem::path& dir, const std::string& prefix,
                                    const std::string& beam);

 private:
  struct Beam {
    post::BeamResults results;
    std::vector<post::DnvPipe> pipes;  // per beam section
    std::vector<Vec3> moment_f;        // functional moment per station
    std::vector<double> tension_f;     // functional effective tension
    std::vector<double> dnv, dnv_t, api, api_t;
    std::filesystem::path path;
  };
  std::vector<Beam> beams_;
  CodeCheckSettings settings_;
  bool any_ = false;
  MatX table_;
  std::vector<CodeCheckSummary> summary_;
};

}  // namespace seaflex::io
