// libFuzzer harness of the file-reading layer (issue 22): the input is written to a file
// (data.csv, in a private directory) that three models name, and each is loaded from disk
// with load_model_file, so that core/input_file.cpp, the motion-table reader and the RAO
// table reader see it as a user's file; the input is also read as the model file itself.
// Each load must give a model or an InputError/ModelError naming the problem; never a
// crash, a hang, a leak or another exception. Seeds: the motion and RAO tables of
// tests/bad-input/motion_data and examples/.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "seaflex/core/errors.hpp"
#include "seaflex/io/model_loader.hpp"

namespace {

// a vessel that follows the motion of data.csv: a time table, an RAO table in columns, or a
// WAMIT .4 RAO file
const char* const kModels[][2] = {
    {"table.yaml", "type: table, file: data.csv"},
    {"rao.yaml", "type: rao, file: data.csv"},
    {"wamit_rao.yaml", "type: rao, wamit: data.csv"},
};

const std::filesystem::path& directory() {
  static const std::filesystem::path dir = [] {
    auto d = std::filesystem::temp_directory_path() /
             ("seaflex_fuzz_input_files_" + std::to_string(::getpid()));
    std::filesystem::create_directories(d);
    for (const auto& [name, motion] : kModels)
      std::ofstream(d / name) << "environment:\n"
                                 "  gravity: 9.81\n"
                                 "  water: {density: 1025, depth: 100}\n"
                                 "  waves: {type: airy, height: 2.0, period: 10.0, direction: 0}\n"
                                 "bodies:\n"
                                 "  vessel:\n"
                                 "    type: rigid_body\n"
                                 "    mass: 1.0e6\n"
                                 "    inertia: [1.0e8, 1.0e8, 1.0e8]\n"
                                 "    position: [0, 0, 0]\n"
                                 "    motion: {"
                              << motion
                              << "}\n"
                                 "dynamics: {integrator: rk4, time_step: 0.1, duration: 1}\n";
    return d;
  }();
  return dir;
}

void load(const std::filesystem::path& path) {
  try {
    seaflex::io::Model model = seaflex::io::load_model_file(path.string());
    (void)model;
  } catch (const seaflex::InputError&) {
  } catch (const seaflex::ModelError&) {
  } catch (const std::exception& e) {
    std::fprintf(stderr, "unexpected exception from %s: %s\n", path.c_str(), e.what());
    std::abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto file = directory() / "data.csv";
  std::ofstream(file, std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  for (const auto& model : kModels) load(directory() / model[0]);
  load(file);  // the bytes as a model file read from disk
  return 0;
}
