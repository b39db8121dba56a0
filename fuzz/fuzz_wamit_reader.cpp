// libFuzzer harness of the WAMIT reader (issue 9). The input is split at the first two
// form feeds into the contents of <stem>.1, <stem>.3 and <stem>.hst (a part that is absent
// leaves its file out), written to a private directory and read with read_wamit. It must
// return a database or throw an InputError naming file and line; never crash, hang, leak
// or throw anything else. Seed corpus: the WAMIT files of tests/data/wamit.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "seaflex/core/errors.hpp"
#include "seaflex/hydro/wamit_reader.hpp"

namespace {

const std::filesystem::path& directory() {
  static const std::filesystem::path dir = [] {
    auto d = std::filesystem::temp_directory_path() /
             ("seaflex_fuzz_wamit_" + std::to_string(::getpid()));
    std::filesystem::create_directories(d);
    return d;
  }();
  return dir;
}

void write(const std::filesystem::path& path, const std::string* text) {
  std::filesystem::remove(path);
  if (!text) return;
  std::ofstream(path, std::ios::binary) << *text;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string input(reinterpret_cast<const char*>(data), size);
  std::string part[3];
  int parts = 0;
  std::size_t start = 0;
  for (; parts < 3; ++parts) {
    const std::size_t ff = parts < 2 ? input.find('\f', start) : std::string::npos;
    part[parts] = input.substr(start, ff == std::string::npos ? std::string::npos : ff - start);
    if (ff == std::string::npos) {
      ++parts;
      break;
    }
    start = ff + 1;
  }
  const auto stem = directory() / "body";
  write(stem.string() + ".1", &part[0]);
  write(stem.string() + ".3", parts > 1 ? &part[1] : nullptr);
  write(stem.string() + ".hst", parts > 2 ? &part[2] : nullptr);
  try {
    const seaflex::hydro::HydroDatabase db = seaflex::hydro::read_wamit(stem.string(), {});
    (void)db;
  } catch (const seaflex::InputError&) {
  } catch (const std::exception& e) {
    std::fprintf(stderr, "unexpected exception: %s\n", e.what());
    std::abort();
  }
  return 0;
}
