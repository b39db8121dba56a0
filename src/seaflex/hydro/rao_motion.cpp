#include "seaflex/hydro/rao_motion.hpp"

#include <cmath>

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
    terms_.push_back({w.omega, H * std::polar(w.amplitude, phase)});
  }
}

MotionSample RaoMotion::sample(double t) const {
  {
    const std::lock_guard<std::mutex> lock(memo_mutex_);
    if (t == memo_t_) return memo_;
  }
  MotionSample m;
  for (const Term& term : terms_) {
    const std::complex<double> e = std::polar(1.0, term.omega * t);
    const double w = term.omega;
    for (int j = 0; j < 6; ++j) {
      const std::complex<double> z = term.c[j] * e;
      // x = Re{c e^{iwt}}, x' = Re{i w c e^{iwt}} = -w Im{.}, x'' = -w^2 x
      m.x[j] += z.real();
      m.x_t[j] -= w * z.imag();
      m.x_tt[j] -= w * w * z.real();
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
