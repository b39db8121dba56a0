// `seaflex plot DIR [CHANNEL...]`: draws PNG figures of a run with the plotting script that
// ships with seaflex (scripts/seaflex_plot.py, Debian's python3-matplotlib).
#pragma once

#include <string>
#include <vector>

namespace seaflex::cli {

/// Runs the plotting script on dir (channels: names or shell patterns; out: the PNG
/// directory, empty for DIR/plots). Returns the script's exit code (0 done, 2 bad input).
int cmd_plot(const std::string& dir, const std::vector<std::string>& channels,
             const std::string& out);

}  // namespace seaflex::cli
