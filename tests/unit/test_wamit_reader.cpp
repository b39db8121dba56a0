// WAMIT reader: the floating hemisphere of tests/data/wamit/sphere (R = 5 m, depth 50 m,
// WAMIT g = 9.81, ULEN = 1) against published values and hand-computed rows, the
// interpolation of HydroDatabase, and every error path with its message.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include "seaflex/core/errors.hpp"
#include "seaflex/hydro/wamit_reader.hpp"

using namespace seaflex::hydro;
using seaflex::InputError;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kRho = 1025.0;
constexpr double kG = 9.81;
constexpr double kR = 5.0;

std::string sphere_stem() {
  return std::string(SEAFLEX_SOURCE_DIR) + "/tests/data/wamit/sphere/sphere";
}

HydroDatabase sphere() {
  return read_wamit(sphere_stem(), WamitUnits{kRho, kG, 1.0});
}

// a fresh directory per test for malformed files
std::filesystem::path temp_dir() {
  const auto* info = testing::UnitTest::GetInstance()->current_test_info();
  auto dir =
      std::filesystem::temp_directory_path() / (std::string("seaflex_wamit_") + info->name());
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

void write(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path) << text;
}

// a small valid .1: two periods, modes 3 and 5 with (3,3), (3,5), (5,3), (5,5)
const char* kGood1 =
    " header line\n"
    "  0.0  3 3  1.0\n"
    "  0.0  5 5  2.0\n"
    "  0.0  3 5  0.1\n"
    "  0.0  5 3  0.1\n"
    "  10.0 3 3  1.5  0.5\n"
    "  10.0 5 5  2.5  0.6\n"
    "  10.0 3 5  0.2  0.01\n"
    "  10.0 5 3  0.2  0.01\n"
    "  5.0  3 3  1.2  0.7\n"
    "  5.0  5 5  2.2  0.8\n"
    "  5.0  3 5  0.3  0.02\n"
    "  5.0  5 3  0.3  0.02\n";

// expects read_wamit(stem) to throw InputError whose diagnostics format to `expected`
void expect_input_error(const std::string& stem, const std::vector<std::string>& expected) {
  try {
    read_wamit(stem, WamitUnits{kRho, kG, 1.0});
    ADD_FAILURE() << "no exception";
  } catch (const InputError& e) {
    ASSERT_EQ(e.diagnostics().size(), expected.size()) << e.what();
    for (std::size_t i = 0; i < expected.size(); ++i)
      EXPECT_EQ(e.diagnostics()[i].format(), expected[i]);
  }
}

}  // namespace

// issue requirements: A33(inf) = 0.5 rho (2/3 pi R^3) (Hulme 1982) and
// C33 = rho g pi R^2, each within 0.2 % (the WAMIT mesh gives both to ~0.1 %)
TEST(WamitReader, SphereInfiniteFrequencyAddedMassAndWaterplaneStiffness) {
  const auto db = sphere();
  ASSERT_TRUE(db.has_added_mass_inf);
  ASSERT_TRUE(db.has_hydrostatics);
  const double volume = 2.0 / 3.0 * kPi * kR * kR * kR;
  EXPECT_NEAR(db.added_mass_inf(2, 2) / (0.5 * kRho * volume), 1.0, 2e-3);
  EXPECT_NEAR(db.hydrostatic_stiffness(2, 2) / (kRho * kG * kPi * kR * kR), 1.0, 2e-3);
}

// 420 finite periods (omega = 0.02 ... 8.38 rad/s), one heading (0 deg), both limits
TEST(WamitReader, SphereCounts) {
  const auto db = sphere();
  ASSERT_EQ(db.omega.size(), 420u);
  EXPECT_EQ(db.added_mass.size(), 420u);
  EXPECT_EQ(db.damping.size(), 420u);
  for (std::size_t k = 1; k < db.omega.size(); ++k) EXPECT_GT(db.omega[k], db.omega[k - 1]);
  EXPECT_NEAR(db.omega.front(), 2 * kPi / 314.1593, 1e-12);
  EXPECT_NEAR(db.omega.back(), 2 * kPi / 0.7479981, 1e-12);
  EXPECT_TRUE(db.has_added_mass_zero);
  EXPECT_TRUE(db.has_excitation);
  ASSERT_EQ(db.headings.size(), 1u);
  EXPECT_EQ(db.headings[0], 0.0);
  ASSERT_EQ(db.excitation.size(), 1u);
  EXPECT_EQ(db.excitation[0].size(), 420u);
}

// sphere.1 lines 398-426 and sphere.3 lines 56-60 (PER = 31.41593 s), sphere.hst (3,3):
// dimensional values by hand; 1e-12 relative (only a product of exact decimal inputs)
TEST(WamitReader, SphereRowByHand) {
  const auto db = sphere();
  const double w = 2 * kPi / 31.41593;
  std::size_t k = 0;
  while (k < db.omega.size() && std::abs(db.omega[k] - w) > 1e-12) ++k;
  ASSERT_LT(k, db.omega.size());
  EXPECT_NEAR(db.added_mass[k](2, 2), 2.232447e2 * kRho, 1e-12 * 2.3e5);  // L^3
  EXPECT_NEAR(db.damping[k](2, 2), 3.362125e1 * kRho * w, 1e-12 * 7e3);   // rho w L^3
  EXPECT_NEAR(db.added_mass[k](0, 4), 2.638250e2 * kRho, 1e-12 * 3e5);    // L^4
  EXPECT_NEAR(db.damping[k](4, 4), 1.519676e-1 * kRho * w, 1e-12 * 50);   // rho w L^5
  const auto& x = db.excitation[0][k];
  EXPECT_NEAR(x(2).real(), 7.654704e1 * kRho * kG, 1e-12 * 8e5);  // rho g L^2
  EXPECT_NEAR(x(2).imag(), 1.371449e-1 * kRho * kG, 1e-12 * 8e5);
  EXPECT_NEAR(x(4).imag(), 7.278945e0 * kRho * kG, 1e-12 * 8e4);  // rho g L^3
  EXPECT_NEAR(db.hydrostatic_stiffness(2, 2), 7.848768e1 * kRho * kG, 1e-12 * 8e5);
  EXPECT_NEAR(db.added_mass_inf(2, 2), 1.308590e2 * kRho, 1e-12 * 2e5);
  EXPECT_NEAR(db.added_mass_zero(2, 2), 2.015387e2 * kRho, 1e-12 * 2e5);
}

// ULEN scales A by L^(3..5), B likewise, X by L^(2..3), C by L^(2..4): reading with
// ulen = 2 multiplies the entries by those powers exactly (1e-12 relative)
TEST(WamitReader, LengthScalePowers) {
  const auto a = sphere();
  const auto b = read_wamit(sphere_stem(), WamitUnits{kRho, kG, 2.0});
  const std::size_t k = 100;
  EXPECT_NEAR(b.added_mass[k](2, 2), 8.0 * a.added_mass[k](2, 2), 1e-12 * b.added_mass[k](2, 2));
  EXPECT_NEAR(b.added_mass[k](0, 4), 16.0 * a.added_mass[k](0, 4),
              1e-9 * std::abs(b.added_mass[k](0, 4)));
  EXPECT_NEAR(b.damping[k](4, 4), 32.0 * a.damping[k](4, 4), 1e-12 * b.damping[k](4, 4));
  EXPECT_NEAR(std::abs(b.excitation[0][k](2)), 4.0 * std::abs(a.excitation[0][k](2)), 1e-6);
  EXPECT_NEAR(std::abs(b.excitation[0][k](4)), 8.0 * std::abs(a.excitation[0][k](4)), 1e-6);
  EXPECT_NEAR(b.hydrostatic_stiffness(3, 3), 16.0 * a.hydrostatic_stiffness(3, 3), 1e-6);
}

// at a tabulated frequency the interpolation returns the table exactly; halfway it
// returns the mean (linear; 1e-9 relative for rounding of s = 0.5); beyond the ends it
// clamps and flags
TEST(WamitReader, ExcitationAndCoefficientInterpolation) {
  const auto db = sphere();
  bool extrapolated = true;
  for (const std::size_t k : {std::size_t{0}, std::size_t{57}, std::size_t{419}}) {
    const Vec6c x = db.excitation_at(db.omega[k], 0.0, &extrapolated);
    EXPECT_FALSE(extrapolated);
    EXPECT_EQ(x, db.excitation[0][k]);
    EXPECT_EQ(db.added_mass_at(db.omega[k]), db.added_mass[k]);
    EXPECT_EQ(db.damping_at(db.omega[k]), db.damping[k]);
  }
  const std::size_t k = 200;
  const double mid = 0.5 * (db.omega[k] + db.omega[k + 1]);
  const Vec6c xm = db.excitation_at(mid, 0.0, &extrapolated);
  EXPECT_FALSE(extrapolated);
  const Vec6c expected = 0.5 * (db.excitation[0][k] + db.excitation[0][k + 1]);
  EXPECT_LT((xm - expected).norm(), 1e-9 * expected.norm());
  const Mat6 am = db.added_mass_at(mid);
  EXPECT_LT((am - 0.5 * (db.added_mass[k] + db.added_mass[k + 1])).norm(), 1e-9 * am.norm());
  // extrapolation: clamped to the nearest end and flagged
  EXPECT_EQ(db.excitation_at(100.0, 0.0, &extrapolated), db.excitation[0].back());
  EXPECT_TRUE(extrapolated);
  EXPECT_EQ(db.excitation_at(0.001, 0.0, &extrapolated), db.excitation[0].front());
  EXPECT_TRUE(extrapolated);
  EXPECT_EQ(db.added_mass_at(100.0), db.added_mass.back());
  // one heading: any other heading is clamped to it and flagged
  bool heading_clamped = false;
  EXPECT_EQ(db.excitation_at(db.omega[k], 0.5, &extrapolated, &heading_clamped),
            db.excitation[0][k]);
  EXPECT_FALSE(extrapolated);
  EXPECT_TRUE(heading_clamped);
  db.excitation_at(db.omega[k], 2 * kPi, &extrapolated, &heading_clamped);
  EXPECT_FALSE(heading_clamped);  // 360 deg is 0 deg
}

// heading interpolation on a synthetic table: 0/90/180/270 deg covers the circle, so
// 315 deg lies halfway between 270 and 360 = 0 deg; 0/90 deg does not, so 135 deg clamps
// to 90 deg and -30 deg to 0 deg (exact arithmetic on small integers: 1e-14)
TEST(WamitReader, HeadingWrapAndClamp) {
  HydroDatabase db;
  db.omega = {1.0, 2.0};
  db.has_excitation = true;
  auto x = [](double v) { return Vec6c::Constant(std::complex<double>(v, -v)); };
  db.headings = {0.0, kPi / 2, kPi, 1.5 * kPi};
  db.excitation = {{x(1), x(1)}, {x(2), x(2)}, {x(3), x(3)}, {x(4), x(4)}};
  bool clamped = true;
  EXPECT_LT((db.excitation_at(1.5, 1.75 * kPi, nullptr, &clamped) - x(2.5)).norm(), 1e-14);
  EXPECT_FALSE(clamped);
  EXPECT_LT((db.excitation_at(1.5, -0.25 * kPi) - x(2.5)).norm(), 1e-14);
  EXPECT_LT((db.excitation_at(1.5, 0.75 * kPi) - x(2.5)).norm(), 1e-14);
  db.headings = {0.0, kPi / 2};
  db.excitation = {{x(1), x(1)}, {x(2), x(2)}};
  EXPECT_LT((db.excitation_at(1.5, 0.75 * kPi, nullptr, &clamped) - x(2)).norm(), 1e-14);
  EXPECT_TRUE(clamped);
  EXPECT_LT((db.excitation_at(1.5, -kPi / 6, nullptr, &clamped) - x(1)).norm(), 1e-14);
  EXPECT_TRUE(clamped);
  EXPECT_LT((db.excitation_at(1.5, kPi / 4, nullptr, &clamped) - x(1.5)).norm(), 1e-14);
  EXPECT_FALSE(clamped);
}

// the optional files: a lone .1 gives no excitation and no hydrostatics; header and blank
// lines are skipped; modes > 6 are skipped; Fortran D exponents read; values dimensional
TEST(WamitReader, MinimalFilesAndSkippedRows) {
  const auto dir = temp_dir();
  write(dir / "a.1", std::string(kGood1) + "\n  5.0 7 7 9.0 9.0\n");
  write(dir / "a.hst", "  3 3 1.0D+01\n  7 7 5.0\n  3 5 2.0\n");
  const auto db = read_wamit((dir / "a").string(), WamitUnits{1000.0, 10.0, 1.0});
  EXPECT_FALSE(db.has_excitation);
  EXPECT_FALSE(db.has_added_mass_zero);
  ASSERT_EQ(db.omega.size(), 2u);
  EXPECT_DOUBLE_EQ(db.omega[0], 2 * kPi / 10.0);
  EXPECT_DOUBLE_EQ(db.damping[0](2, 2), 0.5 * 1000.0 * db.omega[0]);
  EXPECT_DOUBLE_EQ(db.added_mass[1](4, 4), 2.2 * 1000.0);
  EXPECT_DOUBLE_EQ(db.added_mass_inf(2, 4), 0.1 * 1000.0);
  EXPECT_EQ(db.added_mass[0](0, 0), 0.0);
  EXPECT_DOUBLE_EQ(db.hydrostatic_stiffness(2, 2), 10.0 * 1000.0 * 10.0);
  EXPECT_DOUBLE_EQ(db.hydrostatic_stiffness(2, 4), 2.0 * 1000.0 * 10.0);
}

TEST(WamitReader, MissingFirstFile) {
  const auto dir = temp_dir();
  const std::string stem = (dir / "none").string();
  expect_input_error(stem, {stem + ".1: file: cannot read the WAMIT file: no such file"});
}

// note: Diagnostic::format prints "file:line:column", so column 0 shows as ":0"
TEST(WamitReader, ShortRowsAndNonNumericFields) {
  const auto dir = temp_dir();
  const std::string p = (dir / "b").string();
  write(p + ".1",
        " header\n"
        "  10.0 3 3  1.5\n"       // finite period without Bbar
        "  10.0 3 x  1.5 0.5\n"   // non-numeric mode
        "  10.0 3 0  1.5 0.5\n"   // mode 0
        "  abc  3 3  1.5 0.5\n"   // non-numeric period
        "  5.0  3 3  1.5 0.5e\n"  // malformed number
        "  -2.0 3 3  1.5\n"       // negative period other than -1
        "  5.0  3\n");            // short
  expect_input_error(
      p, {p + ".1:2:0: Bbar: missing: the row has 4 of 5 columns (PER I J Abar Bbar)",
          p + ".1:3:0: mode j: expected an integer mode (1 to 6), got 'x'",
          p + ".1:4:0: mode j: expected a mode >= 1, got 0",
          p + ".1:5:0: PER: expected a number, got 'abc'",
          p + ".1:6:0: Bbar: expected a number, got '0.5e'",
          p + ".1:7:0: PER: expected a period > 0 s, 0 (infinite frequency) or -1 (zero "
              "frequency), got -2",
          p + ".1:8:0: mode j: missing: the row has 2 of 5 columns (PER I J Abar Bbar)"});
}

TEST(WamitReader, MissingPairDuplicateAndNoFinitePeriod) {
  const auto dir = temp_dir();
  const std::string p = (dir / "c").string();
  std::string text = kGood1;
  text.replace(text.find("  5.0  5 5  2.2  0.8\n"), 21, "");  // (5,5) missing at PER = 5
  text += "  10.0 3 3  1.5  0.5\n";                           // duplicate at line 13
  write(p + ".1", text);
  expect_input_error(p, {p + ".1:13:0: mode j: duplicate row for PER = 10 s, (i, j) = (3, 3); "
                             "first given at line 6"});
  text.erase(text.rfind("  10.0 3 3"));
  write(p + ".1", text);
  expect_input_error(p, {p + ".1:10:0: modes: PER = 5 s lacks (i, j) = (5, 5) given at other "
                             "periods"});
  write(p + ".1", "  0.0 3 3 1.0\n  -1.0 3 3 2.0\n");
  expect_input_error(p, {p + ".1: PER: no rows with a finite period (PER > 0)"});
}

// .3: non-numeric Re(X), Re/Im inconsistent with Mod/Pha, a period not in .1, a heading
// missing at one period; mode 7 in .hst is skipped (documented), mode 0 is an error
TEST(WamitReader, ExcitationAndHydrostaticsErrors) {
  const auto dir = temp_dir();
  const std::string p = (dir / "d").string();
  write(p + ".1", kGood1);
  write(p + ".3",
        "  10.0  0.0  3  1.0  90.0  0.0  1.0\n"
        "  10.0  0.0  5  2.0   0.0  abc  0.0\n"
        "  5.0   0.0  3  1.0   0.0  0.0  1.0\n"
        "  5.0   0.0  5  2.0   0.0  2.0  0.0\n");
  expect_input_error(p, {p + ".3:2:0: Re(X): expected a number, got 'abc'",
                         p + ".3:3:0: Re(X): Re, Im = (0, 1) disagree with Mod, Pha = (1, 0 deg), "
                             "which give (1, 0)"});
  write(p + ".3",
        "  10.0  0.0  3  1.0  90.0  0.0  1.0\n"
        "  10.0  0.0  5  2.0   0.0  2.0  0.0\n"
        "  10.0  90.0 3  1.0  90.0  0.0  1.0\n"
        "  10.0  90.0 5  2.0   0.0  2.0  0.0\n"
        "  7.0   0.0  3  1.0   0.0  1.0  0.0\n"
        "  7.0   0.0  5  2.0   0.0  2.0  0.0\n");
  expect_input_error(p, {p + ".3:5:0: headings: PER = 7 s lacks BETA = 90 deg given at other "
                             "periods",
                         p + ".3:5:0: PER: period 7 s is not among the periods of " + p + ".1",
                         p + ".3: PER: period 5 s of " + p + ".1 has no excitation rows"});
  write(p + ".3",
        "  10.0  0.0  3  1.0  90.0  0.0  1.0\n"
        "  10.0  0.0  5  2.0   0.0  2.0  0.0\n"
        "  5.0   0.0  5  2.0   0.0  2.0  0.0\n");
  expect_input_error(p, {p + ".3:3:0: modes: PER = 5 s, BETA = 0 deg lacks mode(s) 3 given at "
                             "other periods"});
  std::filesystem::remove(p + ".3");
  write(p + ".hst", "  3 3 1.0\n  7 3 5.0\n  0 3 1.0\n");
  expect_input_error(p, {p + ".hst:3:0: mode i: expected a mode >= 1, got 0"});
}

// several bad rows are reported together, and at most 20
TEST(WamitReader, ReportsEveryProblemUpToTwenty) {
  const auto dir = temp_dir();
  const std::string p = (dir / "e").string();
  std::string text;
  for (int i = 0; i < 30; ++i) text += "  10.0 3 3 x 1.0\n";
  write(p + ".1", text);
  try {
    read_wamit(p, WamitUnits{});
    ADD_FAILURE() << "no exception";
  } catch (const InputError& e) {
    ASSERT_EQ(e.diagnostics().size(), 20u);
    EXPECT_EQ(e.diagnostics()[19].line, 20);
    EXPECT_EQ(e.diagnostics()[19].key, "Abar");
    EXPECT_EQ(e.diagnostics()[19].column, 0);
    EXPECT_EQ(e.diagnostics()[19].file, p + ".1");
  }
}
