// `seaflex batch CASES.yaml -o DIR [--workers N | --scheduler ADDRESS]`: a load-case batch on
// dask.distributed, run by the Python module seaflex.batch (docs/python-batch.md).
#pragma once

#include <CLI/CLI.hpp>

namespace seaflex::cli {

/// Adds the `batch` subcommand to app. When it is parsed, its callback replaces this process
/// with `python3 -m seaflex.batch ...` (SEAFLEX_EXECUTABLE set to this executable, PYTHONPATH
/// to the seaflex package of the build or install tree), whose exit code is the command's:
/// 0 every case ok, 2 bad input, 3 some case failed. When Python cannot be started, the
/// callback prints why and throws CLI::RuntimeError(2).
void add_batch_command(CLI::App& app);

}  // namespace seaflex::cli
