// Validating access to a YAML model file. Every problem is recorded as a Diagnostic
// (file, line, column, dotted key, message) and reading goes on, so one run reports all
// problems at once (DESIGN.md section 6). Readers remember which keys they were asked
// for; finish() reports every other key as unknown, with a "did you mean" suggestion.
#pragma once

#include <yaml-cpp/yaml.h>

#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "seaflex/core/errors.hpp"
#include "seaflex/core/types.hpp"

namespace seaflex::io {

/// Collects the diagnostics of one model file.
class Diagnostics {
 public:
  explicit Diagnostics(std::string file) : file_(std::move(file)) {}
  void error(const YAML::Mark& mark, std::string key, std::string message);
  bool empty() const { return list_.empty(); }
  std::size_t count() const { return list_.size(); }
  /// Throws InputError with every diagnostic, in file order, when there is any.
  void throw_if_any() const;
  const std::string& file() const { return file_; }

 private:
  std::string file_;
  std::vector<Diagnostic> list_;
};

/// Names longer than this (characters) get no suggestion, and no candidate longer than this
/// is suggested: the search then costs at most candidates x 256 x 171 character comparisons.
inline constexpr std::size_t kMaxSuggestedLength = 256;
/// The closest of the candidates to name by (case-insensitive) edit distance, the first of
/// equally close ones, or "" when none is within a third of the longer name (at least 1).
/// *work, when given, receives the number of edit-distance cells computed.
std::string closest_match(std::string_view name, const std::vector<std::string>& candidates,
                          std::size_t* work = nullptr);
/// "did you mean 'x'?" or "expected one of: a, b, c".
std::string suggestion(std::string_view name, const std::vector<std::string>& candidates);

/// Accepted range of a number, with its unit for messages.
struct NumberRule {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_exclusive = false;
  std::string unit;

  static NumberRule positive(std::string unit) { return {0.0, kInf, true, std::move(unit)}; }
  static NumberRule nonnegative(std::string unit) { return {0.0, kInf, false, std::move(unit)}; }
  static NumberRule any(std::string unit) { return {-kInf, kInf, false, std::move(unit)}; }
  static NumberRule range(double lo, double hi, std::string unit) {
    return {lo, hi, false, std::move(unit)};
  }
  static constexpr double kInf = std::numeric_limits<double>::infinity();
};

enum class Need { kRequired, kOptional };

/// Reads one YAML mapping at a dotted path ("bodies.beam").
class MapReader {
 public:
  /// Reports an error (and reads nothing) when node is not a mapping.
  MapReader(Diagnostics& diag, YAML::Node node, std::string path);

  bool valid() const { return valid_; }
  const std::string& path() const { return path_; }
  std::string key_path(std::string_view key) const;
  YAML::Mark mark() const { return node_.Mark(); }
  Diagnostics& diagnostics() { return diag_; }

  /// Registers key as known; true when present.
  bool has(std::string_view key);
  /// Registers key as known; the node (undefined when absent). Reports it when required.
  YAML::Node get(std::string_view key, Need need = Need::kOptional, std::string_view hint = {});

  std::optional<double> number(std::string_view key, Need need, const NumberRule& rule);
  std::optional<int> integer(std::string_view key, Need need, int min, int max);
  std::optional<std::string> text(std::string_view key, Need need);
  /// One of options (exact match); suggests the closest otherwise.
  std::optional<std::string> choice(std::string_view key, Need need,
                                    const std::vector<std::string>& options);
  std::optional<Vec3> vec3(std::string_view key, Need need, std::string_view unit);
  /// A list of rows of numbers, each with `columns` entries; the first column (named
  /// first_column in messages) increasing strictly.
  std::optional<std::vector<std::vector<double>>> table(std::string_view key, Need need,
                                                        int columns,
                                                        std::string_view first_column = "times");

  /// Records an error at key (or at the map itself when the key is absent).
  void error(std::string_view key, std::string message);

  /// Reports keys that no accessor asked for.
  void finish();

 private:
  Diagnostics& diag_;
  YAML::Node node_;
  std::string path_;
  bool valid_ = false;
  std::vector<std::string> known_;
  // lookups in O(1): yaml-cpp searches a map's keys one by one, which made reading a map
  // of N bodies O(N^2)
  std::unordered_set<std::string> known_set_;
  std::unordered_map<std::string, YAML::Node> children_;  // the first value of each key
  YAML::Node child(std::string_view key) const;
};

/// The bound on the magnitude of every length and coordinate (unit "m"): 1e8 m, beyond any
/// site's coordinates (UTM northings reach 1e7 m), and small enough that differences and
/// squares of lengths stay finite.
inline constexpr double kMaxLength = 1e8;

/// A scalar as a finite double; nullopt (and an error) otherwise. With the unit "m", its
/// magnitude must not exceed kMaxLength.
std::optional<double> read_number(Diagnostics& diag, const YAML::Node& node, const std::string& key,
                                  const NumberRule& rule);
/// A scalar as an int in [min, max].
std::optional<int> read_integer(Diagnostics& diag, const YAML::Node& node, const std::string& key,
                                int min, int max);
/// A sequence of three finite numbers.
std::optional<Vec3> read_vec3(Diagnostics& diag, const YAML::Node& node, const std::string& key,
                              std::string_view unit);
/// Short description of a node for messages: its scalar text or its kind.
std::string describe(const YAML::Node& node);

/// The one YAML document of text (a model or scatter diagram file named file); an undefined
/// node when the text holds none (empty, or only comments). Throws InputError for a syntax
/// error, and for a second document (after '---', or '...' and more than comments) at the
/// line where it starts: yaml-cpp's Load would ignore it silently.
YAML::Node parse_document(const std::string& text, const std::string& file);

}  // namespace seaflex::io
