#include "batch_command.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "option_checks.hpp"

namespace seaflex::cli {

namespace fs = std::filesystem;

namespace {

// the interpreter: $SEAFLEX_PYTHON, else Debian's /usr/bin/python3 (which sees
// python3-distributed where another python3 comes first in PATH), else python3 on PATH
std::string interpreter() {
  if (const char* p = std::getenv("SEAFLEX_PYTHON"); p && *p) return p;
  if (::access("/usr/bin/python3", X_OK) == 0) return "/usr/bin/python3";
  return "python3";
}

// this executable, for the cases (SEAFLEX_EXECUTABLE)
std::string own_executable() {
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  return ec ? std::string() : self.string();
}

// Folders holding the seaflex package (seaflex/batch.py): the package staged by the build,
// the installed one next to this executable (<prefix>/bin -> <prefix>/lib/python3*/...), the
// source tree's; joined for PYTHONPATH in that order, before the PYTHONPATH given.
std::string python_path(const std::string& exe) {
  std::vector<fs::path> candidates{SEAFLEX_PYTHON_BUILD_DIR};
  std::error_code ec;
  if (!exe.empty()) {
    const fs::path lib = fs::path(exe).parent_path().parent_path() / "lib";
    for (const auto& entry : fs::directory_iterator(lib, ec)) {
      const std::string name = entry.path().filename().string();
      if (name.rfind("python3", 0) != 0) continue;
      candidates.push_back(entry.path() / "dist-packages");
      candidates.push_back(entry.path() / "site-packages");
    }
  }
  candidates.emplace_back(SEAFLEX_PYTHON_SOURCE_DIR);
  std::string path;
  for (const auto& dir : candidates)
    if (fs::is_regular_file(dir / "seaflex" / "batch.py", ec))
      path += (path.empty() ? "" : ":") + dir.string();
  if (const char* old = std::getenv("PYTHONPATH"); old && *old)
    path += (path.empty() ? "" : ":") + std::string(old);
  return path;
}

struct BatchOptions {
  std::string cases;
  std::string output = "batch";
  int workers = 0;
  std::string scheduler;
  bool quiet = false;
};

[[noreturn]] void run_batch(const BatchOptions& o) {
  const std::string exe = own_executable();
  const std::string py = interpreter();
  if (!exe.empty()) ::setenv("SEAFLEX_EXECUTABLE", exe.c_str(), 1);
  ::setenv("PYTHONPATH", python_path(exe).c_str(), 1);
  ::setenv("SEAFLEX_BATCH_PROG", "seaflex batch", 1);
  std::vector<std::string> args{py, "-m", "seaflex.batch", o.cases, "-o", o.output};
  if (o.workers > 0) {
    args.emplace_back("--workers");
    args.push_back(std::to_string(o.workers));
  }
  if (!o.scheduler.empty()) {
    args.emplace_back("--scheduler");
    args.push_back(o.scheduler);
  }
  if (o.quiet) args.emplace_back("-q");
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::fflush(stdout);
  std::fflush(stderr);
  ::execvp(argv[0], argv.data());
  std::fprintf(stderr,
               "seaflex batch: cannot run %s: %s (install python3, python3-distributed and "
               "python3-pandas, or set SEAFLEX_PYTHON)\n",
               argv[0], std::strerror(errno));
  throw CLI::RuntimeError(2);
}

}  // namespace

void add_batch_command(CLI::App& app) {
  auto options = std::make_shared<BatchOptions>();
  auto* cmd = app.add_subcommand(
      "batch",
      "run a load-case batch (a base model and variations) on dask.distributed: a folder per "
      "case, DIR/summary.csv");
  cmd->add_option("CASES", options->cases, "cases file (YAML, docs/python-batch.md)")->required();
  cmd->add_option("-o,--output", options->output, "output directory")->capture_default_str();
  auto* workers =
      cmd->add_option("--workers", options->workers,
                      "worker processes of a local cluster (default and most: the machine's "
                      "hardware threads)")
          ->check(thread_count());
  cmd->add_option("--scheduler", options->scheduler,
                  "address of a running Dask scheduler (tcp://HOST:PORT) whose workers run the "
                  "cases")
      ->excludes(workers);
  cmd->add_flag("-q,--quiet", options->quiet, "no progress bar; print only errors");
  cmd->callback([options] { run_batch(*options); });
}

}  // namespace seaflex::cli
