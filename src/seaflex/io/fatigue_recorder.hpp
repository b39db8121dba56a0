// Fatigue damage along beams during a run (the model's `fatigue` section): at every output
// row after fatigue.start, the hot-spot stress at `points` points around the outer fibre
// of every result station (post/fatigue_damage.hpp: axial wall force and biaxial bending,
// times the SCF) feeds one streaming rainflow counter per point; each closed cycle adds its
// Miner damage at once. Memory: the counters' stacks (a few dozen reversals per point), not
// the history, so a 3-hour storm costs no more than a short run. Written on flush (end of
// run or failure; the residue is counted as half cycles in a copy, so a flush mid-run does
// not disturb the count): `<prefix><beam>.fatigue.csv` (docs/results-format.md), and with
// write_stresses `<prefix><beam>.fatigue_stress.csv`, every hot-spot stress per row.
// Damage per year = damage of the run * (365.25 d) / exposure, life = 1 / damage per year.
#pragma once

#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "seaflex/core/output_file.hpp"
#include "seaflex/io/design_settings.hpp"
#include "seaflex/post/beam_results.hpp"
#include "seaflex/post/fatigue_damage.hpp"
#include "seaflex/simulation/recorder.hpp"

namespace seaflex::io {

/// The shortest life found on the last flush (for the run's summary).
struct FatigueSummary {
  std::string beam;
  double s = 0.0;       ///< arc length of the governing station (m)
  int point = 0;        ///< its circumferential point
  double damage = 0.0;  ///< damage of the run
  double life_years = 0.0;
  double exposure = 0.0;  ///< s
};

class FatigueRecorder : public Recorder {
 public:
  FatigueRecorder(const std::filesystem::path& dir, const std::string& prefix,
                  std::vector<post::BeamResults> beams, const FatigueSettings& settings);

  void begin(const std::vector<std::string>& channels) override;
  void record(const State& state, std::span<const double> values) override;
  void flush() override;

  std::optional<FatigueSummary> summary() const { return summary_; }
  static std::vector<std::filesystem::path> files(const std::filesystem::path& dir,
                                                  const std::string& prefix,
                                                  const std::string& beam);

 private:
  struct Beam {
    post::BeamResults results;
    post::FatigueDamage damage;
    std::vector<Vec3> reference;  // per station, chosen at the first row
    std::filesystem::path path, stress_path;
    RowFile stresses;  // open when settings.write_stresses
  };
  std::vector<Beam> beams_;
  FatigueSettings settings_;
  double t_first_ = 0.0, t_last_ = 0.0;
  long rows_ = 0;
  MatX table_;
  std::vector<double> buffer_;
  std::string line_;
  std::optional<FatigueSummary> summary_;
};

}  // namespace seaflex::io
