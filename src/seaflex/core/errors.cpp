#include "seaflex/core/errors.hpp"

#include <fmt/format.h>

namespace seaflex {

std::string Diagnostic::format() const {
  std::string where = file.empty() ? std::string("<model>") : file;
  if (line > 0) where += fmt::format(":{}:{}", line, column);
  if (key.empty()) return fmt::format("{}: {}", where, message);
  return fmt::format("{}: {}: {}", where, key, message);
}

namespace {
std::string join(const std::vector<Diagnostic>& diagnostics) {
  std::string text;
  for (const auto& d : diagnostics) {
    if (!text.empty()) text += '\n';
    text += d.format();
  }
  return text;
}
}  // namespace

InputError::InputError(std::vector<Diagnostic> diagnostics)
    : std::runtime_error(join(diagnostics)), diagnostics_(std::move(diagnostics)) {}

ModelError::ModelError(std::string item, const std::string& message)
    : std::runtime_error(item.empty() ? message : item + ": " + message), item_(std::move(item)) {}

}  // namespace seaflex
