// Restart files (issue 9): a checkpoint holds everything a run needs to continue exactly
// where it was: the time loop's counters, the state, the integrator's memory and the
// position of every output file. It is text, one entry per line, "key value ...", with
// every double in hexadecimal floating point (%a), so values round-trip bit for bit and
// a resumed run writes the same bytes as one that was never stopped.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "seaflex/core/types.hpp"

namespace seaflex {

class CheckpointWriter {
 public:
  void put(const std::string& key, const std::string& text);  ///< one word, no blanks
  void put(const std::string& key, double value);
  void put(const std::string& key, long value);
  void put(const std::string& key, const VecX& values);
  void put(const std::string& key, const MatX& values);
  const std::string& text() const { return text_; }
  /// Writes the text to path atomically (a temporary file renamed over it): a run killed
  /// while writing leaves the previous checkpoint intact. Throws std::runtime_error.
  void write(const std::string& path) const;

 private:
  std::string text_;
};

class CheckpointReader {
 public:
  /// Reads path; throws InputError (file, line) for a file that is not a checkpoint.
  explicit CheckpointReader(const std::string& path);
  bool has(const std::string& key) const { return entries_.count(key) > 0; }
  std::string text(const std::string& key) const;
  double number(const std::string& key) const;
  long integer(const std::string& key) const;
  VecX vector(const std::string& key) const;
  MatX matrix(const std::string& key) const;

 private:
  const std::vector<std::string>& words(const std::string& key) const;
  std::string path_;
  std::map<std::string, std::vector<std::string>> entries_;
};

}  // namespace seaflex
