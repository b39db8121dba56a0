#include "seaflex/io/model_inputs.hpp"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "seaflex/core/errors.hpp"

namespace seaflex::io {

namespace fs = std::filesystem;

namespace {

// visits at most this many YAML nodes (aliases can repeat a subtree many times)
constexpr long kMaxNodes = 1000000;

[[noreturn]] void refuse(const std::string& file, const std::string& key, const std::string& m) {
  throw InputError({Diagnostic{file, 0, 0, key, m}});
}

void collect(const YAML::Node& node, const std::string& key, const fs::path& dir,
             std::set<std::string>& files, long& visited, const std::string& model) {
  if (++visited > kMaxNodes)
    refuse(model, "",
           fmt::format("more than {} YAML nodes: too large to list its input files", kMaxNodes));
  if (node.IsMap()) {
    for (const auto& kv : node)
      collect(kv.second, kv.first.IsScalar() ? kv.first.Scalar() : "", dir, files, visited, model);
  } else if (node.IsSequence()) {
    for (const auto& item : node) collect(item, key, dir, files, visited, model);
  } else if (node.IsScalar()) {
    const std::string& s = node.Scalar();
    if (s.empty() || s.size() > 4096 || s.find('\0') != std::string::npos) return;
    fs::path p(s);
    if (p.is_relative()) p = dir / p;
    std::error_code ec;
    p = fs::absolute(p, ec).lexically_normal();
    if (ec) return;
    if (key == "wamit")  // read_wamit's files, each used when present
      for (const char* ext : {".1", ".3", ".hst"}) files.insert(p.string() + ext);
    if (fs::is_regular_file(p, ec)) files.insert(p.string());
  }
}

}  // namespace

std::vector<std::string> model_input_files(const std::string& model_file) {
  std::ifstream in(model_file, std::ios::binary);
  if (!in) refuse(model_file, "", "cannot open the model file");
  std::stringstream text;
  text << in.rdbuf();
  YAML::Node root;
  try {
    root = YAML::Load(text.str());
  } catch (const YAML::Exception& e) {
    refuse(model_file, "", fmt::format("YAML syntax error: {}", e.msg));
  }
  std::set<std::string> files;
  long visited = 0;
  std::error_code ec;
  const fs::path dir = fs::absolute(fs::path(model_file), ec).parent_path();
  collect(root, "", dir, files, visited, model_file);
  files.erase(fs::absolute(fs::path(model_file), ec).lexically_normal().string());
  return {files.begin(), files.end()};
}

std::string input_file_hash(const std::string& path, const std::string& key) {
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (!fs::exists(st)) return "absent";
  if (!fs::is_regular_file(st))
    refuse(path, key, "not a regular file (a directory, device or pipe is not an input file)");
  const std::uintmax_t size = fs::file_size(path, ec);
  if (ec || size > kMaxInputFileBytes)
    refuse(path, key,
           fmt::format("{} bytes, more than the limit of {} bytes for an input file", size,
                       kMaxInputFileBytes));
  std::ifstream in(path, std::ios::binary);
  if (!in) refuse(path, key, "cannot open the file");
  std::uint64_t h = 1469598103934665603ull;  // FNV-1a, 64 bits
  std::vector<char> block(1 << 16);
  std::uintmax_t total = 0;
  while (in && total <= kMaxInputFileBytes) {
    in.read(block.data(), static_cast<std::streamsize>(block.size()));
    const auto n = static_cast<std::size_t>(in.gcount());
    for (std::size_t i = 0; i < n; ++i)
      h = (h ^ static_cast<unsigned char>(block[i])) * 1099511628211ull;
    total += n;
    if (n == 0) break;
  }
  return fmt::format("{:016x}", h);
}

}  // namespace seaflex::io
