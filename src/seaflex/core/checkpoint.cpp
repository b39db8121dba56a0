#include "seaflex/core/checkpoint.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "seaflex/core/errors.hpp"

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
  const std::string tmp = path + ".tmp";
  std::FILE* f = std::fopen(tmp.c_str(), "wb");
  if (!f) throw std::runtime_error(fmt::format("{}: cannot write: {}", tmp, std::strerror(errno)));
  const bool ok = std::fwrite(text_.data(), 1, text_.size(), f) == text_.size();
  if (std::fclose(f) != 0 || !ok)
    throw std::runtime_error(fmt::format("{}: cannot write the checkpoint", tmp));
  if (std::rename(tmp.c_str(), path.c_str()) != 0)
    throw std::runtime_error(fmt::format("{}: cannot rename to {}", tmp, path));
}

CheckpointReader::CheckpointReader(const std::string& path) : path_(path) {
  std::ifstream in(path);
  if (!in)
    bad(path, "", "cannot open the checkpoint (write one with seaflex run --checkpoint-every T)");
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string key, w;
    if (!(words >> key)) continue;
    std::vector<std::string> list;
    while (words >> w) list.push_back(w);
    entries_[key] = std::move(list);
  }
  if (text("format") != "seaflex-checkpoint-1")
    bad(path, "format", "not a seaflex checkpoint (version 1)");
}

const std::vector<std::string>& CheckpointReader::words(const std::string& key) const {
  const auto it = entries_.find(key);
  if (it == entries_.end()) bad(path_, key, "missing from the checkpoint");
  return it->second;
}

std::string CheckpointReader::text(const std::string& key) const {
  const auto& w = words(key);
  if (w.size() != 1) bad(path_, key, "expected one word");
  return w[0];
}

double CheckpointReader::number(const std::string& key) const {
  const std::string w = text(key);
  char* end = nullptr;
  const double x = std::strtod(w.c_str(), &end);
  if (end == w.c_str() || *end != '\0') bad(path_, key, fmt::format("not a number: '{}'", w));
  return x;
}

long CheckpointReader::integer(const std::string& key) const {
  const std::string w = text(key);
  char* end = nullptr;
  const long x = std::strtol(w.c_str(), &end, 10);
  if (end == w.c_str() || *end != '\0') bad(path_, key, fmt::format("not an integer: '{}'", w));
  return x;
}

VecX CheckpointReader::vector(const std::string& key) const {
  const auto& w = words(key);
  const long n = w.empty() ? -1 : std::strtol(w[0].c_str(), nullptr, 10);
  if (n < 0 || static_cast<long>(w.size()) != n + 1) bad(path_, key, "malformed vector");
  VecX v(n);
  for (long i = 0; i < n; ++i) v[i] = std::strtod(w[i + 1].c_str(), nullptr);
  return v;
}

MatX CheckpointReader::matrix(const std::string& key) const {
  const auto& w = words(key);
  const long r = w.size() >= 2 ? std::strtol(w[0].c_str(), nullptr, 10) : -1;
  const long c = w.size() >= 2 ? std::strtol(w[1].c_str(), nullptr, 10) : -1;
  if (r < 0 || c < 0 || static_cast<long>(w.size()) != r * c + 2)
    bad(path_, key, "malformed matrix");
  MatX m(r, c);
  for (long j = 0; j < c; ++j)
    for (long i = 0; i < r; ++i) m(i, j) = std::strtod(w[2 + j * r + i].c_str(), nullptr);
  return m;
}

}  // namespace seaflex
