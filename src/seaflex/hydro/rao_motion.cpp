#include "seaflex/hydro/rao_motion.hpp"

#include <array>
#include <cmath>
#include <stdexcept>

#include "seaflex/math/row_sums.hpp"

namespace seaflex::hydro {

RaoMotion::RaoMotion(const RaoTable& table, const std::vector<WaveComponent>& components,
                     const Vec3& origin, RaoPhaseReference reference, int* clamped) {
  if (clamped) *clamped = 0;
  std::vector<Vec6c> amplitudes;  // H A of each component kept
  for (const WaveComponent& w : components) {
    if (w.amplitude == 0.0) continue;
    bool off = false;
    const Vec6c H = table.at(w.omega, w.direction, &off);
    if (off && clamped) ++*clamped;
    double phase = w.phase;
    if (reference == RaoPhaseReference::kRaoOrigin)
      phase -= w.k * (origin.x() * std::cos(w.direction) + origin.y() * std::sin(w.direction));
    amplitudes.push_back(H * std::polar(w.amplitude, phase));
    omega_.push_back(w.omega);
  }
  const std::size_t K = omega_.size();
  sums_.assign(18 * 2 * K, 0.0);
  auto at = [&](std::size_t row, std::size_t col) -> double& { return sums_[row * 2 * K + col]; };
  for (std::size_t k = 0; k < K; ++k) {
    const double w = omega_[k];
    for (std::size_t j = 0; j < 6; ++j) {
      const double re = amplitudes[k][static_cast<Index>(j)].real();
      const double im = amplitudes[k][static_cast<Index>(j)].imag();
      // z = c_j e^{iwt}; x = Re{z}, x' = Re{i w z} = -w Im{z}, x'' = -w^2 x
      at(j, k) = re;
      at(j, K + k) = -im;
      at(6 + j, k) = -w * im;
      at(6 + j, K + k) = -w * re;
      at(12 + j, k) = -w * w * re;
      at(12 + j, K + k) = w * w * im;
    }
  }
}

Vec6c RaoMotion::complex_amplitude(std::size_t k) const {
  if (k >= omega_.size()) throw std::out_of_range("RaoMotion::complex_amplitude");
  Vec6c c;
  const std::size_t K = omega_.size();
  for (std::size_t j = 0; j < 6; ++j)  // from sums_'s row of x_j: (re, -im)
    c[static_cast<Index>(j)] = {sums_[j * 2 * K + k], -sums_[j * 2 * K + K + k]};
  return c;
}

MotionSample RaoMotion::sample(double t) const {
  {
    const std::lock_guard<std::mutex> lock(memo_mutex_);
    if (t == memo_t_) return memo_;
  }
  const std::size_t K = omega_.size();
  thread_local std::vector<double> cs;  // cos(w_k t), then sin(w_k t); kept per thread
  cs.resize(2 * K);
  for (std::size_t k = 0; k < K; ++k) {
    const double wt = omega_[k] * t;
    const double c = std::cos(wt), s = std::sin(wt);  // one sincos
    cs[k] = c;
    cs[K + k] = s;
  }
  std::array<double, 18> y{};
  math::row_sums(sums_.data(), 2 * K, 18, cs.data(), 2 * K, y.data());
  MotionSample m;
  for (int j = 0; j < 6; ++j) {
    m.x[j] = y[static_cast<std::size_t>(j)];
    m.x_t[j] = y[static_cast<std::size_t>(6 + j)];
    m.x_tt[j] = y[static_cast<std::size_t>(12 + j)];
  }
  const std::lock_guard<std::mutex> lock(memo_mutex_);
  memo_t_ = t;
  memo_ = m;
  return m;
}

MotionSample SumMotion::sample(double t) const {
  MotionSample a = a_->sample(t);
  const MotionSample b = b_->sample(t);
  a.x += b.x;
  a.x_t += b.x_t;
  a.x_tt += b.x_tt;
  return a;
}

}  // namespace seaflex::hydro
