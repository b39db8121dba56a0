// Displacement RAOs (hydro/rao_table.hpp, hydro/rao_motion.hpp): the motion in a regular
// wave against its closed form, the variance in an irregular sea against the spectral
// integral, and the readers (plain table, WAMIT .4, phase conventions, gaps).
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unsupported/Eigen/FFT>

#include <cmath>
#include <complex>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numbers>
#include <vector>

#include "seaflex/core/errors.hpp"
#include "seaflex/hydro/rao_motion.hpp"
#include "seaflex/hydro/wave_spectrum.hpp"

using namespace seaflex;
using namespace seaflex::hydro;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;

std::string temp_file(const std::string& name, const std::string& text) {
  const auto p = std::filesystem::temp_directory_path() / ("seaflex_rao_" + name);
  std::ofstream(p) << text;
  return p.string();
}

// a heave-roll RAO shaped like a damped oscillator, H = 1 / (1 - r^2 + 2 i z r), r = w / w0
std::complex<double> oscillator(double w) {
  const double r = w / 0.55;
  return 1.0 / std::complex<double>(1.0 - r * r, 2.0 * 0.15 * r);
}

// the storm's JONSWAP sea (Hs 6 m, Tp 10 s) with n random-phase components
SpectrumSpec storm_sea(int n, int seed) {
  SpectrumSpec spec;
  spec.hs = 6.0;
  spec.tp = 10.0;
  spec.components = n;
  spec.seed = seed;
  return spec;
}

}  // namespace

// regular wave: x_j = a |H_j| cos(w t + arg H_j - k.o + phase), the wave crest at the RAO
// origin o leading by arg H_j; to 1e-9 (round-off of sums of O(1) terms; the issue's
// tolerance). The plain table read back with the lag convention and the opposite phases
// gives the same motion; the global-origin reference drops the k.o term.
TEST(RaoMotion, RegularWaveAmplitudeAndPhase) {
  const std::string text =
      "period_s, heading_deg, surge_amp, surge_phase, sway_amp, sway_phase, heave_amp, "
      "heave_phase, roll_amp, roll_phase, pitch_amp, pitch_phase, yaw_amp, yaw_phase\n"
      "8, 0, 0.1, 10, 0.0, 0, 0.9, -20, 0.5, 30, 1.0, 40, 0.2, 50\n"
      "8, 45, 0.2, 11, 0.1, 5, 0.8, -25, 0.6, 35, 1.1, 45, 0.3, 55\n"
      "12, 0, 0.3, 12, 0.0, 0, 1.0, -30, 0.7, 40, 1.2, 50, 0.4, 60\n"
      "12, 45, 0.4, 13, 0.2, 6, 0.95, -35, 0.8, 45, 1.3, 55, 0.5, 65\n";
  const RaoTable lead_table = read_rao_table(temp_file("lead.csv", text), RaoPhase::kLead);
  // the same RAOs written with lagging phases
  const std::string lag_text =
      "period_s heading_deg surge_amp surge_phase sway_amp sway_phase heave_amp heave_phase "
      "roll_amp roll_phase pitch_amp pitch_phase yaw_amp yaw_phase\n"
      "8 0 0.1 -10 0.0 0 0.9 20 0.5 -30 1.0 -40 0.2 -50\n"
      "8 45 0.2 -11 0.1 -5 0.8 25 0.6 -35 1.1 -45 0.3 -55\n"
      "12 0 0.3 -12 0.0 0 1.0 30 0.7 -40 1.2 -50 0.4 -60\n"
      "12 45 0.4 -13 0.2 -6 0.95 35 0.8 -45 1.3 -55 0.5 -65\n";
  const RaoTable lag_table = read_rao_table(temp_file("lag.csv", lag_text), RaoPhase::kLag);
  const WaveComponent w = regular_component(3.0, 12.0, 45.0 * kDeg, 0.7, 200.0, 9.81);
  const Vec3 o(20.0, -10.0, 0.0);
  const RaoMotion m(lead_table, {w}, o, RaoPhaseReference::kRaoOrigin);
  const RaoMotion m_lag(lag_table, {w}, o, RaoPhaseReference::kRaoOrigin);
  const RaoMotion m_global(lead_table, {w}, o, RaoPhaseReference::kGlobalOrigin);
  // the 12 s, 45 deg row: amplitudes (m/m, deg/m) and lead phases (deg)
  const double amp[6] = {0.4, 0.2, 0.95, 0.8 * kDeg, 1.3 * kDeg, 0.5 * kDeg};
  const double pha[6] = {13, 6, -35, 45, 55, 65};
  const double ko = w.k * (o.x() * std::cos(w.direction) + o.y() * std::sin(w.direction));
  for (double t : {0.0, 1.3, 4.4, 11.9, 100.05}) {
    const MotionSample s = m.sample(t), sl = m_lag.sample(t), sg = m_global.sample(t);
    for (int j = 0; j < 6; ++j) {
      const double th = w.omega * t + pha[j] * kDeg + w.phase;
      EXPECT_NEAR(s.x[j], w.amplitude * amp[j] * std::cos(th - ko), 1e-9) << j;
      EXPECT_NEAR(s.x_t[j], -w.omega * w.amplitude * amp[j] * std::sin(th - ko), 1e-9) << j;
      EXPECT_NEAR(s.x_tt[j], -w.omega * w.omega * s.x[j], 1e-9) << j;
      EXPECT_NEAR(sl.x[j], s.x[j], 1e-9) << j;
      EXPECT_NEAR(sg.x[j], w.amplitude * amp[j] * std::cos(th), 1e-9) << j;
    }
  }
  // interpolation halfway in period (10 s is not in the table) is linear in Re and Im
  const std::complex<double> H3 = lead_table.at(2 * kPi / 10.0, 0.0)[2];
  const double f = (2 * kPi / 10.0 - 2 * kPi / 12.0) / (2 * kPi / 8.0 - 2 * kPi / 12.0);
  const std::complex<double> expect =
      (1 - f) * std::polar(1.0, -30 * kDeg) + f * std::polar(0.9, -20 * kDeg);
  EXPECT_NEAR(std::abs(H3 - expect), 0.0, 1e-12);
}

// irregular sea (JONSWAP Hs 6 m, Tp 10 s, 400 random-phase components): the variance of a
// 3-hour record of heave (sampled every 0.5 s) equals int |H|^2 S dw within 2 % (the
// issue's tolerance: the random frequencies and the finite record give about 1 %).
TEST(RaoMotion, IrregularSeaVarianceEqualsSpectralIntegral) {
  const SpectrumSpec spec = storm_sea(400, 7);
  const auto comps = irregular_components(spec, std::numeric_limits<double>::infinity(), 9.81);
  RaoTable table;
  table.data.has_excitation = true;
  table.data.headings = {0.0};
  table.data.excitation.resize(1);
  for (int i = 0; i <= 600; ++i) {  // dense table, 0.1 to 4.0 rad/s
    const double w = 0.1 + 3.9 * i / 600.0;
    table.data.omega.push_back(w);
    Vec6c H = Vec6c::Zero();
    H[2] = oscillator(w);
    table.data.excitation[0].push_back(H);
  }
  const RaoMotion m(table, comps, Vec3::Zero(), RaoPhaseReference::kRaoOrigin);
  const double dt = 0.5, T = 3 * 3600.0;
  double sum = 0.0, sum2 = 0.0;
  long n = 0;
  for (double t = 0.0; t < T; t += dt, ++n) {
    const double z = m.sample(t).x[2];
    sum += z;
    sum2 += z * z;
  }
  const double var = sum2 / n - (sum / n) * (sum / n);
  double wmin = 0.0, wmax = 0.0;
  spectrum_band(spec, wmin, wmax);
  double integral = 0.0;  // trapezoid on 20000 intervals
  const int N = 20000;
  for (int i = 0; i <= N; ++i) {
    const double w = wmin + (wmax - wmin) * i / N;
    const double f = std::norm(oscillator(w)) * spectral_density(spec, w);
    integral += (i == 0 || i == N ? 0.5 : 1.0) * f * (wmax - wmin) / N;
  }
  EXPECT_NEAR(var / integral, 1.0, 0.02) << "variance " << var << " m^2, integral " << integral;
  // the spectrum of the record (its FFT, Parseval) against |H|^2 S in bands of 0.2 rad/s
  // over the energetic range: each band's share of the variance within 10 % (a band holds
  // about 25 of the 400 random frequencies, whose sum approximates the band's integral;
  // the record's frequency resolution, 5.8e-4 rad/s, makes band-edge leakage negligible)
  std::vector<double> z;
  for (double t = 0.0; t < T; t += dt) z.push_back(m.sample(t).x[2]);
  Eigen::FFT<double> fft;
  std::vector<std::complex<double>> Z;
  fft.fwd(Z, z);
  const double Nz = static_cast<double>(z.size());
  for (double w0 = 0.4; w0 < 1.19; w0 += 0.2) {
    double band_record = 0.0, band_exact = 0.0;
    for (std::size_t k = 1; k < z.size() / 2; ++k) {
      const double wk = 2.0 * std::numbers::pi * static_cast<double>(k) / (Nz * dt);
      if (wk >= w0 && wk < w0 + 0.2) band_record += 2.0 * std::norm(Z[k]) / (Nz * Nz);
    }
    const int M = 2000;
    for (int i = 0; i <= M; ++i) {
      const double w = w0 + 0.2 * i / M;
      band_exact += (i == 0 || i == M ? 0.5 : 1.0) * std::norm(oscillator(w)) *
                    spectral_density(spec, w) * 0.2 / M;
    }
    std::printf("  band %.1f-%.1f rad/s: record/|H|^2 S = %.4f\n", w0, w0 + 0.2,
                band_record / band_exact);
    EXPECT_NEAR(band_record / band_exact, 1.0, 0.10)
        << "band " << w0 << " to " << w0 + 0.2 << " rad/s: record " << band_record
        << " m^2, |H|^2 S " << band_exact << " m^2";
  }
}

// sample() sums the components with real multiply-adds over amplitudes stored by component
// (hydro/rao_motion.cpp); here the same motion is summed term by term in std::complex from
// complex_amplitude(k), x_j = Re{c_j e^{iwt}}, x' = Re{i w c_j e^{iwt}}, x'' = Re{-w^2 c_j
// e^{iwt}}, over the 3-hour storm's times (large phases w t), all six degrees of freedom with
// complex RAOs. To 1e-13 of sum_k |c_jk| (w, w^2 for the derivatives): round-off of 200 terms in
// another order. And the derivatives against central differences of the displacement
// (step 1e-3 s: truncation (w dt)^2 / 6 < 2e-6 of the largest term's w |c|, round-off 1e-13 / dt).
TEST(RaoMotion, SampleEqualsTheComplexSumTermByTerm) {
  const auto comps = irregular_components(storm_sea(200, 3), 290.0, 9.81);
  RaoTable table;
  table.data.has_excitation = true;
  table.data.headings = {0.0};
  table.data.excitation.resize(1);
  for (int i = 0; i <= 400; ++i) {
    const double w = 0.1 + 3.9 * i / 400.0;
    table.data.omega.push_back(w);
    Vec6c H;
    for (int j = 0; j < 6; ++j)
      H[j] = (0.3 + 0.2 * j) * oscillator(w * (1.0 + 0.1 * j)) * std::polar(1.0, 0.4 * j);
    table.data.excitation[0].push_back(H);
  }
  const RaoMotion m(table, comps, Vec3(3.0, -2.0, -5.0), RaoPhaseReference::kRaoOrigin);
  std::vector<double> omega;
  for (const auto& c : comps)
    if (c.amplitude != 0.0) omega.push_back(c.omega);
  ASSERT_EQ(omega.size(), 200u);
  Vec6 scale0 = Vec6::Zero(), scale1 = Vec6::Zero(), scale2 = Vec6::Zero();
  std::vector<Vec6c> c;
  for (std::size_t k = 0; k < omega.size(); ++k) c.push_back(m.complex_amplitude(k));
  for (std::size_t k = 0; k < omega.size(); ++k)
    for (int j = 0; j < 6; ++j) {
      const double a = std::abs(c[k][j]);
      scale0[j] += a;
      scale1[j] += omega[k] * a;
      scale2[j] += omega[k] * omega[k] * a;
    }
  for (const double t : {0.0, 31.7, 1234.5, 5400.05, 10829.9}) {
    Vec6 x = Vec6::Zero(), xt = Vec6::Zero(), xtt = Vec6::Zero();
    for (std::size_t k = 0; k < omega.size(); ++k) {
      const std::complex<double> e = std::polar(1.0, omega[k] * t);
      for (int j = 0; j < 6; ++j) {
        const std::complex<double> z = c[k][j] * e;
        x[j] += z.real();
        xt[j] += (std::complex<double>(0.0, omega[k]) * z).real();
        xtt[j] += -omega[k] * omega[k] * z.real();
      }
    }
    const MotionSample s = m.sample(t);
    const double dt = 1e-3;
    const MotionSample sp = m.sample(t + dt), sm = m.sample(t - dt);
    for (int j = 0; j < 6; ++j) {
      EXPECT_NEAR(s.x[j], x[j], 1e-13 * scale0[j]) << "t " << t << " dof " << j;
      EXPECT_NEAR(s.x_t[j], xt[j], 1e-13 * scale1[j]) << "t " << t << " dof " << j;
      EXPECT_NEAR(s.x_tt[j], xtt[j], 1e-13 * scale2[j]) << "t " << t << " dof " << j;
      EXPECT_NEAR((sp.x[j] - sm.x[j]) / (2 * dt), s.x_t[j], 2e-6 * scale1[j]) << "t " << t;
      EXPECT_NEAR((sp.x_t[j] - sm.x_t[j]) / (2 * dt), s.x_tt[j], 2e-6 * scale2[j]) << "t " << t;
    }
  }
}

// WAMIT .4: rotations made dimensional with ULEN, Re/Im used; lag flips the phase
TEST(RaoMotion, WamitFourFile) {
  std::string text = " PER BETA I MOD PHA RE IM\n";
  for (double per : {6.0, 10.0})
    for (double beta : {0.0, 90.0})
      for (int i = 1; i <= 7; ++i)
        text += fmt::format("{} {} {} 1 0 {} {}\n", per, beta, i, 0.5 * i, -0.25 * i);
  const std::string path = temp_file("ship.4", text);
  const RaoTable t = read_wamit_rao(path, 10.0, RaoPhase::kLead);
  const Vec6c H = t.at(2 * kPi / 6.0, 90.0 * kDeg);
  EXPECT_NEAR(std::abs(H[1] - std::complex<double>(1.0, -0.5)), 0.0, 1e-15);
  EXPECT_NEAR(std::abs(H[4] - std::complex<double>(0.25, -0.125)), 0.0, 1e-15);  // / ULEN
  const RaoTable lag = read_wamit_rao(path, 10.0, RaoPhase::kLag);
  EXPECT_NEAR(std::abs(lag.at(2 * kPi / 6.0, 0.0)[1] - std::complex<double>(1.0, 0.5)), 0.0, 1e-15);
}

// every problem names the file, the line and the column's key
TEST(RaoMotion, TableErrors) {
  auto message = [](const std::string& text) {
    try {
      read_rao_table(temp_file("bad.csv", text), RaoPhase::kLead);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string row = ", 0.1, 0, 0.1, 0, 1, 0, 0.1, 0, 0.1, 0, 0.1, 0\n";
  EXPECT_NE(message("8, 0" + row + "12, 0" + row + "8, 30" + row)
                .find("gap: period 12 s is missing at heading 30 deg"),
            std::string::npos);
  EXPECT_NE(message("8, 0, 0.1, 0\n").find(":1:0: sway_amp: missing: the row has 4 of 14"),
            std::string::npos);
  EXPECT_NE(message("8, 0" + row + "nan, 0" + row)
                .find(":2:0: period_s: expected a finite "
                      "number, got 'nan'"),
            std::string::npos);
  EXPECT_NE(message("8, 0" + row + "8, 0" + row).find("is given twice (first at line 1)"),
            std::string::npos);
}
