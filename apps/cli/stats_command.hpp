// `seaflex stats DIR [CHANNEL...]`: prints the statistics and extremes of a run
// (DIR/statistics.csv and DIR/extremes.csv, written by a model with a statistics section).
#pragma once

#include <string>
#include <vector>

namespace seaflex::cli {

/// Prints the lines of DIR/statistics.csv whose channel matches one of the patterns (names
/// or shell patterns; none: every channel that is not a beam station), each with its most
/// probable maxima from DIR/extremes.csv. Throws InputError for a missing file or a pattern
/// that matches nothing.
int cmd_stats(const std::string& dir, const std::vector<std::string>& patterns);

}  // namespace seaflex::cli
