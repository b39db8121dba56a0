// Checks of the numeric command-line options, as CLI11 validators: every number must be
// finite and inside a sensible range, so that `--threads 20000`, `--checkpoint-every nan`
// or `bench --duration 1e300` stop with a message naming the option (exit 2) instead of
// starting thousands of threads or a run that never ends.
#pragma once

#include <CLI/CLI.hpp>

#include <string>

namespace seaflex::cli {

/// The hardware threads of this machine: std::thread::hardware_concurrency(), at least 1
/// (the standard allows 0 when it is not known).
int hardware_threads();

/// A whole number from 1 to hardware_threads(): the largest useful thread count.
CLI::Validator thread_count();

/// A whole number from 1 to max.
CLI::Validator whole_number(long max);

/// A finite number x with 0 < x <= max (unit: for the message, e.g. "s").
CLI::Validator finite_positive(double max, const std::string& unit);

}  // namespace seaflex::cli
