// S-N curves for fatigue: the curves of DNV-RP-C203 "Fatigue design of offshore steel
// structures", edition April 2016 (DNVGL-RP-C203), and user-defined bilinear curves.
//
// The standard's basic design curve (2016, eq. (2.4.1) with the thickness effect of
// eq. (2.4.3)):
//   log10 N = log10 a - m log10( dsigma (t / t_ref)^k )
// with dsigma the stress range in MPa, N the predicted number of cycles to failure, and
// two slopes: m1, log a1 for N <= N_knee and m2 = 5, log a2 for N > N_knee. The knee is at
// N = 1e7 in air (Table 2-1) and N = 1e6 in seawater with cathodic protection (Table 2-2);
// the T curve of tubular joints (Table 2-3) has its knee at 1e7 in air and 1.8e6 with
// cathodic protection. The curves for free corrosion (Table 2-4, and Table 2-3 for T)
// have one slope and no fatigue limit. The table's "fatigue limit at 1e7 cycles" column
// is the stress range at N = 1e7 (on the second segment with cathodic protection).
// The branch is chosen by the stress range: dsigma >= the knee stress of segment 1 uses
// segment 1 (the printed log a values make the two segments meet to about 0.1 %).
// Thickness (2016 section 2.4.3): t_ref = 25 mm for welded connections other than tubular
// joints, 16 mm for tubular joints with the T curve; t = t_ref when t < t_ref; k from the
// tables (for T: 0.25 for SCF <= 10, 0.30 for SCF > 10). The free-corrosion curves take the
// exponent of the same detail category of Table 2-1.
// Units: the public functions take stress ranges in Pa and convert to MPa for the curve.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace seaflex::post {

enum class SnEnvironment { kAir, kSeawaterCp, kFreeCorrosion };

/// A one- or two-slope S-N curve in the form of DNV-RP-C203 eq. (2.4.1) (log N = log a -
/// m log dsigma, dsigma in MPa).
struct SnCurve {
  std::string name;                ///< "D", "F1", ... or "user"
  double m1 = 3.0;                 ///< slope for N <= n_knee
  double log_a1 = 0.0;             ///< intercept for N <= n_knee (dsigma in MPa)
  double m2 = 0.0;                 ///< slope for N > n_knee; 0: one slope
  double log_a2 = 0.0;             ///< intercept for N > n_knee
  double n_knee = 0.0;             ///< cycles where the slope changes (0: one slope)
  double k = 0.0;                  ///< thickness exponent
  double t_ref = 0.025;            ///< reference thickness (m)
  double fatigue_limit_mpa = 0.0;  ///< the table's stress range at 1e7 cycles; 0 if none

  bool bilinear() const { return m2 > 0.0 && n_knee > 0.0; }
  /// The stress range (Pa) at the knee: segment 1 at n_knee; 0 for one slope.
  double knee_stress() const;
  /// Predicted cycles to failure at stress range dsigma (Pa, > 0): eq. (2.4.1).
  double cycles(double dsigma) const;
  /// Damage of one cycle of range dsigma (Pa): 1 / N; 0 for dsigma <= 0.
  double damage(double dsigma) const { return dsigma > 0.0 ? 1.0 / cycles(dsigma) : 0.0; }
};

/// The tabulated curves' names in table order (B1 ... W3, T).
const std::vector<std::string>& dnv_curve_names();
/// The DNV-RP-C203 (2016) curve of that name and environment; nullopt when the name is not
/// tabulated. scf selects the T curve's thickness exponent (0.30 above 10).
std::optional<SnCurve> dnv_curve(std::string_view name, SnEnvironment env, double scf = 1.0);

/// A user-defined curve: one slope (m2 = 0) or two; the knee is where the segments meet,
/// log dsigma* = (log a1 - log a2) / (m1 - m2), N* = 10^(log a1 - m1 log dsigma*).
/// Throws std::invalid_argument when two slopes do not meet (m1 == m2).
SnCurve user_curve(double m1, double log_a1, double m2 = 0.0, double log_a2 = 0.0, double k = 0.0,
                   double t_ref = 0.025);

/// The factor on the stress range for thickness t (m): (t / t_ref)^k for t > t_ref, else
/// 1 (DNV-RP-C203 (2016) eq. (2.4.3) and section 2.4.3).
double thickness_factor(double t, double t_ref, double k);

}  // namespace seaflex::post
