// Radiation memory (Cummins 1962, thesis eq. 173): the retardation kernel from B(w) and
// back, the ERA state-space fit, direct convolution against state-space, and the heave
// decay of the floating hemisphere of tests/data/wamit/sphere.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "seaflex/hydro/radiation_memory.hpp"
#include "seaflex/hydro/retardation.hpp"
#include "seaflex/hydro/wamit_reader.hpp"

using namespace seaflex::hydro;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kRho = 1025.0;
constexpr double kG = 9.81;
constexpr double kR = 5.0;

const HydroDatabase& sphere() {
  static const HydroDatabase db =
      read_wamit(std::string(SEAFLEX_SOURCE_DIR) + "/tests/data/wamit/sphere/sphere",
                 WamitUnits{kRho, kG, 1.0});
  return db;
}

const RetardationKernel& sphere_kernel() {
  static const RetardationKernel k = RetardationKernel::from_damping(sphere(), 0.05, 60.0);
  return k;
}

// synthetic kernel with K'(0) = 0 so that B decays like w^-4 and a table to 30 rad/s
// resolves it: K(t) = c e^{-a t} (cos bt + (a/b) sin bt), whose cosine transform is
// B(w) = c/2 [a/(a^2+(w-b)^2) + a/(a^2+(w+b)^2)] + c a/(2b) [(w+b)/(a^2+(w+b)^2) -
// (w-b)/(a^2+(w-b)^2)]
constexpr double kC = 1000.0, kA = 0.4, kB = 1.5;
double k_exact(double t) {
  return kC * std::exp(-kA * t) * (std::cos(kB * t) + kA / kB * std::sin(kB * t));
}
double b_exact(double w) {
  const double p = kA * kA + (w + kB) * (w + kB), m = kA * kA + (w - kB) * (w - kB);
  return 0.5 * kC * (kA / m + kA / p) + 0.5 * kC * kA / kB * ((w + kB) / p - (w - kB) / m);
}
HydroDatabase synthetic_db() {
  HydroDatabase db;
  for (int k = 0; k <= 1500; ++k) {
    const double w = 0.02 * k;
    db.omega.push_back(w);
    Mat6 b = Mat6::Zero();
    b(2, 2) = b_exact(w);
    b(0, 0) = 2.0 * b_exact(w);
    db.damping.push_back(b);
    db.added_mass.push_back(Mat6::Zero());
  }
  return db;
}

// a kernel given by samples: K_33(t) = c e^{-a t}
RetardationKernel exponential_kernel(double c, double a, double dt, double t_max) {
  std::vector<Mat6> s;
  for (int k = 0; k * dt <= t_max + 1e-12; ++k) {
    Mat6 m = Mat6::Zero();
    m(2, 2) = c * std::exp(-a * k * dt);
    s.push_back(m);
  }
  return RetardationKernel::from_samples(std::move(s), dt);
}

Vec6 heave(double v) {
  Vec6 x = Vec6::Zero();
  x(2) = v;
  return x;
}

// 1-DOF heave of the freely floating hemisphere, (M + A33_inf) x'' = -C33 x + F_mem, from
// x(0) = 1 m at rest; classical RK4 with the memory force evaluated at the stage times
// through force(t, v) and committed with accept() once per step
struct Decay {
  std::vector<double> t, x, f;
};
template <class Radiation>
Decay heave_decay(Radiation& radiation, double h, double duration) {
  const auto& db = sphere();
  const double mass = kRho * 2.0 / 3.0 * kPi * kR * kR * kR + db.added_mass_inf(2, 2);
  const double c33 = db.hydrostatic_stiffness(2, 2);
  auto accel = [&](double t, double x, double v) {
    return (-c33 * x + radiation.force(t, heave(v))(2)) / mass;
  };
  double t = 0.0, x = 1.0, v = 0.0;
  radiation.reset(0.0, heave(0.0));
  Decay out;
  const int steps = static_cast<int>(std::lround(duration / h));
  for (int n = 0; n <= steps; ++n) {
    out.t.push_back(t);
    out.x.push_back(x);
    out.f.push_back(radiation.force(t, heave(v))(2));
    const double k1x = v, k1v = accel(t, x, v);
    const double k2x = v + 0.5 * h * k1v, k2v = accel(t + 0.5 * h, x + 0.5 * h * k1x, k2x);
    const double k3x = v + 0.5 * h * k2v, k3v = accel(t + 0.5 * h, x + 0.5 * h * k2x, k3x);
    const double k4x = v + h * k3v, k4v = accel(t + h, x + h * k3x, k4x);
    x += h / 6.0 * (k1x + 2 * k2x + 2 * k3x + k4x);
    v += h / 6.0 * (k1v + 2 * k2v + 2 * k3v + k4v);
    t = h * (n + 1);
    radiation.accept(t, heave(v));
  }
  return out;
}

// zero crossings of x(t) by linear interpolation
std::vector<double> zero_crossings(const Decay& d) {
  std::vector<double> z;
  for (std::size_t k = 1; k < d.x.size(); ++k)
    if ((d.x[k - 1] > 0) != (d.x[k] > 0))
      z.push_back(d.t[k - 1] + (d.t[k] - d.t[k - 1]) * d.x[k - 1] / (d.x[k - 1] - d.x[k]));
  return z;
}

}  // namespace

// K from the synthetic B against its closed form: the table (dw = 0.02 to 30 rad/s)
// misses the tail int_30^inf B ~ 2/pi C/(3 30^3) and interpolates B linearly (error
// dw^2/8 max|B''|); both are below 1e-3 K(0), the tolerance
TEST(RadiationKernel, SyntheticKernelMatchesClosedForm) {
  const auto db = synthetic_db();
  const auto kernel = RetardationKernel::from_damping(db, 0.05, 30.0);
  EXPECT_DOUBLE_EQ(kernel.t_max(), 30.0);
  ASSERT_EQ(kernel.samples().size(), 601u);
  double worst = 0.0;
  for (std::size_t k = 0; k < kernel.samples().size(); ++k) {
    const double t = 0.05 * k;
    worst = std::max(worst, std::abs(kernel.samples()[k](2, 2) - k_exact(t)));
    EXPECT_NEAR(kernel.samples()[k](0, 0), 2.0 * kernel.samples()[k](2, 2), 1e-9 * kC);
    EXPECT_EQ(kernel.samples()[k](1, 1), 0.0);
  }
  EXPECT_LT(worst, 1e-3 * kC);
  // at() interpolates linearly and is zero outside [0, t_max]
  const Mat6 mid = kernel.at(1.025);
  EXPECT_NEAR(mid(2, 2), 0.5 * (kernel.samples()[20](2, 2) + kernel.samples()[21](2, 2)), 1e-9);
  EXPECT_EQ(kernel.at(30.01), Mat6::Zero());
  EXPECT_EQ(kernel.at(-0.01), Mat6::Zero());
}

// B -> K -> B round trip for the sphere (issue: within 1 %): |B_rt - B| below 1 % of the
// peak B33 over the resolved band 0.3 .. 6 rad/s (2 pi / t_max = 0.1 rad/s is the
// resolution of a 60 s kernel; above 6 rad/s the irregular frequency near 8.4 rad/s and
// the truncated table dominate), and pointwise within 1 % where B33 > 10 % of its peak.
// The Ogilvie relation gives A33(w) from K and A33_inf: within 1 % of the table as well.
TEST(RadiationKernel, SphereRoundTripDampingAndAddedMass) {
  const auto& db = sphere();
  const auto& kernel = sphere_kernel();
  double peak = 0.0;
  for (const auto& b : db.damping) peak = std::max(peak, b(2, 2));
  for (std::size_t k = 0; k < db.omega.size(); ++k) {
    const double w = db.omega[k];
    if (w < 0.3 || w > 6.0) continue;
    const double b_rt = kernel.damping(w)(2, 2);
    const double b = db.damping[k](2, 2);
    EXPECT_LT(std::abs(b_rt - b), 0.01 * peak) << "w=" << w;
    if (b > 0.1 * peak) {
      EXPECT_NEAR(b_rt / b, 1.0, 0.01) << "w=" << w;
    }
    EXPECT_NEAR(kernel.added_mass(w, db.added_mass_inf)(2, 2) / db.added_mass[k](2, 2), 1.0, 0.01)
        << "w=" << w;
    // surge-pitch coupling too, relative to the surge peak scale R B11
    EXPECT_LT(std::abs(kernel.damping(w)(0, 4) - db.damping[k](0, 4)), 0.01 * kR * peak);
  }
}

// round trip of the synthetic case against the closed form B (1 %, the bound;
// the kernel is 30 s long and decays as e^{-0.4 t}, so truncation is e^{-12})
TEST(RadiationKernel, SyntheticRoundTrip) {
  const auto kernel = RetardationKernel::from_damping(synthetic_db(), 0.05, 30.0);
  const double peak = b_exact(kB);
  for (double w = 0.0; w <= 10.0; w += 0.25)
    EXPECT_NEAR(kernel.damping(w)(2, 2), b_exact(w), 0.01 * peak) << "w=" << w;
}

TEST(RadiationKernel, RejectsBadArguments) {
  const auto& db = sphere();
  EXPECT_THROW(RetardationKernel::from_damping(db, 0.0, 10.0), std::invalid_argument);
  EXPECT_THROW(RetardationKernel::from_damping(db, 0.1, 0.05), std::invalid_argument);
  EXPECT_THROW(RetardationKernel::from_damping(HydroDatabase{}, 0.1, 10.0), std::invalid_argument);
  EXPECT_THROW(RetardationKernel::from_samples({Mat6::Zero()}, 0.1), std::invalid_argument);
  try {
    RetardationKernel::from_damping(db, -1.0, 10.0);
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "retardation kernel: dt must be > 0, got -1");
  }
}

// ERA on an exact single exponential: the Hankel matrix has rank 1, the fitted pole is
// -a to rounding (1e-9 relative) and the residue c; a damped cosine gives the pair -a +- ib
TEST(RadiationStateSpace, SingleExponentialPoleIsMinusA) {
  std::vector<double> y;
  for (int k = 0; k <= 400; ++k) y.push_back(3.0 * std::exp(-0.7 * 0.05 * k));
  const auto m = fit_impulse_response(y, 0.05, 1e-6, 20);
  ASSERT_EQ(m.order(), 1);
  EXPECT_NEAR(m.a(0, 0), -0.7, 0.7e-9);
  EXPECT_NEAR(m.c(0) * m.b(0), 3.0, 3e-9);
  EXPECT_LT(m.fit_error, 1e-9);
  EXPECT_NEAR(m.evaluate(1.234), 3.0 * std::exp(-0.7 * 1.234), 1e-9);
  y.clear();
  for (int k = 0; k <= 400; ++k) y.push_back(k_exact(0.05 * k));
  const auto p = fit_impulse_response(y, 0.05, 1e-6, 20);
  ASSERT_EQ(p.order(), 2);
  EXPECT_NEAR(p.a(0, 0), -kA, 1e-9);
  EXPECT_NEAR(std::abs(p.a(0, 1)), kB, 1e-9);
  EXPECT_LT(p.fit_error, 1e-9);
  // through the class: a kernel of one exponential entry gives one state
  const StateSpaceRadiation ss(exponential_kernel(3.0, 0.7, 0.05, 20.0), {});
  EXPECT_EQ(ss.total_order(), 1);
  EXPECT_NEAR(ss.kernel(2.0)(2, 2), 3.0 * std::exp(-1.4), 1e-9);
  EXPECT_EQ(ss.kernel(2.0)(0, 0), 0.0);
}

// the sphere's fitted kernel against the sampled one: relative L2 error below 1 % per
// entry (the default tolerance 1e-3 on the Hankel singular values gives ~1e-3), all poles
// stable, and at the samples the heave entry within 1 % of K33(0)
TEST(RadiationStateSpace, SphereFitMatchesSampledKernel) {
  const auto& kernel = sphere_kernel();
  const StateSpaceRadiation ss(kernel, {});
  EXPECT_LT(ss.fit_error(), 1e-2);
  EXPECT_GT(ss.total_order(), 0);
  EXPECT_LE(ss.total_order(), 9 * 20);  // 9 significant entries (11, 15, 22, 24, 33, ...)
  EXPECT_EQ(ss.discarded_poles(), 0);
  EXPECT_GT(ss.fit_errors()(2, 2), 0.0);  // heave is fitted
  EXPECT_EQ(ss.fit_errors()(5, 5), 0.0);  // yaw is not significant
  const double k0 = kernel.samples()[0](2, 2);
  for (std::size_t k = 0; k < kernel.samples().size(); k += 7)
    EXPECT_NEAR(ss.kernel(0.05 * k)(2, 2), kernel.samples()[k](2, 2), 0.01 * k0) << k;
}

// issue 22: a 2000 s memory with a 1 ms kernel step (2,000,001 samples of K, 30 s and
// 565 MB before) fits from at most 2 x 4096 samples. Heave: relative L2 error below 1 % and
// within 1 % of K33(0) at the samples of the 60 s, 0.05 s kernel, as the direct fit
// (SphereFitMatchesSampledKernel). Surge and pitch: the sphere's table ends where B11 is
// not yet negligible, so K11 carries a ripple ~ 1/t that a 2000 s window holds and no
// 20-pole fit follows: the direct fit of the 40,001 samples of the same 2000 s at 0.05 s
// has a relative error of 0.329 there (measured), the bounded one 0.370; bound 0.4.
TEST(RadiationStateSpace, LongMemoryAndFineStepFitFromBoundedSamples) {
  const auto& kernel = sphere_kernel();
  const StateSpaceRadiation ss = StateSpaceRadiation::from_damping(sphere(), 1e-3, 2000.0, {});
  EXPECT_LT(ss.fit_errors()(2, 2), 1e-2);
  EXPECT_LT(ss.fit_error(), 0.4);
  EXPECT_EQ(ss.fit_errors()(5, 5), 0.0);  // yaw is not significant
  const double k0 = kernel.samples()[0](2, 2);
  for (std::size_t k = 0; k < kernel.samples().size(); k += 7)
    EXPECT_NEAR(ss.kernel(0.05 * k)(2, 2), kernel.samples()[k](2, 2), 0.01 * k0) << k;
  EXPECT_LT(std::abs(ss.kernel(1500.0)(2, 2)), 1e-3 * k0);
  // below the bound from_damping samples as asked: the same fit as the constructor's
  const StateSpaceRadiation direct(kernel, {});
  const StateSpaceRadiation bounded = StateSpaceRadiation::from_damping(sphere(), 0.05, 60.0, {});
  EXPECT_EQ(bounded.total_order(), direct.total_order());
  EXPECT_EQ(bounded.kernel(3.3)(2, 2), direct.kernel(3.3)(2, 2));
}

// the residues of a fit to 2,000,001 samples (a damped cosine over 2000 s at 1 ms) come
// from every 245th sample (8,164 rows, not a 2e6 x 2 matrix); the pole pair and the
// residues are those of the exact response to 1e-9, and fit_error covers every sample
TEST(RadiationStateSpace, ResiduesOfAVeryLongResponseFromBoundedRows) {
  std::vector<double> y(2000001);
  for (std::size_t k = 0; k < y.size(); ++k) y[k] = k_exact(1e-3 * static_cast<double>(k));
  const auto p = fit_impulse_response(y, 1e-3, 1e-6, 20);
  ASSERT_EQ(p.order(), 2);
  EXPECT_NEAR(p.a(0, 0), -kA, 1e-9);
  EXPECT_NEAR(std::abs(p.a(0, 1)), kB, 1e-9);
  EXPECT_LT(p.fit_error, 1e-9);
  for (const double t : {0.0, 0.4567, 3.21})
    EXPECT_NEAR(p.evaluate(t), k_exact(t), 1e-9 * std::abs(k_exact(0.0))) << t;
}

// constant velocity v from t0: F(t) = -v int_0^{t-t0} K = -v c/a (1 - e^{-a (t - t0)}),
// reaching the steady value -v int K dt (a constant damping b would be the limit of a
// very short kernel, which a sampled K cannot hold: this is the sampled analogue).
// Convolution: trapezoid with h = 0.05 on a kernel sampled at 0.01 (interpolated):
// relative error (a h)^2 / 12 = 4.7e-4, tolerance 1e-3; state-space: exact propagation
// of an exact one-pole fit, tolerance 1e-6 (the kernel's own sampling does not enter).
TEST(RadiationMemory, ConstantVelocityReachesSteadyValue) {
  const double c = 500.0, a = 1.5, v = 0.8;
  const auto kernel = exponential_kernel(c, a, 0.01, 20.0);
  ConvolutionRadiation conv(kernel, 20.0);
  StateSpaceRadiation ss(kernel, {});
  conv.reset(1.0, heave(v));
  ss.reset(1.0, heave(v));
  const double steady = -v * c / a;
  for (int n = 1; n <= 300; ++n) {
    const double t = 1.0 + 0.05 * n;
    const double expected = steady * (1.0 - std::exp(-a * (t - 1.0)));
    EXPECT_NEAR(conv.force(t, heave(v))(2), expected, 1e-3 * std::abs(steady)) << t;
    EXPECT_NEAR(ss.force(t, heave(v))(2), expected, 1e-6 * std::abs(steady)) << t;
    conv.accept(t, heave(v));
    ss.accept(t, heave(v));
  }
  EXPECT_NEAR(conv.force(16.0, heave(v))(2), steady, 1e-3 * std::abs(steady));
  EXPECT_NEAR(ss.force(16.0, heave(v))(2), steady, 1e-6 * std::abs(steady));
  EXPECT_EQ(conv.force(16.0, heave(v))(0), 0.0);
}

// dF/dv_now is the exact derivative (both forces are affine in v_now): central
// differences with dv = 1e-3 agree to rounding (1e-9 relative to the force scale)
TEST(RadiationMemory, JacobianMatchesFiniteDifferences) {
  const auto kernel = exponential_kernel(500.0, 1.5, 0.01, 20.0);
  ConvolutionRadiation conv(kernel, 20.0);
  StateSpaceRadiation ss(kernel, {});
  for (int n = 1; n <= 10; ++n) {
    conv.accept(0.1 * n, heave(std::sin(n)));
    ss.accept(0.1 * n, heave(std::sin(n)));
  }
  const double t = 1.07, dv = 1e-3;
  const double fd_conv =
      (conv.force(t, heave(0.3 + dv))(2) - conv.force(t, heave(0.3 - dv))(2)) / (2 * dv);
  const double fd_ss =
      (ss.force(t, heave(0.3 + dv))(2) - ss.force(t, heave(0.3 - dv))(2)) / (2 * dv);
  EXPECT_NEAR(conv.dforce_dv(t)(2, 2), fd_conv, 1e-9 * 500);
  EXPECT_NEAR(conv.dforce_dv(t)(2, 2), -500.0 * 0.07 / 2, 1e-9 * 500);
  EXPECT_NEAR(ss.dforce_dv(t)(2, 2), fd_ss, 1e-9 * 500);
  EXPECT_EQ(conv.dforce_dv(1.0), Mat6::Zero());
  EXPECT_EQ(ss.dforce_dv(1.0), Mat6::Zero());
}

// the history is bounded by memory: with h = 0.1 s and memory 1 s at most 11 + 1 samples
TEST(RadiationMemory, HistoryIsBoundedAndTimesIncrease) {
  ConvolutionRadiation conv(exponential_kernel(1.0, 1.0, 0.1, 5.0), 1.0);
  for (int n = 1; n <= 200; ++n) conv.accept(0.1 * n, heave(1.0));
  EXPECT_LE(conv.stored_samples(), 12u);
  EXPECT_GE(conv.stored_samples(), 10u);
  EXPECT_THROW(conv.accept(20.0, heave(1.0)), std::invalid_argument);
  EXPECT_THROW(conv.force(19.9, heave(1.0)), std::invalid_argument);
  EXPECT_THROW(ConvolutionRadiation(exponential_kernel(1.0, 1.0, 0.1, 5.0), 0.0),
               std::invalid_argument);
  StateSpaceRadiation ss(exponential_kernel(1.0, 1.0, 0.1, 5.0), {});
  ss.accept(1.0, heave(1.0));
  EXPECT_THROW(ss.accept(1.0, heave(1.0)), std::invalid_argument);
  EXPECT_THROW(ss.force(0.5, heave(1.0)), std::invalid_argument);
}

// the two requirements on the hemisphere's heave decay from x(0) = 1 m:
// - the memory forces of the convolution and the state-space model agree within 2 % of
//   max |F| (each model integrated on its own, RK4 with h = 0.05 s, 30 s)
// - the natural period with memory is within 1 % of 2 pi / w with w^2 (M + A33(w)) = C33,
//   M = rho 2/3 pi R^3 (freely floating), A33 from the table (measured: +0.6 %, the
//   damped period being longer than the undamped one; damping ratio ~0.09)
TEST(RadiationMemory, SphereHeaveDecayConvolutionVsStateSpaceAndPeriod) {
  const auto& db = sphere();
  const auto& kernel = sphere_kernel();
  ConvolutionRadiation conv(kernel, kernel.t_max());
  StateSpaceRadiation ss(kernel, {});
  const Decay a = heave_decay(conv, 0.05, 30.0);
  const Decay b = heave_decay(ss, 0.05, 30.0);
  double f_max = 0.0, diff = 0.0;
  for (std::size_t k = 0; k < a.f.size(); ++k) {
    f_max = std::max(f_max, std::abs(a.f[k]));
    diff = std::max(diff, std::abs(a.f[k] - b.f[k]));
  }
  EXPECT_GT(f_max, 1e4);  // the memory force matters: ~ B33 * max velocity
  EXPECT_LT(diff / f_max, 0.02);

  // predicted natural frequency: bisection on w^2 (M + A33(w)) - C33
  const double mass = kRho * 2.0 / 3.0 * kPi * kR * kR * kR;
  const double c33 = db.hydrostatic_stiffness(2, 2);
  double lo = 0.5, hi = 3.0;
  for (int i = 0; i < 100; ++i) {
    const double w = 0.5 * (lo + hi);
    (w * w * (mass + db.added_mass_at(w)(2, 2)) > c33 ? hi : lo) = w;
  }
  const double period_predicted = 2 * kPi / lo;
  for (const Decay* d : {&a, &b}) {
    const auto z = zero_crossings(*d);
    ASSERT_GE(z.size(), 5u);
    const double period = 0.5 * (z[4] - z[0]);  // two full periods
    EXPECT_NEAR(period / period_predicted, 1.0, 0.01);
  }
}
