// The recorders of the model's `fatigue` and `code_check` sections for one output stem
// (fatigue only for the dynamic run "timeseries"; code checks also for "statics"), and
// the summary line printed at the end of a run.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "seaflex/io/code_check_recorder.hpp"
#include "seaflex/io/fatigue_recorder.hpp"
#include "seaflex/io/model_loader.hpp"

namespace seaflex::io {

class DesignRecorders {
 public:
  /// prefix: "" for timeseries, "statics." for statics; fatigue only when dynamic.
  DesignRecorders(const Model& model, const std::filesystem::path& dir, const std::string& prefix,
                  bool dynamic);
  /// The recorders to attach (none when the model has neither section).
  std::vector<Recorder*> recorders();
  /// Lines for the end of a run: the shortest fatigue life and the governing utilisations.
  std::string summary() const;
  /// Every file these sections may write (for clearing an output directory).
  static std::vector<std::filesystem::path> files(const Model& model,
                                                  const std::filesystem::path& dir);

 private:
  std::unique_ptr<FatigueRecorder> fatigue_;
  std::unique_ptr<CodeCheckRecorder> code_check_;
};

}  // namespace seaflex::io
