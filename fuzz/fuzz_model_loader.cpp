// libFuzzer harness of the model loader (issue 9): any byte string as a model file must
// give a model or an InputError/ModelError naming the problem; never a crash, a hang, a
// leak or another exception. Seed corpus: the examples and tests/bad-input.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "seaflex/core/errors.hpp"
#include "seaflex/io/model_loader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    seaflex::io::Model model = seaflex::io::load_model_text(text, "fuzz.yaml");
    (void)model;
  } catch (const seaflex::InputError&) {
  } catch (const seaflex::ModelError&) {
  } catch (const std::exception& e) {
    // anything else reaches the user as an unlocated "seaflex: error": a loader bug
    std::fprintf(stderr, "unexpected exception: %s\n", e.what());
    std::abort();
  }
  return 0;
}
