#include "seaflex/hydro/wamit_reader.hpp"

#include <fmt/format.h>

#include <array>
#include <charconv>
#include <cmath>
#include <complex>
#include <map>
#include <numbers>
#include <stdexcept>
#include <string_view>

#include "seaflex/core/errors.hpp"
#include "seaflex/core/input_file.hpp"

namespace seaflex::hydro {

namespace {

constexpr std::size_t kMaxProblems = 20;

// problems found in one file, thrown together
struct Problems {
  std::string file;
  std::vector<Diagnostic> list;
  void add(int line, std::string key, std::string message) {
    if (list.size() < kMaxProblems)
      list.push_back(Diagnostic{file, line, 0, std::move(key), std::move(message)});
  }
  bool full() const { return list.size() >= kMaxProblems; }
  void throw_if_any() const {
    if (!list.empty()) throw InputError(list);
  }
};

// the lines of a WAMIT file: a regular file of at most kMaxDataFileBytes (core/input_file.hpp)
std::vector<std::string> read_lines(const std::string& path) {
  const std::string text = read_input_file(path, "WAMIT file", kMaxDataFileBytes, "file");
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    lines.emplace_back(text, start, end - start);
    start = end + 1;
  }
  return lines;
}

std::vector<std::string_view> split(const std::string& line) {
  std::vector<std::string_view> fields;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    const std::size_t start = i;
    while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    if (i > start) fields.push_back(std::string_view(line).substr(start, i - start));
  }
  return fields;
}

// a finite number, the whole token; Fortran 'D' exponents accepted
bool parse_double(std::string_view token, double& out) {
  std::string text(token);
  for (char& c : text)
    if (c == 'D' || c == 'd') c = 'E';
  const char* first = text.data();
  const char* last = first + text.size();
  if (first != last && *first == '+') ++first;
  const auto [ptr, ec] = std::from_chars(first, last, out);
  return ec == std::errc() && ptr == last && std::isfinite(out);
}

// calls row(line_number, fields) for every data row: blank lines and a first line that
// does not start with a number (a header) are skipped
template <class F>
void for_each_row(const std::vector<std::string>& lines, F&& row) {
  bool first = true;
  for (std::size_t n = 0; n < lines.size(); ++n) {
    const auto fields = split(lines[n]);
    if (fields.empty()) continue;
    double dummy = 0.0;
    if (first && !parse_double(fields[0], dummy)) {
      first = false;
      continue;
    }
    first = false;
    row(static_cast<int>(n + 1), fields);
  }
}

// checks the row has `needed` columns; names the first missing one
bool has_columns(Problems& p, int line, const std::vector<std::string_view>& fields,
                 const std::vector<const char*>& names, std::size_t needed, const char* columns) {
  if (fields.size() >= needed) return true;
  p.add(line, names[fields.size()],
        fmt::format("missing: the row has {} of {} columns ({})", fields.size(), needed, columns));
  return false;
}

bool number(Problems& p, int line, std::string_view token, const char* key, double& out) {
  if (parse_double(token, out)) return true;
  p.add(line, key, fmt::format("expected a number, got '{}'", token));
  return false;
}

enum class ModeResult { kOk, kSkip, kBad };

// a mode index 1..6; larger modes (generalized modes) are skipped
ModeResult mode(Problems& p, int line, std::string_view token, const char* key, int& out) {
  const auto [ptr, ec] = std::from_chars(token.data(), token.data() + token.size(), out);
  if (ec != std::errc() || ptr != token.data() + token.size()) {
    p.add(line, key, fmt::format("expected an integer mode (1 to 6), got '{}'", token));
    return ModeResult::kBad;
  }
  if (out < 1) {
    p.add(line, key, fmt::format("expected a mode >= 1, got {}", out));
    return ModeResult::kBad;
  }
  return out > 6 ? ModeResult::kSkip : ModeResult::kOk;
}

int rotational(int i) {
  return i >= 4 ? 1 : 0;
}

// A_ij = Abar rho L^k, k = 3 + number of rotational indices (manual sec. 4.1)
double mass_scale(int i, int j, const WamitUnits& u) {
  return u.rho * std::pow(u.ulen, 3 + rotational(i) + rotational(j));
}

std::string period_name(double per) {
  if (per == 0.0) return "PER = 0 (infinite frequency)";
  if (per == -1.0) return "PER = -1 (zero frequency)";
  return fmt::format("PER = {} s", per);
}

// ---- <stem>.1 ----

struct RadiationBlock {
  int line = 0;  // first row of this period
  Mat6 a = Mat6::Zero();
  Mat6 b = Mat6::Zero();
  std::array<int, 36> row_line{};  // line of each (i, j); 0 if absent
};

void read_radiation(const std::string& path, const WamitUnits& units, HydroDatabase& db) {
  const auto lines = read_lines(path);
  Problems p{path, {}};
  const std::vector<const char*> names{"PER", "mode i", "mode j", "Abar", "Bbar"};
  std::map<double, RadiationBlock> blocks;  // by PER
  for_each_row(lines, [&](int line, const std::vector<std::string_view>& f) {
    if (p.full()) return;
    double per = 0.0;
    if (!number(p, line, f[0], "PER", per)) return;
    if (!(per > 0.0 || per == 0.0 || per == -1.0)) {
      p.add(line, "PER",
            fmt::format("expected a period > 0 s, 0 (infinite frequency) or -1 (zero "
                        "frequency), got {}",
                        per));
      return;
    }
    if (!has_columns(p, line, f, names, per > 0.0 ? 5 : 4,
                     per > 0.0 ? "PER I J Abar Bbar" : "PER I J Abar"))
      return;
    int i = 0, j = 0;
    const auto ri = mode(p, line, f[1], "mode i", i);
    const auto rj = mode(p, line, f[2], "mode j", j);
    double abar = 0.0, bbar = 0.0;
    const bool ok_a = number(p, line, f[3], "Abar", abar);
    const bool ok_b = per > 0.0 ? number(p, line, f[4], "Bbar", bbar) : true;
    if (ri == ModeResult::kBad || rj == ModeResult::kBad || !ok_a || !ok_b) return;
    if (ri == ModeResult::kSkip || rj == ModeResult::kSkip) return;
    auto& block = blocks[per];
    if (block.line == 0) block.line = line;
    int& seen = block.row_line[static_cast<std::size_t>(6 * (i - 1) + j - 1)];
    if (seen != 0) {
      p.add(line, "mode j",
            fmt::format("duplicate row for {}, (i, j) = ({}, {}); first given at line {}",
                        period_name(per), i, j, seen));
      return;
    }
    seen = line;
    block.a(i - 1, j - 1) = abar;
    block.b(i - 1, j - 1) = bbar;
  });
  p.throw_if_any();

  // the pairs given at any finite period are required at every period
  std::array<bool, 36> required{};
  bool any_finite = false;
  for (const auto& [per, block] : blocks) {
    if (per <= 0.0) continue;
    any_finite = true;
    for (std::size_t k = 0; k < 36; ++k) required[k] = required[k] || block.row_line[k] != 0;
  }
  if (!any_finite) p.add(0, "PER", "no rows with a finite period (PER > 0)");
  for (const auto& [per, block] : blocks) {
    std::string missing;
    int count = 0;
    for (std::size_t k = 0; k < 36; ++k) {
      if (!required[k] || block.row_line[k] != 0) continue;
      if (++count <= 6)
        missing += fmt::format("{}({}, {})", count > 1 ? ", " : "", k / 6 + 1, k % 6 + 1);
    }
    if (count > 6) missing += fmt::format(" and {} more", count - 6);
    if (count > 0)
      p.add(block.line, "modes",
            fmt::format("{} lacks (i, j) = {} given at other periods", period_name(per), missing));
  }
  p.throw_if_any();

  // dimensional, omega ascending = PER descending
  for (auto it = blocks.rbegin(); it != blocks.rend(); ++it) {
    const double per = it->first;
    const auto& block = it->second;
    Mat6 a, b;
    const double w = per > 0.0 ? 2.0 * std::numbers::pi / per : 0.0;
    for (int i = 1; i <= 6; ++i) {
      for (int j = 1; j <= 6; ++j) {
        const double s = mass_scale(i, j, units);
        a(i - 1, j - 1) = block.a(i - 1, j - 1) * s;
        b(i - 1, j - 1) = block.b(i - 1, j - 1) * s * w;
      }
    }
    if (per == 0.0) {
      db.has_added_mass_inf = true;
      db.added_mass_inf = a;
    } else if (per == -1.0) {
      db.has_added_mass_zero = true;
      db.added_mass_zero = a;
    } else {
      db.omega.push_back(w);
      db.added_mass.push_back(a);
      db.damping.push_back(b);
    }
  }
}

// ---- <stem>.3 ----

struct ExcitationBlock {
  int line = 0;
  Vec6c x = Vec6c::Zero();
  std::array<int, 6> row_line{};
};

void read_excitation(const std::string& path, const std::string& path1, const WamitUnits& units,
                     HydroDatabase& db) {
  const auto lines = read_lines(path);
  Problems p{path, {}};
  const std::vector<const char*> names{"PER",    "BETA",  "mode i", "Mod(X)",
                                       "Pha(X)", "Re(X)", "Im(X)"};
  std::map<double, std::map<double, ExcitationBlock>> blocks;  // [PER][BETA]
  std::map<double, int> period_line;
  for_each_row(lines, [&](int line, const std::vector<std::string_view>& f) {
    if (p.full()) return;
    double per = 0.0;
    if (!number(p, line, f[0], "PER", per)) return;
    if (per <= 0.0) return;  // zero or infinite frequency: no excitation used
    if (!has_columns(p, line, f, names, 7, "PER BETA I Mod Pha Re Im")) return;
    double beta = 0.0, v[4] = {0, 0, 0, 0};
    int i = 0;
    bool ok = number(p, line, f[1], "BETA", beta);
    const auto ri = mode(p, line, f[2], "mode i", i);
    for (int c = 0; c < 4; ++c) ok = number(p, line, f[3 + c], names[3 + c], v[c]) && ok;
    if (!ok || ri == ModeResult::kBad) return;
    if (ri == ModeResult::kSkip) return;
    const std::complex<double> x(v[2], v[3]);
    const std::complex<double> x_polar = std::polar(v[0], v[1] * std::numbers::pi / 180.0);
    if (std::abs(x - x_polar) > 1e-4 * std::max(std::abs(v[0]), std::abs(x))) {
      p.add(line, "Re(X)",
            fmt::format("Re, Im = ({}, {}) disagree with Mod, Pha = ({}, {} deg), which give "
                        "({:.7g}, {:.7g})",
                        v[2], v[3], v[0], v[1], x_polar.real(), x_polar.imag()));
      return;
    }
    if (period_line.count(per) == 0) period_line[per] = line;
    auto& block = blocks[per][beta];
    if (block.line == 0) block.line = line;
    int& seen = block.row_line[static_cast<std::size_t>(i - 1)];
    if (seen != 0) {
      p.add(line, "mode i",
            fmt::format("duplicate row for PER = {} s, BETA = {} deg, mode {}; first given at "
                        "line {}",
                        per, beta, i, seen));
      return;
    }
    seen = line;
    block.x(i - 1) = x;
  });
  p.throw_if_any();

  // every heading and mode at every period
  std::map<double, bool> all_headings;
  std::array<bool, 6> required{};
  for (const auto& [per, by_beta] : blocks) {
    for (const auto& [beta, block] : by_beta) {
      all_headings[beta] = true;
      for (std::size_t k = 0; k < 6; ++k) required[k] = required[k] || block.row_line[k] != 0;
    }
  }
  for (const auto& [per, by_beta] : blocks) {
    std::string missing;
    for (const auto& [beta, unused] : all_headings)
      if (by_beta.count(beta) == 0)
        missing += fmt::format("{}{}", missing.empty() ? "" : ", ", beta);
    if (!missing.empty())
      p.add(period_line[per], "headings",
            fmt::format("PER = {} s lacks BETA = {} deg given at other periods", per, missing));
    for (const auto& [beta, block] : by_beta) {
      std::string modes;
      for (std::size_t k = 0; k < 6; ++k)
        if (required[k] && block.row_line[k] == 0)
          modes += fmt::format("{}{}", modes.empty() ? "" : ", ", k + 1);
      if (!modes.empty())
        p.add(block.line, "modes",
              fmt::format("PER = {} s, BETA = {} deg lacks mode(s) {} given at other periods", per,
                          beta, modes));
    }
  }
  // the periods are those of the .1 file
  auto index_of = [&](double per) -> int {
    const double w = 2.0 * std::numbers::pi / per;
    for (std::size_t k = 0; k < db.omega.size(); ++k)
      if (std::abs(db.omega[k] - w) <= 1e-6 * w) return static_cast<int>(k);
    return -1;
  };
  std::vector<bool> covered(db.omega.size(), false);
  for (const auto& [per, by_beta] : blocks) {
    const int k = index_of(per);
    if (k < 0)
      p.add(period_line[per], "PER",
            fmt::format("period {} s is not among the periods of {}", per, path1));
    else
      covered[static_cast<std::size_t>(k)] = true;
  }
  for (std::size_t k = 0; k < covered.size(); ++k)
    if (!covered[k])
      p.add(0, "PER",
            fmt::format("period {:.7g} s of {} has no excitation rows",
                        2.0 * std::numbers::pi / db.omega[k], path1));
  p.throw_if_any();

  for (const auto& [beta, unused] : all_headings)
    db.headings.push_back(beta * std::numbers::pi / 180.0);
  db.excitation.assign(db.headings.size(), std::vector<Vec6c>(db.omega.size(), Vec6c::Zero()));
  for (const auto& [per, by_beta] : blocks) {
    const auto k = static_cast<std::size_t>(index_of(per));
    std::size_t h = 0;
    for (const auto& [beta, block] : by_beta) {
      Vec6c x = block.x;
      // X_i = Xbar rho g L^m, m = 2 (forces), 3 (moments) (manual sec. 4.3)
      for (int i = 0; i < 6; ++i)
        x(i) *= units.rho * units.g * std::pow(units.ulen, 2 + rotational(i + 1));
      db.excitation[h++][k] = x;
    }
  }
  db.has_excitation = !db.headings.empty();
}

// ---- <stem>.hst ----

void read_hydrostatics(const std::string& path, const WamitUnits& units, HydroDatabase& db) {
  const auto lines = read_lines(path);
  Problems p{path, {}};
  const std::vector<const char*> names{"mode i", "mode j", "Cbar"};
  std::array<int, 36> row_line{};
  Mat6 c = Mat6::Zero();
  for_each_row(lines, [&](int line, const std::vector<std::string_view>& f) {
    if (p.full()) return;
    if (!has_columns(p, line, f, names, 3, "I J C")) return;
    int i = 0, j = 0;
    const auto ri = mode(p, line, f[0], "mode i", i);
    const auto rj = mode(p, line, f[1], "mode j", j);
    double cbar = 0.0;
    const bool ok = number(p, line, f[2], "Cbar", cbar);
    if (ri == ModeResult::kBad || rj == ModeResult::kBad || !ok) return;
    if (ri == ModeResult::kSkip || rj == ModeResult::kSkip) return;
    int& seen = row_line[static_cast<std::size_t>(6 * (i - 1) + j - 1)];
    if (seen != 0) {
      p.add(line, "mode j",
            fmt::format("duplicate row for (i, j) = ({}, {}); first given at line {}", i, j, seen));
      return;
    }
    seen = line;
    // C_ij = Cbar rho g L^k, k = 2 + number of rotational indices (manual sec. 4.2)
    c(i - 1, j - 1) =
        cbar * units.rho * units.g * std::pow(units.ulen, 2 + rotational(i) + rotational(j));
  });
  p.throw_if_any();
  db.has_hydrostatics = true;
  db.hydrostatic_stiffness = c;
}

}  // namespace

HydroDatabase read_wamit(const std::string& stem, const WamitUnits& units) {
  if (!(units.rho > 0.0) || !(units.g > 0.0) || !(units.ulen > 0.0))
    throw std::invalid_argument(fmt::format(
        "read_wamit: rho, g and ulen must be > 0, got {}, {}, {}", units.rho, units.g, units.ulen));
  HydroDatabase db;
  const std::string path1 = stem + ".1";
  read_radiation(path1, units, db);
  // optional files: whatever is there (a directory, a dangling link) is read and reported
  if (input_file_present(stem + ".3")) read_excitation(stem + ".3", path1, units, db);
  if (input_file_present(stem + ".hst")) read_hydrostatics(stem + ".hst", units, db);
  return db;
}

}  // namespace seaflex::hydro
