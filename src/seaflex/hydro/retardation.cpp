#include "seaflex/hydro/retardation.hpp"

#include <fmt/format.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <stdexcept>

namespace seaflex::hydro {

namespace {

using cplx = std::complex<double>;

// E0 = int_0^1 (1 - u) e^{i th u} du and E1 = int_0^1 u e^{i th u} du: the weights of the
// end values of a linear function in int_x0^x1 f(x) e^{i t x} dx = h e^{i t x0} (f0 E0 + f1 E1),
// th = t h; power series for small |th| (no cancellation), closed form otherwise
void linear_weights(double th, cplx& e0, cplx& e1) {
  const cplx i(0.0, 1.0);
  if (std::abs(th) < 1.0) {
    // E1 = sum (i th)^n / (n! (n + 2)), E0 + E1 = sum (i th)^n / (n + 1)!
    cplx term(1.0, 0.0);  // (i th)^n / n!
    cplx sum0(0.0, 0.0), sum1(0.0, 0.0);
    for (int n = 0; n < 30; ++n) {
      sum0 += term / static_cast<double>(n + 1);
      sum1 += term / static_cast<double>(n + 2);
      term *= i * th / static_cast<double>(n + 1);
    }
    e1 = sum1;
    e0 = sum0 - sum1;
    return;
  }
  const cplx e = std::exp(i * th);
  const cplx full = (e - 1.0) / (i * th);  // int_0^1 e^{i th u} du
  e1 = e / (i * th) - (e - 1.0) / ((i * th) * (i * th));
  e0 = full - e1;
}

}  // namespace

RetardationKernel RetardationKernel::from_damping(const HydroDatabase& db, double dt,
                                                  double t_max) {
  if (!(dt > 0.0) || !std::isfinite(dt))
    throw std::invalid_argument(fmt::format("retardation kernel: dt must be > 0, got {}", dt));
  if (!(t_max >= dt) || !std::isfinite(t_max))
    throw std::invalid_argument(
        fmt::format("retardation kernel: t_max must be >= dt ({} s), got {}", dt, t_max));
  if (db.omega.empty() || db.damping.size() != db.omega.size())
    throw std::invalid_argument("retardation kernel: the damping table is empty");
  // the table as a piecewise-linear B(w), from (0, 0) if it does not start at w = 0
  std::vector<double> w;
  std::vector<Mat6> b;
  if (db.omega.front() > 0.0) {
    w.push_back(0.0);
    b.push_back(Mat6::Zero());
  }
  w.insert(w.end(), db.omega.begin(), db.omega.end());
  b.insert(b.end(), db.damping.begin(), db.damping.end());

  const auto n = static_cast<std::size_t>(std::floor(t_max / dt + 0.5)) + 1;
  std::vector<Mat6> samples(n, Mat6::Zero());
  for (std::size_t k = 0; k < n; ++k) {
    const double t = dt * static_cast<double>(k);
    Mat6 sum = Mat6::Zero();
    for (std::size_t s = 0; s + 1 < w.size(); ++s) {
      const double h = w[s + 1] - w[s];
      cplx e0, e1;
      linear_weights(t * h, e0, e1);
      const cplx phase = h * std::exp(cplx(0.0, t * w[s]));
      // Re of h e^{i t w0} (B0 E0 + B1 E1) = int B cos(w t) dw over the piece
      sum += (phase * e0).real() * b[s] + (phase * e1).real() * b[s + 1];
    }
    samples[k] = (2.0 / std::numbers::pi) * sum;  // thesis eq. 173, K(t)
  }
  return RetardationKernel(std::move(samples), dt);
}

RetardationKernel RetardationKernel::from_samples(std::vector<Mat6> samples, double dt) {
  if (!(dt > 0.0) || !std::isfinite(dt))
    throw std::invalid_argument(fmt::format("retardation kernel: dt must be > 0, got {}", dt));
  if (samples.size() < 2)
    throw std::invalid_argument(
        fmt::format("retardation kernel: needs at least 2 samples, got {}", samples.size()));
  return RetardationKernel(std::move(samples), dt);
}

Mat6 RetardationKernel::at(double t) const {
  if (!(t >= 0.0) || t > t_max()) return Mat6::Zero();
  const double x = t / dt_;
  auto k = static_cast<std::size_t>(x);
  if (k >= samples_.size() - 1) k = samples_.size() - 2;
  const double s = x - static_cast<double>(k);
  return (1.0 - s) * samples_[k] + s * samples_[k + 1];
}

Mat6 RetardationKernel::damping(double omega) const {
  cplx e0, e1;
  linear_weights(omega * dt_, e0, e1);
  Mat6 sum = Mat6::Zero();
  for (std::size_t k = 0; k + 1 < samples_.size(); ++k) {
    const cplx phase = dt_ * std::exp(cplx(0.0, omega * dt_ * static_cast<double>(k)));
    sum += (phase * e0).real() * samples_[k] + (phase * e1).real() * samples_[k + 1];
  }
  return sum;
}

Mat6 RetardationKernel::added_mass(double omega, const Mat6& a_inf) const {
  Mat6 sum = Mat6::Zero();
  if (omega == 0.0) {
    // int K t dt over linear pieces: h (K0 (t0/2 + h/6) + K1 (t0/2 + h/3))
    for (std::size_t k = 0; k + 1 < samples_.size(); ++k) {
      const double t0 = dt_ * static_cast<double>(k);
      sum +=
          dt_ * ((0.5 * t0 + dt_ / 6.0) * samples_[k] + (0.5 * t0 + dt_ / 3.0) * samples_[k + 1]);
    }
    return a_inf - sum;
  }
  cplx e0, e1;
  linear_weights(omega * dt_, e0, e1);
  for (std::size_t k = 0; k + 1 < samples_.size(); ++k) {
    const cplx phase = dt_ * std::exp(cplx(0.0, omega * dt_ * static_cast<double>(k)));
    sum += (phase * e0).imag() * samples_[k] + (phase * e1).imag() * samples_[k + 1];
  }
  return a_inf - sum / omega;  // Ogilvie (1964)
}

}  // namespace seaflex::hydro
