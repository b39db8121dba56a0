#include "seaflex/post/sn_curve.hpp"

#include <array>
#include <cmath>
#include <stdexcept>

namespace seaflex::post {

namespace {

// DNV-RP-C203 (2016) Table 2-1 (air), Table 2-2 (seawater with cathodic protection),
// Table 2-4 (free corrosion), Table 2-3 (T curve, all three): m1, log a1 of air, log a1 of
// seawater with CP, log a2 (m2 = 5, the same in air and with CP), fatigue limit at 1e7
// cycles (MPa), thickness exponent k, free corrosion m and log a.
struct Row {
  const char* name;
  double m1, log_a1_air, log_a1_cp, log_a2, limit, k, m_fc, log_a_fc;
};
constexpr std::array<Row, 15> kTable = {{
    {"B1", 4.0, 15.117, 14.917, 17.146, 106.97, 0.00, 3.0, 12.436},
    {"B2", 4.0, 14.885, 14.685, 16.856, 93.59, 0.00, 3.0, 12.262},
    {"C", 3.0, 12.592, 12.192, 16.320, 73.10, 0.05, 3.0, 12.115},
    {"C1", 3.0, 12.449, 12.049, 16.081, 65.50, 0.10, 3.0, 11.972},
    {"C2", 3.0, 12.301, 11.901, 15.835, 58.48, 0.15, 3.0, 11.824},
    {"D", 3.0, 12.164, 11.764, 15.606, 52.63, 0.20, 3.0, 11.687},
    {"E", 3.0, 12.010, 11.610, 15.350, 46.78, 0.20, 3.0, 11.533},
    {"F", 3.0, 11.855, 11.455, 15.091, 41.52, 0.25, 3.0, 11.378},
    {"F1", 3.0, 11.699, 11.299, 14.832, 36.84, 0.25, 3.0, 11.222},
    {"F3", 3.0, 11.546, 11.146, 14.576, 32.75, 0.25, 3.0, 11.068},
    {"G", 3.0, 11.398, 10.998, 14.330, 29.24, 0.25, 3.0, 10.921},
    {"W1", 3.0, 11.261, 10.861, 14.101, 26.32, 0.25, 3.0, 10.784},
    {"W2", 3.0, 11.107, 10.707, 13.845, 23.39, 0.25, 3.0, 10.630},
    {"W3", 3.0, 10.970, 10.570, 13.617, 21.05, 0.25, 3.0, 10.493},
    // Table 2-3: T curve for tubular joints (log a printed with two decimals)
    {"T", 3.0, 12.48, 12.18, 16.13, 67.09, 0.25, 3.0, 12.03},
}};

constexpr double kMpa = 1e6;

}  // namespace

double SnCurve::knee_stress() const {
  if (!bilinear()) return 0.0;
  return kMpa * std::pow(10.0, (log_a1 - std::log10(n_knee)) / m1);
}

double SnCurve::cycles(double dsigma) const {
  const double log_s = std::log10(dsigma / kMpa);
  // DNV-RP-C203 (2016) eq. (2.4.1), segment by the stress range
  if (!bilinear() || dsigma >= knee_stress()) return std::pow(10.0, log_a1 - m1 * log_s);
  return std::pow(10.0, log_a2 - m2 * log_s);
}

const std::vector<std::string>& dnv_curve_names() {
  static const std::vector<std::string> kNames = [] {
    std::vector<std::string> names;
    for (const Row& r : kTable) names.emplace_back(r.name);
    return names;
  }();
  return kNames;
}

std::optional<SnCurve> dnv_curve(std::string_view name, SnEnvironment env, double scf) {
  for (const Row& r : kTable) {
    if (name != r.name) continue;
    const bool t_curve = name == "T";
    SnCurve c;
    c.name = std::string(name);  // (from a const char*, GCC 12 -O3 warns -Wrestrict falsely)
    // section 2.4.3: T curve k = 0.25 (SCF <= 10) or 0.30, t_ref 16 mm; else 25 mm
    c.k = t_curve && scf > 10.0 ? 0.30 : r.k;
    c.t_ref = t_curve ? 0.016 : 0.025;
    if (env == SnEnvironment::kFreeCorrosion) {
      c.m1 = r.m_fc;
      c.log_a1 = r.log_a_fc;
      return c;
    }
    c.m1 = r.m1;
    c.log_a1 = env == SnEnvironment::kAir ? r.log_a1_air : r.log_a1_cp;
    c.m2 = 5.0;
    c.log_a2 = r.log_a2;
    c.n_knee = env == SnEnvironment::kAir ? 1e7 : (t_curve ? 1.8e6 : 1e6);
    c.fatigue_limit_mpa = r.limit;
    return c;
  }
  return std::nullopt;
}

SnCurve user_curve(double m1, double log_a1, double m2, double log_a2, double k, double t_ref) {
  SnCurve c;
  c.name = std::string("user");
  c.m1 = m1;
  c.log_a1 = log_a1;
  c.k = k;
  c.t_ref = t_ref;
  if (m2 > 0.0) {
    if (m1 == m2) throw std::invalid_argument("the two slopes of an S-N curve must differ");
    c.m2 = m2;
    c.log_a2 = log_a2;
    const double log_s = (log_a1 - log_a2) / (m1 - m2);  // where the segments meet
    c.n_knee = std::pow(10.0, log_a1 - m1 * log_s);
  }
  return c;
}

double thickness_factor(double t, double t_ref, double k) {
  // DNV-RP-C203 (2016) eq. (2.4.3): t = t_ref for t < t_ref
  return t > t_ref ? std::pow(t / t_ref, k) : 1.0;
}

}  // namespace seaflex::post
