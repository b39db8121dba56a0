// Restart files (issue 9): a checkpoint holds everything a run needs to continue exactly
// where it was: the time loop's counters, the state, the integrator's memory and the
// position of every output file. It is text, one entry per line, "key value ...", with
// every double in hexadecimal floating point (%a), so values round-trip bit for bit and
// a resumed run writes the same bytes as one that was never stopped.
#pragma once

#include <cstdint>
#include <filesystem>
#include <limits>
#include <map>
#include <string>
#include <string_view>
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
  /// Writes the text to path atomically (a fresh temporary file, created exclusively,
  /// renamed over it): a run killed while writing leaves the previous checkpoint intact,
  /// and a file or link planted under a temporary name is never written. Throws
  /// OutputError (core/output_file.hpp).
  void write(const std::string& path) const;

 private:
  std::string text_;
};

class CheckpointReader {
 public:
  /// The largest checkpoint read (bytes): larger files are refused, not read.
  static constexpr std::uintmax_t kMaxBytes = std::uintmax_t{2} << 30;  // 2 GiB

  /// Reads path (a regular file of at most kMaxBytes); throws InputError (file, line, key)
  /// for a file that is not a checkpoint.
  explicit CheckpointReader(const std::string& path);
  /// Parses text as the checkpoint `name` (for tests and fuzzing).
  CheckpointReader(const std::string& text, const std::string& name);

  bool has(const std::string& key) const { return entries_.count(key) > 0; }
  /// Every key, sorted.
  std::vector<std::string> keys() const;
  std::string text(const std::string& key) const;
  /// Any double (hexadecimal or decimal), infinities and NaN included.
  double number(const std::string& key) const;
  /// A finite double.
  double finite(const std::string& key) const;
  /// A whole number in [lo, hi].
  long integer(const std::string& key, long lo = std::numeric_limits<long>::min(),
               long hi = std::numeric_limits<long>::max()) const;
  VecX vector(const std::string& key) const;
  /// A vector of exactly `size` entries ("the checkpoint is for another model" otherwise).
  VecX vector(const std::string& key, Index size) const;
  MatX matrix(const std::string& key) const;
  MatX matrix(const std::string& key, Index rows, Index cols) const;
  /// Throws InputError "checkpoint:LINE:1: key: message" (the line of key, if present).
  [[noreturn]] void fail(const std::string& key, const std::string& message) const;
  /// A result file the checkpoint continues (recorded under key): it must be a regular
  /// file (not a link) of at least `bytes` bytes; throws InputError naming it otherwise.
  void require_file(const std::string& key, const std::filesystem::path& file,
                    std::uintmax_t bytes) const;
  const std::string& path() const { return path_; }

 private:
  struct Entry {
    int line = 0;
    std::size_t begin = 0, end = 0;  // the words after the key, in text_
  };
  void parse();
  int line_of(const std::string& key) const;
  std::vector<std::string_view> words(const std::string& key) const;
  double parse_number(const std::string& key, std::string_view word) const;
  long parse_count(const std::string& key, std::string_view word, long max) const;
  std::string path_;
  std::string text_;
  std::map<std::string, Entry, std::less<>> entries_;
};

}  // namespace seaflex
