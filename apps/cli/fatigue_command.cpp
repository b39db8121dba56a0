#include "fatigue_command.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <vector>

#include "seaflex/core/errors.hpp"
#include "seaflex/core/input_file.hpp"
#include "seaflex/core/output_file.hpp"
#include "seaflex/io/yaml_reader.hpp"

namespace fs = std::filesystem;

namespace seaflex::cli {

namespace {

constexpr double kYear = 365.25 * 86400.0;  // s

struct Case {
  std::string name, folder, model;  // model: run it into folder
  double probability = 0.0, hs = NAN, tp = NAN, heading = NAN;
  YAML::Mark mark;
  std::string key;
};

// a CSV of numbers with a header line: columns by name
struct Table {
  std::vector<std::string> header;
  std::vector<std::vector<double>> rows;
  int column(const std::string& name) const {
    for (std::size_t i = 0; i < header.size(); ++i)
      if (header[i] == name) return static_cast<int>(i);
    return -1;
  }
};

std::optional<Table> read_table(const fs::path& path) {
  std::istringstream in(read_input_file(path.string(), "fatigue result", kMaxDataFileBytes));
  Table t;
  std::string line, cell;
  if (!std::getline(in, line)) return std::nullopt;
  std::stringstream hs(line);
  while (std::getline(hs, cell, ',')) t.header.push_back(cell);
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    std::vector<double> row;
    std::stringstream ls(line);
    while (std::getline(ls, cell, ',')) row.push_back(std::strtod(cell.c_str(), nullptr));
    if (row.size() != t.header.size()) return std::nullopt;
    t.rows.push_back(std::move(row));
  }
  return t;
}

// the beams of a result folder: every <beam>.fatigue.csv (not the statics ones), sorted
std::vector<std::string> fatigue_beams(const fs::path& folder) {
  std::vector<std::string> beams;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(folder, ec)) {
    const std::string name = e.path().filename().string();
    const std::string suffix = ".fatigue.csv";
    if (name.size() > suffix.size() && name.ends_with(suffix) && !name.starts_with("statics."))
      beams.push_back(name.substr(0, name.size() - suffix.size()));
  }
  std::sort(beams.begin(), beams.end());
  return beams;
}

}  // namespace

int cmd_fatigue(const std::string& file, const std::string& dir,
                const std::function<int(const std::string&, const std::string&)>& run_model) {
  io::Diagnostics diag(file);
  const YAML::Node root =
      io::parse_document(read_input_file(file, "scatter diagram file", kMaxModelFileBytes), file);
  io::MapReader top(diag, root, "");
  if (!top.valid()) diag.throw_if_any();
  bool normalise = false;
  if (top.has("normalise")) {
    const auto v = top.choice("normalise", io::Need::kOptional, {"true", "false"});
    normalise = v && *v == "true";
  }
  const fs::path base = fs::path(file).parent_path();
  const YAML::Node list =
      top.get("cases", io::Need::kRequired, "a list of {result: DIR or model: FILE, probability}");
  std::vector<Case> cases;
  if (list.IsDefined() && (!list.IsSequence() || list.size() == 0))
    top.error("cases",
              fmt::format("expected a non-empty list of load cases, got {}", io::describe(list)));
  else if (list.IsDefined())
    for (std::size_t i = 0; i < list.size(); ++i) {
      const std::string key = fmt::format("cases[{}]", i);
      io::MapReader r(diag, list[i], key);
      if (!r.valid()) continue;
      Case c;
      c.mark = list[i].Mark();
      c.key = key;
      c.name = r.text("name", io::Need::kOptional).value_or(fmt::format("case{}", i));
      c.probability =
          r.number("probability", io::Need::kRequired, io::NumberRule::range(0.0, 1.0, ""))
              .value_or(0.0);
      c.hs = r.number("hs", io::Need::kOptional, io::NumberRule::nonnegative("m")).value_or(NAN);
      c.tp = r.number("tp", io::Need::kOptional, io::NumberRule::positive("s")).value_or(NAN);
      c.heading =
          r.number("heading", io::Need::kOptional, io::NumberRule::any("deg")).value_or(NAN);
      const auto result = r.text("result", io::Need::kOptional);
      const auto model = r.text("model", io::Need::kOptional);
      if (result && model)
        r.error("model",
                "give either result (a finished run's folder) or model (to run), not both");
      else if (!result && !model)
        r.error("result", "required key is missing (a finished run's folder, or model: FILE)");
      else if (result)
        c.folder = (base / *result).string();
      else {
        c.folder = (fs::path(dir) / c.name).string();
        c.model = (base / *model).string();
      }
      r.finish();
      cases.push_back(std::move(c));
    }
  top.finish();
  diag.throw_if_any();
  double sum = 0.0;
  for (const auto& c : cases) sum += c.probability;
  if (std::abs(sum - 1.0) > 1e-6) {
    if (!normalise) {
      diag.error(list.Mark(), "cases",
                 fmt::format("the probabilities sum to {:.10g}, not 1: correct them, or give "
                             "normalise: true to scale them to 1",
                             sum));
      diag.throw_if_any();
    }
    fmt::print(stderr, "warning: {}: the probabilities sum to {:.10g}; normalised to 1\n", file,
               sum);
  }
  std::error_code ec;
  fs::create_directories(dir, ec);
  // run the cases given as models
  for (const auto& c : cases) {
    if (c.model.empty()) continue;
    fmt::print("fatigue: running {} into {}\n", c.model, c.folder);
    const int code = run_model(c.model, c.folder);
    if (code != 0) return code;
  }
  // the beams, from the first case; every case must have the same
  const std::vector<std::string> beams = fatigue_beams(cases.front().folder);
  for (const auto& c : cases) {
    const auto here = fatigue_beams(c.folder);
    if (here.empty() || here != beams)
      diag.error(c.mark, c.key,
                 here.empty() ? fmt::format("no fatigue results (<beam>.fatigue.csv) in {}: run "
                                            "the case with a fatigue section first",
                                            c.folder)
                              : fmt::format("the fatigue results in {} are for other beams than "
                                            "those of {}",
                                            c.folder, cases.front().folder));
  }
  diag.throw_if_any();
  std::string report;
  double worst_life = INFINITY;
  std::string worst_at;
  for (const auto& beam : beams) {
    std::vector<double> total, s;  // damage per year (station x point), arc length
    int points = 0;
    std::size_t stations = 0;
    for (const auto& c : cases) {
      const fs::path path = fs::path(c.folder) / (beam + ".fatigue.csv");
      const auto t = read_table(path);
      const int exposure = t ? t->column("exposure_s") : -1;
      if (!t || exposure < 0 || t->column("damage_p0") < 0)
        throw InputError({Diagnostic{path.string(), 0, 0, "",
                                     "not a fatigue result of seaflex (columns exposure_s, "
                                     "damage_p0 ...)"}});
      const int p0 = t->column("damage_p0");
      const int n = static_cast<int>(t->header.size()) - p0;
      if (total.empty()) {
        points = n;
        stations = t->rows.size();
        total.assign(stations * static_cast<std::size_t>(points), 0.0);
        for (const auto& row : t->rows) s.push_back(row[static_cast<std::size_t>(t->column("s"))]);
      }
      if (n != points || t->rows.size() != stations)
        throw InputError({Diagnostic{path.string(), 0, 0, "",
                                     "the stations or points differ from the first case's"}});
      for (std::size_t i = 0; i < stations; ++i) {
        const auto& row = t->rows[i];
        const double T = row[static_cast<std::size_t>(exposure)];
        for (int j = 0; j < points; ++j)
          total[i * static_cast<std::size_t>(points) + static_cast<std::size_t>(j)] +=
              c.probability / sum * row[static_cast<std::size_t>(p0 + j)] * kYear / T;
      }
    }
    std::string text = "station,s,worst_point,worst_angle_deg,damage_per_year,life_years\n";
    for (std::size_t i = 0; i < stations; ++i) {
      int w = 0;
      for (int j = 1; j < points; ++j)
        if (total[i * static_cast<std::size_t>(points) + static_cast<std::size_t>(j)] >
            total[i * static_cast<std::size_t>(points) + static_cast<std::size_t>(w)])
          w = j;
      const double d = total[i * static_cast<std::size_t>(points) + static_cast<std::size_t>(w)];
      const double life = d > 0.0 ? 1.0 / d : INFINITY;
      fmt::format_to(std::back_inserter(text), "{},{:.17g},{},{:.17g},{:.17g},{:.17g}\n", i, s[i],
                     w, 360.0 * w / points, d, life);
      if (life < worst_life) {
        worst_life = life;
        worst_at = fmt::format("{} s = {:.4g} m (point {})", beam, s[i], w);
      }
    }
    const fs::path out = fs::path(dir) / (beam + ".fatigue_total.csv");
    write_file_atomically(out, text);  // complete or absent, never through a planted link
    report += fmt::format("wrote {}\n", out.string());
  }
  std::string cases_csv = "name,hs,tp,heading,probability,folder\n";
  for (const auto& c : cases)
    fmt::format_to(std::back_inserter(cases_csv), "{},{:.17g},{:.17g},{:.17g},{:.17g},{}\n", c.name,
                   c.hs, c.tp, c.heading, c.probability / sum, c.folder);
  write_file_atomically(fs::path(dir) / "fatigue_cases.csv", cases_csv);
  fmt::print("{}fatigue: {} load cases; shortest life {:.4g} years at {}\n", report, cases.size(),
             worst_life, worst_at);
  return 0;
}

}  // namespace seaflex::cli
