#include "seaflex/hydro/radiation_memory.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>
#include <unsupported/Eigen/MatrixFunctions>

namespace seaflex::hydro {

// ---- ConvolutionRadiation ----

ConvolutionRadiation::ConvolutionRadiation(RetardationKernel kernel, double memory)
    : kernel_(std::move(kernel)), memory_(memory) {
  if (!(memory > 0.0))
    throw std::invalid_argument(
        fmt::format("convolution radiation: memory must be > 0, got {}", memory));
  buffer_.resize(16);
  reset(0.0, Vec6::Zero());
}

void ConvolutionRadiation::reset(double t0, const Vec6& v0) {
  head_ = 0;
  size_ = 0;
  push(Sample{t0, v0});
}

void ConvolutionRadiation::push(const Sample& s) {
  if (size_ == buffer_.size()) {
    // grow: unroll the ring into a buffer twice as large
    std::vector<Sample> bigger(2 * buffer_.size());
    for (std::size_t k = 0; k < size_; ++k) bigger[k] = sample(k);
    buffer_.swap(bigger);
    head_ = 0;
  }
  buffer_[(head_ + size_) % buffer_.size()] = s;
  ++size_;
}

void ConvolutionRadiation::accept(double t, const Vec6& v) {
  const double t_last = sample(size_ - 1).t;
  if (!(t > t_last))
    throw std::invalid_argument(fmt::format(
        "convolution radiation: accepted time {} s must exceed the last one, {} s", t, t_last));
  push(Sample{t, v});
  // keep one sample at or before t - memory for the partial first segment
  while (size_ >= 2 && sample(1).t <= t - memory_) {
    head_ = (head_ + 1) % buffer_.size();
    --size_;
  }
}

Vec6 ConvolutionRadiation::force(double t, const Vec6& v_now) const {
  const Sample& last = sample(size_ - 1);
  if (t < last.t)
    throw std::invalid_argument(fmt::format(
        "convolution radiation: time {} s is before the last accepted time {} s", t, last.t));
  const double lower = std::max(sample(0).t, t - memory_);
  const double t_max = kernel_.t_max();
  Vec6 sum = Vec6::Zero();
  // trapezoid over [s_k, s_k+1], the last segment ending at (t, v_now)
  for (std::size_t k = 0; k < size_; ++k) {
    const Sample& a = sample(k);
    const bool final_segment = k + 1 == size_;
    const double tb = final_segment ? t : sample(k + 1).t;
    const Vec6& vb = final_segment ? v_now : sample(k + 1).v;
    if (tb <= lower || t - tb > t_max) continue;  // outside the memory or the kernel
    double ta = a.t;
    Vec6 va = a.v;
    if (ta < lower) {
      const double s = (lower - ta) / (tb - ta);
      va = (1.0 - s) * a.v + s * vb;
      ta = lower;
    }
    const double h = tb - ta;
    if (h <= 0.0) continue;
    sum += 0.5 * h * (kernel_.at(t - ta) * va + kernel_.at(t - tb) * vb);
  }
  return -sum;  // thesis eq. 173: the memory term enters with a minus sign as a force
}

Mat6 ConvolutionRadiation::dforce_dv(double t) const {
  const double h = t - sample(size_ - 1).t;
  if (h <= 0.0) return Mat6::Zero();
  return -0.5 * std::min(h, memory_) * kernel_.at(0.0);
}

// ---- StateSpaceRadiation ----

StateSpaceRadiation::StateSpaceRadiation(const RetardationKernel& kernel, Options options) {
  const auto& samples = kernel.samples();
  Mat6 peak = Mat6::Zero();
  for (const auto& k : samples) peak = peak.cwiseMax(k.cwiseAbs());
  const double largest = peak.maxCoeff();
  Eigen::Index offset = 0;
  std::vector<double> y(samples.size());
  for (int j = 0; j < 6; ++j) {
    for (int i = 0; i < 6; ++i) {
      if (largest == 0.0 || !(peak(i, j) > options.significance * largest)) continue;
      for (std::size_t k = 0; k < samples.size(); ++k) y[k] = samples[k](i, j);
      Entry e{i, j,
              fit_impulse_response(y, kernel.dt(), options.relative_tolerance, options.max_order),
              offset};
      offset += e.model.order();
      if (e.model.order() > 0) entries_.push_back(std::move(e));
    }
  }
  x_ = Eigen::VectorXd::Zero(offset);
  scratch_ = Eigen::VectorXd::Zero(offset);
  reset(0.0, Vec6::Zero());
}

StateSpaceRadiation StateSpaceRadiation::from_damping(const HydroDatabase& db, double kernel_dt,
                                                      double memory, Options options) {
  const auto max_samples = static_cast<double>(kMaxKernelSamples);
  if (!(memory / kernel_dt > max_samples))
    return StateSpaceRadiation(RetardationKernel::from_damping(db, kernel_dt, memory), options);
  // first pass: where the kernel ends (the last sample above 1e-4 of each entry's peak)
  const double coarse_dt = memory / (max_samples - 1.0);
  const RetardationKernel coarse = RetardationKernel::from_damping(db, coarse_dt, memory);
  const auto& samples = coarse.samples();
  Mat6 peak = Mat6::Zero();
  for (const auto& k : samples) peak = peak.cwiseMax(k.cwiseAbs());
  // (only the entries that will be fitted: see Options::significance)
  const double largest = peak.maxCoeff();
  const Eigen::Array<bool, 6, 6> fitted = peak.array() > options.significance * largest;
  std::size_t last = 1;
  for (std::size_t k = 0; k < samples.size(); ++k)
    if ((fitted && (samples[k].cwiseAbs().array() > 1e-4 * peak.array())).any()) last = k;
  // one coarse sample more (the kernel may still be above the threshold until the next one)
  // and a fifth more, as fit_impulse_response does
  const double length = std::min(memory, coarse_dt * static_cast<double>(last + 1) * 1.2);
  const double dt = std::max(kernel_dt, length / (max_samples - 1.0));
  return StateSpaceRadiation(RetardationKernel::from_damping(db, dt, std::max(length, dt)),
                             options);
}

void StateSpaceRadiation::reset(double t0, const Vec6& v0) {
  x_.setZero();
  t_last_ = t0;
  v_last_ = v0;
}

const StateSpaceRadiation::Propagator& StateSpaceRadiation::propagator(double tau) const {
  for (const auto& p : cache_)
    if (p.tau == tau) return p;
  Propagator& p = cache_[next_slot_];
  next_slot_ = (next_slot_ + 1) % cache_.size();
  p.tau = tau;
  p.entries.resize(entries_.size());
  for (std::size_t e = 0; e < entries_.size(); ++e) {
    const auto& m = entries_[e].model;
    const Eigen::Index n = m.order();
    // Van Loan (1978): exp([A b 0; 0 0 1; 0 0 0] tau) = [phi g0 g1; 0 1 tau; 0 0 1] with
    // g0 = int_0^tau e^{A s} ds b and g1 = int_0^tau e^{A (tau - s)} s ds b
    Eigen::MatrixXd aug = Eigen::MatrixXd::Zero(n + 2, n + 2);
    aug.topLeftCorner(n, n) = m.a;
    aug.block(0, n, n, 1) = m.b;
    aug(n, n + 1) = 1.0;
    const Eigen::MatrixXd ex = (aug * tau).exp();
    auto& ep = p.entries[e];
    ep.phi = ex.topLeftCorner(n, n);
    ep.g0 = ex.block(0, n, n, 1);
    ep.g1 = ex.block(0, n + 1, n, 1);
    ep.c_phi = m.c * ep.phi;
    ep.c_g0 = m.c.dot(ep.g0);
    ep.c_g1 = m.c.dot(ep.g1);
  }
  return p;
}

void StateSpaceRadiation::accept(double t, const Vec6& v) {
  const double tau = t - t_last_;
  if (!(tau > 0.0))
    throw std::invalid_argument(fmt::format(
        "state-space radiation: accepted time {} s must exceed the last one, {} s", t, t_last_));
  const Propagator& p = propagator(tau);
  for (std::size_t e = 0; e < entries_.size(); ++e) {
    const auto& entry = entries_[e];
    const auto& ep = p.entries[e];
    const Eigen::Index n = entry.model.order();
    const double v0 = v_last_(entry.j), v1 = v(entry.j);
    auto x = x_.segment(entry.offset, n);
    auto tmp = scratch_.segment(entry.offset, n);
    tmp.noalias() = ep.phi * x;
    x = tmp + ep.g0 * v0 + ep.g1 * ((v1 - v0) / tau);
  }
  t_last_ = t;
  v_last_ = v;
}

Vec6 StateSpaceRadiation::force(double t, const Vec6& v_now) const {
  const double tau = t - t_last_;
  if (tau < 0.0)
    throw std::invalid_argument(fmt::format(
        "state-space radiation: time {} s is before the last accepted time {} s", t, t_last_));
  Vec6 f = Vec6::Zero();
  if (tau == 0.0) {
    for (const auto& entry : entries_)
      f(entry.i) -= entry.model.c.dot(x_.segment(entry.offset, entry.model.order()));
    return f;
  }
  const Propagator& p = propagator(tau);
  for (std::size_t e = 0; e < entries_.size(); ++e) {
    const auto& entry = entries_[e];
    const auto& ep = p.entries[e];
    const double v0 = v_last_(entry.j), v1 = v_now(entry.j);
    const double cx = ep.c_phi.dot(x_.segment(entry.offset, entry.model.order()));
    f(entry.i) -= cx + ep.c_g0 * v0 + ep.c_g1 * (v1 - v0) / tau;
  }
  return f;
}

Mat6 StateSpaceRadiation::dforce_dv(double t) const {
  const double tau = t - t_last_;
  Mat6 d = Mat6::Zero();
  if (!(tau > 0.0)) return d;
  const Propagator& p = propagator(tau);
  for (std::size_t e = 0; e < entries_.size(); ++e)
    d(entries_[e].i, entries_[e].j) -= p.entries[e].c_g1 / tau;
  return d;
}

Mat6 StateSpaceRadiation::kernel(double t) const {
  Mat6 k = Mat6::Zero();
  for (const auto& entry : entries_) k(entry.i, entry.j) = entry.model.evaluate(t);
  return k;
}

double StateSpaceRadiation::fit_error() const {
  double worst = 0.0;
  for (const auto& entry : entries_) worst = std::max(worst, entry.model.fit_error);
  return worst;
}

Mat6 StateSpaceRadiation::fit_errors() const {
  Mat6 err = Mat6::Zero();
  for (const auto& entry : entries_) err(entry.i, entry.j) = entry.model.fit_error;
  return err;
}

int StateSpaceRadiation::discarded_poles() const {
  int n = 0;
  for (const auto& entry : entries_) n += entry.model.discarded_poles;
  return n;
}

}  // namespace seaflex::hydro
