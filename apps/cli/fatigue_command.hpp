// `seaflex fatigue SCATTER.yaml -o DIR`: a fatigue run. The load cases of a scatter diagram
// (Hs, Tp, heading, probability of occurrence), each a finished result folder with
// <beam>.fatigue.csv or a model to run, are combined into the long-term damage per year
// at every station and circumferential point,
//   D_year(s, j) = sum_i p_i D_i(s, j) (1 year) / T_i
// (Miner's rule over the cases, DNV-RP-C203 (2016) section 2.2 and eq. (2.2.1); D_i the
// damage of case i's run, T_i the time it represents), and the life 1 / max_j D_year(s, j).
// Probabilities must sum to 1 (to 1e-6) unless `normalise: true` scales them (with a
// warning). Writes DIR/<beam>.fatigue_total.csv and DIR/fatigue_cases.csv
// (docs/results-format.md); the file format is in docs/model-format.md.
#pragma once

#include <functional>
#include <string>

namespace seaflex::cli {

/// run_model(model, dir) runs a model (seaflex run) into dir and returns its exit code.
/// Returns 0; throws InputError on a bad scatter file or missing results.
int cmd_fatigue(const std::string& file, const std::string& dir,
                const std::function<int(const std::string&, const std::string&)>& run_model);

}  // namespace seaflex::cli
