// The exceptions seaflex throws: input errors point at file, line, column and key;
// model errors name an item; solver errors carry the simulated time and the worst
// coordinate. The CLI maps InputError/ModelError to exit code 2 and SolverError to 3.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace seaflex {

/// One problem found in an input file. line and column are 1-based; 0 means unknown.
struct Diagnostic {
  std::string file;
  int line = 0;
  int column = 0;
  std::string key;  ///< dotted path of the offending key, e.g. "bodies.beam.elements"
  std::string message;

  /// "file:line:col: key: message"
  std::string format() const;
};

/// A model file that cannot be accepted. Holds every problem found, in file order.
class InputError : public std::runtime_error {
 public:
  explicit InputError(std::vector<Diagnostic> diagnostics);
  const std::vector<Diagnostic>& diagnostics() const { return diagnostics_; }

 private:
  std::vector<Diagnostic> diagnostics_;
};

/// A model that is well-formed but inconsistent (e.g. an unconstrained mechanism).
class ModelError : public std::runtime_error {
 public:
  ModelError(std::string item, const std::string& message);
  const std::string& item() const { return item_; }

 private:
  std::string item_;
};

/// A solver that could not continue: divergence, NaN, Newton failure.
class SolverError : public std::runtime_error {
 public:
  SolverError(const std::string& message, double time) : std::runtime_error(message), time_(time) {}
  double time() const { return time_; }

 private:
  double time_;
};

}  // namespace seaflex
