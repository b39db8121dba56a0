#include "seaflex/core/checkpoint.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "seaflex/core/errors.hpp"
#include "seaflex/core/output_file.hpp"

namespace seaflex {

namespace {
std::string hex(double x) {
  return fmt::format("{:a}", x);
}

[[noreturn]] void bad(const std::string& path, const std::string& key, const std::string& msg) {
  throw InputError({Diagnostic{path, 0, 0, key, msg}});
}
}  // namespace

void CheckpointWriter::put(const std::string& key, const std::string& text) {
  text_ += fmt::format("{} {}\n", key, text);
}

void CheckpointWriter::put(const std::string& key, double value) {
  text_ += fmt::format("{} {}\n", key, hex(value));
}

void CheckpointWriter::put(const std::string& key, long value) {
  text_ += fmt::format("{} {}\n", key, value);
}

void CheckpointWriter::put(const std::string& key, const VecX& values) {
  text_ += fmt::format("{} {}", key, values.size());
  for (Index i = 0; i < values.size(); ++i) text_ += fmt::format(" {}", hex(values[i]));
  text_ += '\n';
}

void CheckpointWriter::put(const std::string& key, const MatX& values) {
  text_ += fmt::format("{} {} {}", key, values.rows(), values.cols());
  for (Index j = 0; j < values.cols(); ++j)
    for (Index i = 0; i < values.rows(); ++i) text_ += fmt::format(" {}", hex(values(i, j)));
  text_ += '\n';
}

void CheckpointWriter::write(const std::string& path) const {
  write_file_atomically(path, text_);
}

namespace {

// a word of the file for a message: at most 40 characters, control bytes as '?'
std::string shown(std::string_view word) {
  std::string out;
  for (char c : word.substr(0, 40))
    out += (static_cast<unsigned char>(c) < 32 || c == 127) ? '?' : c;
  if (word.size() > 40) out += "...";
  return out;
}

bool blank(char c) {
  return c == ' ' || c == '\t' || c == '\r';
}

}  // namespace

CheckpointReader::CheckpointReader(const std::string& path) : path_(path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (!fs::exists(st))
    bad(path, "", "cannot open the checkpoint (write one with seaflex run --checkpoint-every T)");
  if (!fs::is_regular_file(st))
    bad(path, "", "not a regular file (a directory, device or pipe is not a checkpoint)");
  const std::uintmax_t size = fs::file_size(path, ec);
  if (ec) bad(path, "", fmt::format("cannot read the checkpoint: {}", ec.message()));
  if (size > kMaxBytes)
    bad(path, "",
        fmt::format("{} bytes, more than the limit of {} bytes for a checkpoint", size, kMaxBytes));
  std::ifstream in(path, std::ios::binary);
  if (!in) bad(path, "", fmt::format("cannot open the checkpoint: {}", std::strerror(errno)));
  text_.resize(static_cast<std::size_t>(size));
  in.read(text_.data(), static_cast<std::streamsize>(size));
  text_.resize(static_cast<std::size_t>(in.gcount()));  // a file that shrank meanwhile
  parse();
}

CheckpointReader::CheckpointReader(const std::string& text, const std::string& name)
    : path_(name), text_(text) {
  parse();
}

void CheckpointReader::parse() {
  int line = 0;
  std::size_t pos = 0;
  while (pos < text_.size()) {
    ++line;
    std::size_t end = text_.find('\n', pos);
    if (end == std::string::npos) end = text_.size();
    std::size_t k = pos;
    while (k < end && blank(text_[k])) ++k;
    std::size_t key_end = k;
    while (key_end < end && !blank(text_[key_end])) ++key_end;
    if (key_end > k) {
      std::string key = text_.substr(k, key_end - k);
      const auto [it, fresh] = entries_.try_emplace(key, Entry{line, key_end, end});
      if (!fresh)
        throw InputError(
            {Diagnostic{path_, line, 1, shown(key),
                        fmt::format("appears twice (first on line {})", it->second.line)}});
    }
    pos = end + 1;
  }
  if (!has("format")) bad(path_, "format", "not a seaflex checkpoint (no format line)");
  if (text("format") != "seaflex-checkpoint-1")
    fail("format", "not a seaflex checkpoint (version 1)");
}

std::vector<std::string> CheckpointReader::keys() const {
  std::vector<std::string> list;
  for (const auto& [key, entry] : entries_) list.push_back(key);
  return list;
}

int CheckpointReader::line_of(const std::string& key) const {
  const auto it = entries_.find(key);
  return it == entries_.end() ? 0 : it->second.line;
}

void CheckpointReader::fail(const std::string& key, const std::string& message) const {
  const int line = line_of(key);
  throw InputError({Diagnostic{path_, line, line > 0 ? 1 : 0, key, message}});
}

std::vector<std::string_view> CheckpointReader::words(const std::string& key) const {
  const auto it = entries_.find(key);
  if (it == entries_.end()) bad(path_, key, "missing from the checkpoint");
  std::vector<std::string_view> list;
  const std::string_view all(text_.data() + it->second.begin, it->second.end - it->second.begin);
  std::size_t k = 0;
  while (k < all.size()) {
    while (k < all.size() && blank(all[k])) ++k;
    std::size_t e = k;
    while (e < all.size() && !blank(all[e])) ++e;
    if (e > k) list.push_back(all.substr(k, e - k));
    k = e;
  }
  return list;
}

std::string CheckpointReader::text(const std::string& key) const {
  const auto w = words(key);
  if (w.size() != 1) fail(key, fmt::format("expected one word, got {}", w.size()));
  return std::string(w[0]);
}

double CheckpointReader::parse_number(const std::string& key, std::string_view word) const {
  const std::string w(word);
  char* end = nullptr;
  const double x = std::strtod(w.c_str(), &end);
  if (w.empty() || end != w.c_str() + w.size())
    fail(key, fmt::format("not a number: '{}'", shown(word)));
  return x;
}

long CheckpointReader::parse_count(const std::string& key, std::string_view word, long max) const {
  const std::string w(word);
  char* end = nullptr;
  errno = 0;
  const long n = std::strtol(w.c_str(), &end, 10);
  if (w.empty() || end != w.c_str() + w.size() || errno == ERANGE)
    fail(key, fmt::format("not a whole number: '{}'", shown(word)));
  if (n < 0 || n > max)
    fail(key, fmt::format("a size of {} does not match the {} numbers on the line", n, max));
  return n;
}

double CheckpointReader::number(const std::string& key) const {
  const auto w = words(key);
  if (w.size() != 1) fail(key, fmt::format("expected one number, got {} words", w.size()));
  return parse_number(key, w[0]);
}

double CheckpointReader::finite(const std::string& key) const {
  const double x = number(key);
  if (!std::isfinite(x)) fail(key, fmt::format("must be finite, got {}", x));
  return x;
}

long CheckpointReader::integer(const std::string& key, long lo, long hi) const {
  const auto w = words(key);
  if (w.size() != 1) fail(key, fmt::format("expected one whole number, got {} words", w.size()));
  const std::string s(w[0]);
  char* end = nullptr;
  errno = 0;
  const long x = std::strtol(s.c_str(), &end, 10);
  if (s.empty() || end != s.c_str() + s.size() || errno == ERANGE)
    fail(key, fmt::format("not a whole number: '{}'", shown(w[0])));
  if (x < lo || x > hi) fail(key, fmt::format("must be from {} to {}, got {}", lo, hi, x));
  return x;
}

VecX CheckpointReader::vector(const std::string& key) const {
  const auto w = words(key);
  if (w.empty()) fail(key, "expected a size and numbers, got nothing");
  const long n = parse_count(key, w[0], static_cast<long>(w.size()) - 1);
  if (static_cast<long>(w.size()) != n + 1)
    fail(key,
         fmt::format("a size of {} does not match the {} numbers on the line", n, w.size() - 1));
  VecX v(n);
  for (long i = 0; i < n; ++i) v[i] = parse_number(key, w[static_cast<std::size_t>(i) + 1]);
  return v;
}

VecX CheckpointReader::vector(const std::string& key, Index size) const {
  const auto w = words(key);
  if (!w.empty() && w[0] != std::to_string(size))
    fail(key, fmt::format("has {} entries where the model has {}: the checkpoint is for another "
                          "model or damaged",
                          shown(w[0]), size));
  return vector(key);
}

MatX CheckpointReader::matrix(const std::string& key) const {
  const auto w = words(key);
  if (w.size() < 2) fail(key, "expected rows, columns and numbers");
  const long max = static_cast<long>(w.size()) - 2;
  const long r = parse_count(key, w[0], max), c = parse_count(key, w[1], max);
  if (r * c != max)
    fail(key, fmt::format("{} x {} does not match the {} numbers on the line", r, c, max));
  MatX m(r, c);
  for (long j = 0; j < c; ++j)
    for (long i = 0; i < r; ++i)
      m(i, j) = parse_number(key, w[static_cast<std::size_t>(2 + j * r + i)]);
  return m;
}

MatX CheckpointReader::matrix(const std::string& key, Index rows, Index cols) const {
  const auto w = words(key);
  if (w.size() >= 2 && (w[0] != std::to_string(rows) || w[1] != std::to_string(cols)))
    fail(key, fmt::format("is {} x {} where the model needs {} x {}: the checkpoint is for "
                          "another model or damaged",
                          shown(w[0]), shown(w[1]), rows, cols));
  return matrix(key);
}

void CheckpointReader::require_file(const std::string& key, const std::filesystem::path& file,
                                    std::uintmax_t bytes) const {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status st = fs::symlink_status(file, ec);
  const std::string again =
      "resume needs the files of the run before the checkpoint; start the "
      "run again";
  if (!fs::exists(st)) fail(key, fmt::format("{} is missing: {}", file.string(), again));
  if (fs::is_symlink(st))
    fail(key, fmt::format("{} is a symbolic link (results are never written through a link): {}",
                          file.string(), again));
  if (!fs::is_regular_file(st))
    fail(key, fmt::format("{} is not a regular file: {}", file.string(), again));
  const std::uintmax_t size = fs::file_size(file, ec);
  if (ec) fail(key, fmt::format("{}: {}", file.string(), ec.message()));
  if (size < bytes)
    fail(key, fmt::format("{} has {} bytes, fewer than the {} it had at the checkpoint: it was cut "
                          "or replaced; {}",
                          file.string(), size, bytes, again));
}

}  // namespace seaflex
