#include "seaflex/hydro/rao_table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <map>
#include <numbers>
#include <sstream>

#include "seaflex/core/errors.hpp"
#include "seaflex/core/input_file.hpp"

namespace seaflex::hydro {

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr std::size_t kMaxProblems = 20;

const std::vector<std::string> kPlainColumns{"period_s", "heading_deg", "surge_amp", "surge_phase",
                                             "sway_amp", "sway_phase",  "heave_amp", "heave_phase",
                                             "roll_amp", "roll_phase",  "pitch_amp", "pitch_phase",
                                             "yaw_amp",  "yaw_phase"};
const std::vector<std::string> kWamitColumns{"PER", "BETA", "I", "Mod", "Pha", "Re", "Im"};

struct Problems {
  std::string file;
  std::vector<Diagnostic> list;
  void add(int line, std::string key, std::string message) {
    if (list.size() < kMaxProblems)
      list.push_back(Diagnostic{file, line, 0, std::move(key), std::move(message)});
  }
};

// fields split at commas and white space (an empty field between two commas counts as
// missing: the row then has too few columns)
std::vector<std::string> split(std::string line) {
  std::replace(line.begin(), line.end(), ',', ' ');
  std::vector<std::string> out;
  std::istringstream in(line);
  std::string field;
  while (in >> field) out.push_back(field);
  return out;
}

bool parse(const std::string& token, double& out) {
  std::string text(token);
  for (char& c : text)
    if (c == 'D' || c == 'd') c = 'E';
  const char* first = text.data();
  const char* last = first + text.size();
  if (first != last && *first == '+') ++first;
  const auto [ptr, ec] = std::from_chars(first, last, out);
  return ec == std::errc() && ptr == last && !text.empty();
}

// rows of numbers: '#' lines, blank lines and one leading header are skipped; problems
// name the column of `columns`; returns (line, values) of the complete rows
std::vector<std::pair<int, std::vector<double>>> read_rows(
    Problems& p, const std::vector<std::string>& columns) {
  std::istringstream in;
  try {
    in.str(read_input_file(p.file, "RAO file", kMaxDataFileBytes, "file"));
  } catch (const InputError& e) {
    for (const auto& d : e.diagnostics()) p.add(0, d.key, d.message);
    return {};
  }
  std::vector<std::pair<int, std::vector<double>>> rows;
  std::string line;
  int n = 0;
  bool first = true;
  while (std::getline(in, line)) {
    ++n;
    const auto s = line.find_first_not_of(" \t\r");
    if (s == std::string::npos || line[s] == '#') continue;
    const auto fields = split(line);
    double dummy = 0.0;
    if (first && !fields.empty() && !parse(fields[0], dummy)) {
      first = false;
      continue;
    }
    first = false;
    if (fields.size() < columns.size()) {
      p.add(n, columns[fields.size()],
            fmt::format("missing: the row has {} of {} columns ({})", fields.size(), columns.size(),
                        fmt::join(columns, ", ")));
      continue;
    }
    std::vector<double> v(columns.size());
    bool ok = true;
    for (std::size_t c = 0; c < columns.size(); ++c) {
      if (!parse(fields[c], v[c]) || !std::isfinite(v[c])) {
        p.add(n, columns[c], fmt::format("expected a finite number, got '{}'", fields[c]));
        ok = false;
      }
    }
    if (ok) rows.emplace_back(n, std::move(v));
  }
  return rows;
}

// key (period, heading) in rounded form, for finding rows of the same grid point
using GridKey = std::pair<long long, long long>;
GridKey grid_key(double period, double heading_deg) {
  return {std::llround(period * 1e9), std::llround(heading_deg * 1e9)};
}

// assembles the grid from (line, period, heading_deg, mode 0..5, H) entries, checking
// for gaps
struct Entry {
  int line;
  double period, heading_deg;
  int mode;
  std::complex<double> H;
};
RaoTable assemble(Problems& p, const std::vector<Entry>& entries, bool need_all_modes) {
  std::map<long long, double> periods, headings;
  std::map<GridKey, std::pair<int, Vec6c>> cells;
  std::map<GridKey, std::array<int, 6>> seen;
  for (const Entry& e : entries) {
    const GridKey k = grid_key(e.period, e.heading_deg);
    periods[k.first] = e.period;
    headings[k.second] = e.heading_deg;
    auto& cell = cells[k];
    if (cell.first == 0) cell = {e.line, Vec6c::Zero()};
    auto& marks = seen[k];
    if (marks[e.mode] != 0) {
      if (need_all_modes && e.mode != 0) continue;  // a plain row: reported once
      p.add(e.line, "table",
            fmt::format("period {:g} s, heading {:g} deg{} is given twice (first at line {})",
                        e.period, e.heading_deg,
                        need_all_modes ? "" : fmt::format(", mode {}", e.mode + 1), marks[e.mode]));
      continue;
    }
    marks[e.mode] = e.line;
    cell.second[e.mode] = e.H;
  }
  RaoTable t;
  if (cells.empty()) {
    if (p.list.empty()) p.add(0, "table", "the file holds no RAO rows");
    return t;
  }
  // every period at every heading
  for (const auto& [pk, period] : periods)
    for (const auto& [hk, heading] : headings)
      if (!cells.count({pk, hk}))
        p.add(0, "table",
              fmt::format("gap: period {:g} s is missing at heading {:g} deg (every period must "
                          "be given at every heading)",
                          period, heading));
  if (!p.list.empty()) return t;
  // periods -> ascending omega
  std::vector<std::pair<double, long long>> by_omega;
  for (const auto& [pk, period] : periods) {
    if (!(period > 0.0)) {
      p.add(0, "period_s", fmt::format("periods must be positive, got {:g} s", period));
      return t;
    }
    by_omega.emplace_back(2.0 * std::numbers::pi / period, pk);
  }
  std::sort(by_omega.begin(), by_omega.end());
  t.data.has_excitation = true;
  for (const auto& [w, pk] : by_omega) t.data.omega.push_back(w);
  for (const auto& [hk, heading] : headings) {
    t.data.headings.push_back(heading * kDeg);
    std::vector<Vec6c> row;
    for (const auto& [w, pk] : by_omega) row.push_back(cells.at({pk, hk}).second);
    t.data.excitation.push_back(std::move(row));
  }
  return t;
}

}  // namespace

RaoTable read_rao_table(const std::string& path, RaoPhase phase) {
  Problems p{path, {}};
  const auto rows = read_rows(p, kPlainColumns);
  std::vector<Entry> entries;
  const double sign = phase == RaoPhase::kLead ? 1.0 : -1.0;
  for (const auto& [line, v] : rows) {
    bool ok = true;
    if (!(v[0] > 0.0)) {
      p.add(line, "period_s", fmt::format("must be positive, got {:g} s", v[0]));
      ok = false;
    }
    for (int j = 0; j < 6; ++j)
      if (v[2 + 2 * j] < 0.0) {
        p.add(line, kPlainColumns[2 + 2 * j],
              fmt::format("an amplitude cannot be negative, got {:g}", v[2 + 2 * j]));
        ok = false;
      }
    if (!ok) continue;
    for (int j = 0; j < 6; ++j) {
      const double amp = v[2 + 2 * j] * (j < 3 ? 1.0 : kDeg);
      entries.push_back({line, v[0], v[1], j, std::polar(amp, sign * v[3 + 2 * j] * kDeg)});
    }
  }
  RaoTable t = assemble(p, entries, true);
  if (!p.list.empty()) throw InputError(p.list);
  return t;
}

RaoTable read_wamit_rao(const std::string& path, double ulen, RaoPhase phase) {
  Problems p{path, {}};
  const auto rows = read_rows(p, kWamitColumns);
  std::vector<Entry> entries;
  const double sign = phase == RaoPhase::kLead ? 1.0 : -1.0;
  std::map<GridKey, std::array<bool, 6>> modes;
  for (const auto& [line, v] : rows) {
    if (v[0] <= 0.0) continue;  // zero and infinite frequency rows carry no motion
    const double i = v[2];
    if (i != std::floor(i) || i < 1.0) {
      p.add(line, "I", fmt::format("expected a mode 1 to 6, got {:g}", i));
      continue;
    }
    if (i > 6.0) continue;  // generalized modes
    const int j = static_cast<int>(i) - 1;
    // WAMIT manual sec. 4.4: Xi_j / A, times L for rotations (nondimensional by ULEN)
    const double scale = j < 3 ? 1.0 : 1.0 / ulen;
    const std::complex<double> H(v[5] * scale, sign * v[6] * scale);
    entries.push_back({line, v[0], v[1], j, H});
    modes[grid_key(v[0], v[1])][j] = true;
  }
  for (const auto& [k, m] : modes)
    for (int j = 0; j < 6; ++j)
      if (!m[j])
        p.add(0, "I",
              fmt::format("mode {} is missing at period {:g} s, heading {:g} deg", j + 1,
                          k.first * 1e-9, k.second * 1e-9));
  RaoTable t = assemble(p, entries, false);
  if (!p.list.empty()) throw InputError(p.list);
  return t;
}

}  // namespace seaflex::hydro
