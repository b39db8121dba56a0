#include "stats_command.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <map>
#include <sstream>

#include "seaflex/core/errors.hpp"
#include "seaflex/core/input_file.hpp"
#include "seaflex/io/output_selection.hpp"
#include "seaflex/io/yaml_reader.hpp"

namespace seaflex::cli {

namespace {

// the fields of a CSV line; a field in double quotes may hold commas
std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out(1);
  bool quoted = false;
  for (char c : line) {
    if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      out.emplace_back();
    } else {
      out.back() += c;
    }
  }
  return out;
}

// header and rows of a CSV file; InputError when it cannot be read
std::vector<std::vector<std::string>> read_csv(const std::filesystem::path& path,
                                               const std::string& hint) {
  std::istringstream in;
  try {
    in.str(read_input_file(path.string(), "result file", kMaxDataFileBytes));
  } catch (const InputError& e) {
    if (hint.empty()) throw;
    throw InputError(
        {Diagnostic{path.string(), 0, 0, "", e.diagnostics().front().message + "; " + hint}});
  }
  std::vector<std::vector<std::string>> rows;
  std::string line;
  while (std::getline(in, line))
    if (!line.empty()) rows.push_back(split(line));
  return rows;
}

}  // namespace

int cmd_stats(const std::string& dir, const std::vector<std::string>& patterns) {
  const std::filesystem::path d(dir);
  const auto stats = read_csv(d / "statistics.csv",
                              "run a model with a statistics section (docs/model-format.md)");
  if (stats.empty())
    throw InputError({Diagnostic{(d / "statistics.csv").string(), 0, 0, "", "empty"}});
  // most probable maxima by channel and method
  std::map<std::string, std::map<std::string, std::string>> mpm;
  if (input_file_present((d / "extremes.csv").string()))
    for (const auto& row : read_csv(d / "extremes.csv", ""))
      if (row.size() >= 7) mpm[row[0]][row[1]] = row[6];
  std::vector<std::string> names;
  for (std::size_t i = 1; i < stats.size(); ++i) names.push_back(stats[i][0]);
  for (const auto& p : patterns) {
    bool any = false;
    for (const auto& n : names) any = any || io::glob_match(p, n);
    if (!any) {
      const std::string close = io::closest_match(p, names);
      throw InputError({Diagnostic{
          (d / "statistics.csv").string(), 0, 0, "CHANNEL",
          close.empty() ? fmt::format("'{}' matches no channel", p)
                        : fmt::format("'{}' matches no channel; did you mean '{}'?", p, close)}});
    }
  }
  const auto wanted = [&](const std::string& name) {
    if (patterns.empty()) return name.find(".station") == std::string::npos;
    for (const auto& p : patterns)
      if (io::glob_match(p, name)) return true;
    return false;
  };
  // statistics.csv: channel,count,duration,min,max,mean,std,skewness,kurtosis,up_crossings,
  // period,peaks
  fmt::print("{:<32} {:>13} {:>13} {:>13} {:>13} {:>9} {:>9} {:>10} {:>7} {:>13} {:>13} {:>13}\n",
             "channel", "min", "max", "mean", "std", "skewness", "kurtosis", "Tz (s)", "peaks",
             "MPM rayleigh", "MPM weibull", "MPM gumbel");
  for (std::size_t i = 1; i < stats.size(); ++i) {
    const auto& r = stats[i];
    if (r.size() < 12 || !wanted(r[0])) continue;
    const auto num = [](const std::string& s) { return std::stod(s); };
    const auto& m = mpm[r[0]];
    const auto extreme = [&](const char* method) {
      const auto it = m.find(method);
      return it == m.end() || it->second.empty() ? std::string("-")
                                                 : fmt::format("{:.6g}", num(it->second));
    };
    fmt::print(
        "{:<32} {:>13.6g} {:>13.6g} {:>13.6g} {:>13.6g} {:>9.4f} {:>9.4f} {:>10.4g} {:>7} {:>13} "
        "{:>13} {:>13}\n",
        r[0], num(r[3]), num(r[4]), num(r[5]), num(r[6]), num(r[7]), num(r[8]), num(r[10]), r[11],
        extreme("rayleigh"), extreme("weibull"), extreme("gumbel"));
  }
  if (stats.size() > 1 && stats[1].size() >= 3)
    fmt::print(
        "{} rows over {} s from statistics.start; Tz the mean up-crossing period; MPM the most "
        "probable maximum in the storm of extremes.csv; units those of each channel\n",
        stats[1][1], stats[1][2]);
  return 0;
}

}  // namespace seaflex::cli
