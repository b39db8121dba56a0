// The summary of a loaded model that `seaflex check` prints (and Python's Model.check()
// returns): bodies, constraints, forces, channels and the analysis settings.
#pragma once

#include <string>

#include "seaflex/io/model_loader.hpp"

namespace seaflex::analysis {

/// Lines ending in '\n', without the final "model OK".
std::string model_summary(const io::Model& model);

}  // namespace seaflex::analysis
