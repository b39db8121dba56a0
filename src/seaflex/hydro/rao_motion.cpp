#include "seaflex/hydro/rao_motion.hpp"

#include <cmath>
#include <stdexcept>

namespace seaflex::hydro {

RaoMotion::RaoMotion(const RaoTable& table, const std::vector<WaveComponent>& components,
                     const Vec3& origin, RaoPhaseReference reference, int* clamped) {
  if (clamped) *clamped = 0;
  for (const WaveComponent& w : components) {
    if (w.amplitude == 0.0) continue;
    bool off = false;
    const Vec6c H = table.at(w.omega, w.direction, &off);
    if (off && clamped) ++*clamped;
    double phase = w.phase;
    if (reference == RaoPhaseReference::kRaoOrigin)
      phase -= w.k * (origin.x() * std::cos(w.direction) + origin.y() * std::sin(w.direction));
    const Vec6c c = H * std::polar(w.amplitude, phase);
    omega_.push_back(w.omega);
    for (int j = 0; j < 6; ++j) {
      re_.push_back(c[j].real());
      im_.push_back(c[j].imag());
    }
  }
}

Vec6c RaoMotion::complex_amplitude(std::size_t k) const {
  if (k >= omega_.size()) throw std::out_of_range("RaoMotion::complex_amplitude");
  Vec6c c;
  for (int j = 0; j < 6; ++j) c[j] = {re_[6 * k + j], im_[6 * k + j]};
  return c;
}

MotionSample RaoMotion::sample(double t) const {
  {
    const std::lock_guard<std::mutex> lock(memo_mutex_);
    if (t == memo_t_) return memo_;
  }
  MotionSample m;
  for (std::size_t k = 0; k < omega_.size(); ++k) {
    const double w = omega_[k];
    const double c = std::cos(w * t), s = std::sin(w * t);
    const double* re = &re_[6 * k];
    const double* im = &im_[6 * k];
    for (int j = 0; j < 6; ++j) {
      // z = c_j e^{iwt}; x = Re{z}, x' = Re{i w z} = -w Im{z}, x'' = -w^2 x
      const double zr = re[j] * c - im[j] * s;
      const double zi = re[j] * s + im[j] * c;
      m.x[j] += zr;
      m.x_t[j] -= w * zi;
      m.x_tt[j] -= w * w * zr;
    }
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
