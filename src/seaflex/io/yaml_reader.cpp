#include "seaflex/io/yaml_reader.hpp"

#include <fmt/format.h>
#include <yaml-cpp/eventhandler.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <sstream>

namespace seaflex::io {

void Diagnostics::error(const YAML::Mark& mark, std::string key, std::string message) {
  Diagnostic d;
  d.file = file_;
  d.line = mark.is_null() ? 0 : mark.line + 1;
  d.column = mark.is_null() ? 0 : mark.column + 1;
  d.key = std::move(key);
  d.message = std::move(message);
  list_.push_back(std::move(d));
}

void Diagnostics::throw_if_any() const {
  if (list_.empty()) return;
  std::vector<Diagnostic> sorted = list_;
  std::stable_sort(sorted.begin(), sorted.end(), [](const Diagnostic& a, const Diagnostic& b) {
    return std::tie(a.line, a.column) < std::tie(b.line, b.column);
  });
  throw InputError(std::move(sorted));
}

namespace {

int lower(char c) {
  return std::tolower(static_cast<unsigned char>(c));
}

// Levenshtein distance (case-insensitive) when it is at most k, else k + 1: Ukkonen's band,
// only the cells with |i - j| <= k can hold a distance <= k (E. Ukkonen, "Algorithms for
// approximate string matching", Information and Control 64, 1985). O(min(|a|, |b|) k)
// operations instead of O(|a| |b|); *cells counts the cells filled.
std::size_t bounded_edit_distance(std::string_view a, std::string_view b, std::size_t k,
                                  std::size_t* cells) {
  if (a.size() > b.size()) std::swap(a, b);
  if (b.size() - a.size() > k) return k + 1;
  const std::size_t over = k + 1;
  std::vector<std::size_t> prev(b.size() + 1, over), cur(b.size() + 1, over);
  for (std::size_t j = 0; j <= std::min(b.size(), k); ++j) prev[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    const std::size_t lo = i > k ? i - k : 1;
    const std::size_t hi = std::min(b.size(), i + k);
    cur[lo - 1] = lo == 1 && i <= k ? i : over;
    std::size_t row_min = cur[lo - 1];
    for (std::size_t j = lo; j <= hi; ++j) {
      const std::size_t sub = prev[j - 1] + (lower(a[i - 1]) == lower(b[j - 1]) ? 0 : 1);
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, sub, over});
      row_min = std::min(row_min, cur[j]);
    }
    if (hi < b.size()) cur[hi + 1] = over;
    *cells += hi - lo + 1;
    // every later row is at least this row's minimum
    if (row_min > k) return over;
    std::swap(prev, cur);
  }
  return std::min(prev[b.size()], over);
}

}  // namespace

std::string closest_match(std::string_view name, const std::vector<std::string>& candidates,
                          std::size_t* work) {
  std::size_t cells = 0;
  std::string best;
  if (name.size() <= kMaxSuggestedLength) {
    // no candidate is accepted beyond a third of the longer name: the band of the search
    std::size_t longest = name.size();
    for (const auto& c : candidates)
      if (c.size() <= kMaxSuggestedLength) longest = std::max(longest, c.size());
    const std::size_t cutoff = std::max<std::size_t>(1, longest / 3);
    std::size_t best_d = cutoff + 1;
    for (const auto& c : candidates) {
      if (c.size() > kMaxSuggestedLength || best_d == 0) continue;
      // the first of equally close candidates wins: a later one must be strictly closer
      const std::size_t d = bounded_edit_distance(name, c, best_d - 1, &cells);
      if (d < best_d) {
        best_d = d;
        best = c;
      }
    }
    // close enough: at most a third of the longer name, and at least one letter
    const std::size_t limit = std::max<std::size_t>(1, std::max(name.size(), best.size()) / 3);
    if (best.empty() || best_d > limit) best.clear();
  }
  if (work != nullptr) *work = cells;
  return best;
}

std::string suggestion(std::string_view name, const std::vector<std::string>& candidates) {
  const std::string best = closest_match(name, candidates);
  if (!best.empty()) return fmt::format("did you mean '{}'?", best);
  if (candidates.empty()) return "nothing is expected here";
  return fmt::format("expected one of: {}", fmt::join(candidates, ", "));
}

std::string describe(const YAML::Node& node) {
  switch (node.Type()) {
    case YAML::NodeType::Scalar:
      return fmt::format("'{}'", node.Scalar());
    case YAML::NodeType::Sequence:
      return "a list";
    case YAML::NodeType::Map:
      return "a mapping";
    case YAML::NodeType::Null:
      return "nothing";
    default:
      return "nothing";
  }
}

std::optional<double> read_number(Diagnostics& diag, const YAML::Node& node, const std::string& key,
                                  const NumberRule& rule) {
  const std::string in_unit = rule.unit.empty() ? "" : " in " + rule.unit;
  const std::string unit = rule.unit.empty() ? "" : " " + rule.unit;
  if (!node.IsScalar()) {
    diag.error(node.Mark(), key,
               fmt::format("expected a number{}, got {}", in_unit, describe(node)));
    return std::nullopt;
  }
  const std::string& s = node.Scalar();
  double value = 0.0;
  const char* first = s.data();
  const char* last = s.data() + s.size();
  if (first != last && *first == '+') ++first;
  const auto [ptr, ec] = std::from_chars(first, last, value);
  if (ec != std::errc() || ptr != last || s.empty()) {
    diag.error(node.Mark(), key, fmt::format("expected a number{}, got '{}'", in_unit, s));
    return std::nullopt;
  }
  if (!std::isfinite(value)) {
    diag.error(node.Mark(), key, fmt::format("must be a finite number, got '{}'", s));
    return std::nullopt;
  }
  // lengths and coordinates are bounded, so that their differences and squares stay finite
  // (a beam from z = -1e308 to 1e308 had an infinite length, "off by nan")
  if (rule.unit == "m" && std::abs(value) > kMaxLength) {
    diag.error(node.Mark(), key,
               fmt::format("{} m is beyond the bound of {:g} m (100,000 km) on lengths and "
                           "coordinates",
                           s, kMaxLength));
    return std::nullopt;
  }
  const bool low = rule.min_exclusive ? !(value > rule.min) : !(value >= rule.min);
  if (low || value > rule.max) {
    std::string expected;
    if (std::isinf(rule.max))
      expected = fmt::format("{} {:g}{}", rule.min_exclusive ? "greater than" : "at least",
                             rule.min, unit);
    else if (std::isinf(rule.min))
      expected = fmt::format("at most {:g}{}", rule.max, unit);
    else
      expected = fmt::format("between {:g} and {:g}{}", rule.min, rule.max, unit);
    diag.error(node.Mark(), key, fmt::format("must be {}, got {}", expected, s));
    return std::nullopt;
  }
  return value;
}

std::optional<int> read_integer(Diagnostics& diag, const YAML::Node& node, const std::string& key,
                                int min, int max) {
  if (!node.IsScalar()) {
    diag.error(node.Mark(), key, fmt::format("expected a whole number, got {}", describe(node)));
    return std::nullopt;
  }
  const std::string& s = node.Scalar();
  long long value = 0;
  const char* first = s.data() + (!s.empty() && s[0] == '+' ? 1 : 0);
  const auto [ptr, ec] = std::from_chars(first, s.data() + s.size(), value);
  if (ec == std::errc::result_out_of_range ||
      (ec == std::errc() && ptr == s.data() + s.size() && (value < min || value > max))) {
    diag.error(node.Mark(), key, fmt::format("must be between {} and {}, got {}", min, max, s));
    return std::nullopt;
  }
  if (ec != std::errc() || ptr != s.data() + s.size() || s.empty()) {
    diag.error(node.Mark(), key, fmt::format("expected a whole number, got '{}'", s));
    return std::nullopt;
  }
  return static_cast<int>(value);
}

std::optional<Vec3> read_vec3(Diagnostics& diag, const YAML::Node& node, const std::string& key,
                              std::string_view unit) {
  if (!node.IsSequence() || node.size() != 3) {
    diag.error(
        node.Mark(), key,
        fmt::format("expected a list of three numbers [x, y, z]{}{}, got {}",
                    unit.empty() ? "" : " in ", unit,
                    node.IsSequence() ? fmt::format("{} entries", node.size()) : describe(node)));
    return std::nullopt;
  }
  Vec3 v;
  bool ok = true;
  for (int i = 0; i < 3; ++i) {
    const auto x = read_number(diag, node[i], fmt::format("{}[{}]", key, i),
                               NumberRule::any(std::string(unit)));
    if (x)
      v[i] = *x;
    else
      ok = false;
  }
  return ok ? std::optional<Vec3>(v) : std::nullopt;
}

MapReader::MapReader(Diagnostics& diag, YAML::Node node, std::string path)
    : diag_(diag), node_(std::move(node)), path_(std::move(path)) {
  if (!node_.IsMap()) {
    diag_.error(node_.Mark(), path_,
                fmt::format("expected a mapping of keys, got {}", describe(node_)));
    return;
  }
  valid_ = true;
  // duplicate keys: YAML forbids them, yaml-cpp keeps both (and finds the first)
  std::unordered_set<std::string> seen;
  for (const auto& kv : node_) {
    const std::string k = kv.first.Scalar();
    if (!seen.insert(k).second)
      diag_.error(kv.first.Mark(), key_path(k), "duplicate key");
    else if (kv.first.IsScalar())
      children_.emplace(k, kv.second);
  }
}

YAML::Node MapReader::child(std::string_view key) const {
  const auto it = valid_ ? children_.find(std::string(key)) : children_.end();
  return it != children_.end() ? it->second : YAML::Node(YAML::NodeType::Undefined);
}

std::string MapReader::key_path(std::string_view key) const {
  if (key.empty()) return path_;
  return path_.empty() ? std::string(key) : fmt::format("{}.{}", path_, key);
}

bool MapReader::has(std::string_view key) {
  if (known_set_.emplace(key).second) known_.emplace_back(key);
  const YAML::Node n = child(key);
  return n.IsDefined() && !n.IsNull();
}

YAML::Node MapReader::get(std::string_view key, Need need, std::string_view hint) {
  const bool present = has(key);
  if (!present) {
    if (valid_ && need == Need::kRequired)
      diag_.error(node_.Mark(), key_path(key),
                  hint.empty() ? std::string("required key is missing")
                               : fmt::format("required key is missing ({})", hint));
    return YAML::Node(YAML::NodeType::Undefined);
  }
  return child(key);
}

void MapReader::error(std::string_view key, std::string message) {
  const YAML::Node n = child(key);
  diag_.error(n.IsDefined() ? n.Mark() : node_.Mark(), key_path(key), std::move(message));
}

std::optional<double> MapReader::number(std::string_view key, Need need, const NumberRule& rule) {
  const YAML::Node n = get(key, need, rule.unit.empty() ? "" : "a number in " + rule.unit);
  if (!n.IsDefined()) return std::nullopt;
  return read_number(diag_, n, key_path(key), rule);
}

std::optional<int> MapReader::integer(std::string_view key, Need need, int min, int max) {
  const YAML::Node n = get(key, need, "a whole number");
  if (!n.IsDefined()) return std::nullopt;
  return read_integer(diag_, n, key_path(key), min, max);
}

std::optional<std::string> MapReader::text(std::string_view key, Need need) {
  const YAML::Node n = get(key, need);
  if (!n.IsDefined()) return std::nullopt;
  if (!n.IsScalar()) {
    diag_.error(n.Mark(), key_path(key), fmt::format("expected text, got {}", describe(n)));
    return std::nullopt;
  }
  return n.Scalar();
}

std::optional<std::string> MapReader::choice(std::string_view key, Need need,
                                             const std::vector<std::string>& options) {
  const YAML::Node n = get(key, need, fmt::format("one of: {}", fmt::join(options, ", ")));
  if (!n.IsDefined()) return std::nullopt;
  if (!n.IsScalar()) {
    diag_.error(n.Mark(), key_path(key),
                fmt::format("expected one of: {}; got {}", fmt::join(options, ", "), describe(n)));
    return std::nullopt;
  }
  const std::string& v = n.Scalar();
  if (std::find(options.begin(), options.end(), v) != options.end()) return v;
  diag_.error(n.Mark(), key_path(key),
              fmt::format("unknown value '{}'; {}", v, suggestion(v, options)));
  return std::nullopt;
}

std::optional<Vec3> MapReader::vec3(std::string_view key, Need need, std::string_view unit) {
  const YAML::Node n = get(key, need, fmt::format("[x, y, z] in {}", unit));
  if (!n.IsDefined()) return std::nullopt;
  return read_vec3(diag_, n, key_path(key), unit);
}

std::optional<std::vector<std::vector<double>>> MapReader::table(std::string_view key, Need need,
                                                                 int columns,
                                                                 std::string_view first_column) {
  const YAML::Node n = get(key, need, fmt::format("a list of rows of {} numbers", columns));
  if (!n.IsDefined()) return std::nullopt;
  if (!n.IsSequence() || n.size() < 2) {
    diag_.error(n.Mark(), key_path(key),
                fmt::format("expected a list of at least two rows of {} numbers, got {}", columns,
                            n.IsSequence() ? fmt::format("{} rows", n.size()) : describe(n)));
    return std::nullopt;
  }
  std::vector<std::vector<double>> rows;
  bool ok = true;
  for (std::size_t r = 0; r < n.size(); ++r) {
    const YAML::Node row = n[r];
    const std::string rk = fmt::format("{}[{}]", key_path(key), r);
    if (!row.IsSequence() || static_cast<int>(row.size()) != columns) {
      diag_.error(
          row.Mark(), rk,
          fmt::format("expected a row of {} numbers, got {}", columns,
                      row.IsSequence() ? fmt::format("{} entries", row.size()) : describe(row)));
      ok = false;
      continue;
    }
    std::vector<double> values;
    for (int c = 0; c < columns; ++c) {
      const auto x = read_number(diag_, row[c], fmt::format("{}[{}]", rk, c), NumberRule::any(""));
      if (!x) ok = false;
      values.push_back(x.value_or(0.0));
    }
    if (ok && !rows.empty() && !(values[0] > rows.back()[0])) {
      diag_.error(row.Mark(), rk,
                  fmt::format("{} must increase strictly: {} follows {}", first_column, values[0],
                              rows.back()[0]));
      ok = false;
    }
    rows.push_back(std::move(values));
  }
  return ok ? std::optional(rows) : std::nullopt;
}

void MapReader::finish() {
  if (!valid_) return;
  for (const auto& kv : node_) {
    const std::string k = kv.first.Scalar();
    if (known_set_.count(k) == 0) {
      std::vector<std::string> options = known_;
      std::sort(options.begin(), options.end());
      options.erase(std::unique(options.begin(), options.end()), options.end());
      diag_.error(kv.first.Mark(), key_path(k),
                  fmt::format("unknown key; {}", suggestion(k, options)));
    }
  }
}

namespace {

// Watches the parser's events for the document after the first: where its first node is,
// and whether it has one. Only the start of that document is needed.
class SecondDocumentProbe final : public YAML::EventHandler {
 public:
  void OnDocumentStart(const YAML::Mark& mark) override { start = mark; }
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark& mark, YAML::anchor_t) override { node(mark, false); }
  void OnAlias(const YAML::Mark& mark, YAML::anchor_t) override { node(mark, true); }
  void OnScalar(const YAML::Mark& mark, const std::string&, YAML::anchor_t,
                const std::string&) override {
    node(mark, true);
  }
  void OnSequenceStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t,
                       YAML::EmitterStyle::value) override {
    node(mark, true);
  }
  void OnSequenceEnd() override {}
  void OnMapStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t,
                  YAML::EmitterStyle::value) override {
    node(mark, true);
  }
  void OnMapEnd() override {}

  YAML::Mark start = YAML::Mark::null_mark();
  YAML::Mark first_node = YAML::Mark::null_mark();
  bool any_node = false;  // an event of any node, null included
  bool content = false;   // a node that is not null

 private:
  void node(const YAML::Mark& mark, bool not_null) {
    if (!any_node) first_node = mark;
    any_node = true;
    content = content || not_null;
  }
};

class NullHandler final : public YAML::EventHandler {
 public:
  void OnDocumentStart(const YAML::Mark&) override {}
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark&, YAML::anchor_t) override {}
  void OnAlias(const YAML::Mark&, YAML::anchor_t) override {}
  void OnScalar(const YAML::Mark&, const std::string&, YAML::anchor_t,
                const std::string&) override {}
  void OnSequenceStart(const YAML::Mark&, const std::string&, YAML::anchor_t,
                       YAML::EmitterStyle::value) override {}
  void OnSequenceEnd() override {}
  void OnMapStart(const YAML::Mark&, const std::string&, YAML::anchor_t,
                  YAML::EmitterStyle::value) override {}
  void OnMapEnd() override {}
};

}  // namespace

// One document per file. YAML::LoadAll is not used: on some malformed text (a line that
// starts with ',' after a multi-line plain scalar, found by fuzz_input_files) yaml-cpp 0.7's
// parser reports an empty document at the same place forever and LoadAll never returns.
// The first document is loaded with YAML::Load; a second pass over the events asks for at
// most two more documents: a third that starts where the second did means the parser is
// stuck, and that text is reported as a syntax error.
YAML::Node parse_document(const std::string& text, const std::string& name) {
  Diagnostics diag(name);
  try {
    YAML::Node root = YAML::Load(text);
    std::istringstream stream(text);
    YAML::Parser parser(stream);
    NullHandler first;
    SecondDocumentProbe second;
    if (parser.HandleNextDocument(first) && parser.HandleNextDocument(second)) {
      SecondDocumentProbe third;
      const bool stuck = parser.HandleNextDocument(third) && third.start.pos == second.start.pos;
      if (stuck)
        diag.error(second.start, "",
                   "YAML syntax error: this text is not part of the document above it and "
                   "does not start a new one (a plain value cannot start with ',')");
      else if (second.content)
        diag.error(second.first_node, "",
                   "a second YAML document starts here (after '---' or '...'): seaflex reads "
                   "one document per file; delete it, with the '---' or '...' before it, or put "
                   "it in a file of its own");
    }
    diag.throw_if_any();
    return root;
  } catch (const YAML::ParserException& e) {
    diag.error(e.mark, "", fmt::format("YAML syntax error: {}", e.msg));
    diag.throw_if_any();
  }
  return {};
}

}  // namespace seaflex::io
