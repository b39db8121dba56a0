#include "plot_command.hpp"

#include <fmt/format.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>

namespace seaflex::cli {

namespace {

// the interpreter: $SEAFLEX_PYTHON, else Debian's /usr/bin/python3 (which sees
// python3-matplotlib even where another python3 comes first in PATH), else python3
std::string interpreter() {
  if (const char* p = std::getenv("SEAFLEX_PYTHON"); p && *p) return p;
  if (::access("/usr/bin/python3", X_OK) == 0) return "/usr/bin/python3";
  return "python3";
}

// the script: $SEAFLEX_PLOT_SCRIPT, else the source tree's (set at build time)
std::string script() {
  if (const char* p = std::getenv("SEAFLEX_PLOT_SCRIPT"); p && *p) return p;
  return SEAFLEX_PLOT_SCRIPT;
}

}  // namespace

int cmd_plot(const std::string& dir, const std::vector<std::string>& channels,
             const std::string& out) {
  const std::string py = interpreter(), path = script();
  if (!std::filesystem::is_regular_file(path)) {
    std::fprintf(stderr,
                 "seaflex plot: the plotting script %s is missing (set SEAFLEX_PLOT_SCRIPT to "
                 "seaflex_plot.py)\n",
                 path.c_str());
    return 2;
  }
  std::vector<std::string> args{py, path, dir};
  args.insert(args.end(), channels.begin(), channels.end());
  if (!out.empty()) {
    args.emplace_back("--out");
    args.push_back(out);
  }
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::fflush(stdout);
  std::fflush(stderr);
  const pid_t pid = ::fork();
  if (pid < 0) {
    std::fprintf(stderr, "seaflex plot: cannot start %s: %s\n", py.c_str(), std::strerror(errno));
    return 2;
  }
  if (pid == 0) {
    ::execvp(argv[0], argv.data());
    std::fprintf(stderr,
                 "seaflex plot: cannot run %s: %s (install python3 and python3-matplotlib, or "
                 "set SEAFLEX_PYTHON)\n",
                 argv[0], std::strerror(errno));
    std::_Exit(2);
  }
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return 2;
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  std::fprintf(stderr, "seaflex plot: the plotting script stopped abnormally\n");
  return 2;
}

}  // namespace seaflex::cli
