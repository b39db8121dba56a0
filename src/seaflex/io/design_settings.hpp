// The model's `fatigue` and `code_check` sections (docs/model-format.md, "Fatigue" and
// "Code checks"): which beams, the S-N curve and stress factors, the code-check material
// and partial factors.
#pragma once

#include <string>
#include <vector>

#include "seaflex/post/code_check.hpp"
#include "seaflex/post/sn_curve.hpp"

namespace seaflex::io {

struct FatigueSettings {
  std::vector<std::string> beams;  ///< ANCF pipe beams (all pipe beams when none were given)
  post::SnCurve curve;             ///< DNV-RP-C203 (2016) or user-defined
  post::SnEnvironment environment = post::SnEnvironment::kAir;
  double scf = 1.0;             ///< stress concentration factor (>= 1)
  double thickness = 0.0;       ///< m; 0: the pipe wall (Do - Di)/2
  int points = 8;               ///< points around the circumference
  double start = 0.0;           ///< s; rows before it are skipped (build-up)
  double exposure = 0.0;        ///< s one run represents; 0: the recorded time after start
  bool write_stresses = false;  ///< <beam>.fatigue_stress.csv with every hot-spot stress
};

struct CodeCheckSettings {
  std::vector<std::string> beams;  ///< ANCF pipe beams (all pipe beams when none were given)
  double smys = 0.0;               ///< Pa
  double smts = 0.0;               ///< Pa
  double corrosion = 0.0;          ///< corrosion allowance (m)
  double fabrication = 0.0;        ///< negative fabrication tolerance (m)
  post::DnvFactors factors;
  double design_factor = 1.0;  ///< API RP 2RD C_f
  double start = 0.0;          ///< s
};

}  // namespace seaflex::io
