// The memory term of Cummins' equation (Cummins 1962; thesis eq. 173),
//   F_mem(t) = - int_0^t K(t - s) v(s) ds,
// for one rigid body with generalized velocity v = (linear velocity, angular velocity),
// evaluated two ways:
// - ConvolutionRadiation: direct trapezoidal convolution over the stored history.
// - StateSpaceRadiation: each significant K_ij(t) replaced by a state-space model
//   c e^{A t} b fitted to the samples (ERA, Kung 1978 / Juang & Pappa 1985, see
//   impulse_response_fit.hpp; cf. Taghipour, Perez & Moan 2008, "Hybrid frequency-time
//   domain models for dynamic response analysis of marine structures", Ocean Eng. 35),
//   x_ij' = A x_ij + b v_j, F_i = -sum_j c x_ij. Between accepted steps v is taken linear in
//   time and the states are propagated exactly with the matrix exponential of the
//   augmented matrix [A b 0; 0 0 1; 0 0 0] (Van Loan 1978, "Computing integrals involving
//   the matrix exponential", IEEE TAC 23), computed with Eigen's MatrixFunctions and
//   cached per step length (RK4 asks for h/2 and h: after the first step no exponential).
// Both follow the accept/force protocol of forces with memory (DESIGN.md 1): force() is
// const and may be called at any stage time t >= the last accepted time with a trial
// velocity; accept() commits a step. Neither is thread-safe (StateSpaceRadiation's force()
// fills a mutable cache).
#pragma once

#include <array>
#include <vector>

#include "seaflex/hydro/hydro_database.hpp"
#include "seaflex/hydro/impulse_response_fit.hpp"
#include "seaflex/hydro/retardation.hpp"

namespace seaflex::hydro {

/// Direct convolution F = -int_{max(t0, t - memory)}^t K(t - s) v(s) ds (N, N m) by the
/// trapezoid over the accepted samples and the segment from the last one to (t, v_now);
/// K between its samples by linear interpolation. Samples older than memory are dropped
/// (ring buffer; it grows by doubling only while the history fills).
class ConvolutionRadiation {
 public:
  /// memory (s, > 0): length of history kept; K is zero beyond kernel.t_max(), so memory
  /// >= kernel.t_max() loses nothing. Starts as reset(0, 0).
  /// Throws std::invalid_argument for memory <= 0.
  ConvolutionRadiation(RetardationKernel kernel, double memory);

  /// Clears the history: the body moved with v0 (m/s, rad/s) from t0 (s) on (no earlier
  /// history: the integral starts at t0).
  void reset(double t0, const Vec6& v0);
  /// Appends the accepted sample (t, v); t (s) must exceed the last accepted time
  /// (std::invalid_argument otherwise).
  void accept(double t, const Vec6& v);
  /// Memory force (N, N m) at t (s, >= the last accepted time) with velocity v_now.
  /// Throws std::invalid_argument for t before the last accepted time.
  Vec6 force(double t, const Vec6& v_now) const;
  /// dF/dv_now = -K(0) (t - t_last) / 2 (kg/s, ...), t_last the last accepted time.
  Mat6 dforce_dv(double t) const;

  /// The kernel used.
  const RetardationKernel& kernel() const { return kernel_; }
  /// Number of stored samples (for tests of the memory bound).
  std::size_t stored_samples() const { return size_; }

 private:
  struct Sample {
    double t;
    Vec6 v;
  };
  const Sample& sample(std::size_t k) const { return buffer_[(head_ + k) % buffer_.size()]; }
  void push(const Sample& s);

  RetardationKernel kernel_;
  double memory_;
  std::vector<Sample> buffer_;
  std::size_t head_ = 0;
  std::size_t size_ = 0;
};

/// State-space approximation of the memory force (see the file comment).
class StateSpaceRadiation {
 public:
  struct Options {
    double relative_tolerance = 1e-3;  ///< ERA: keep singular values above this * sigma_1
    int max_order = 20;                ///< ERA: maximum order per kernel entry
    double significance = 1e-3;        ///< fit K_ij if max|K_ij| > significance * max over all |K|
  };

  /// Fits every significant entry of kernel (see Options). Starts as reset(0, 0).
  /// Throws std::invalid_argument for bad options (see fit_impulse_response).
  StateSpaceRadiation(const RetardationKernel& kernel, Options options);

  /// Most kernel samples that from_damping computes in one pass.
  static constexpr std::size_t kMaxKernelSamples = 4096;
  /// The kernel of the damping table on [0, memory] (s), sampled every kernel_dt (s), and
  /// its fit. When memory / kernel_dt exceeds kMaxKernelSamples, the cost is bounded
  /// instead (issue 22: 2000 s at 1 ms took 30 s and 565 MB): a first pass with at most
  /// kMaxKernelSamples samples over [0, memory] finds where every entry of K has fallen
  /// below 1e-4 of its peak for good (plus a fifth, as the fit does), and a second pass
  /// samples only [0, that time] with at most kMaxKernelSamples samples, every kernel_dt or
  /// coarser. The fit keeps 2 x 120 decimated samples for its poles anyway
  /// (impulse_response_fit.hpp), so a finer step changes nothing it can resolve.
  /// Throws std::invalid_argument as RetardationKernel::from_damping and the constructor.
  static StateSpaceRadiation from_damping(const HydroDatabase& db, double kernel_dt, double memory,
                                          Options options);

  /// States zero, last accepted sample (t0 (s), v0).
  void reset(double t0, const Vec6& v0);
  /// Propagates the states exactly to t (s, > the last accepted time) with v linear from
  /// the last accepted sample to (t, v), and makes (t, v) the last accepted sample.
  void accept(double t, const Vec6& v);
  /// Memory force (N, N m) at t (s, >= the last accepted time) with velocity v_now, v linear
  /// in between. Throws std::invalid_argument for t before the last accepted time.
  Vec6 force(double t, const Vec6& v_now) const;
  /// dF/dv_now at t (exact for the linear-velocity propagation).
  Mat6 dforce_dv(double t) const;

  /// K(t) of the fitted model (zero for entries not fitted), t in s.
  Mat6 kernel(double t) const;
  /// Largest relative L2 fit error over the fitted entries (0 if none).
  double fit_error() const;
  /// Relative L2 fit error of each entry (0 where not fitted).
  Mat6 fit_errors() const;
  /// Sum of the orders of all fitted entries (number of states).
  int total_order() const { return static_cast<int>(x_.size()); }
  /// Number of poles discarded as unstable over all entries.
  int discarded_poles() const;

 private:
  struct Entry {
    int i, j;
    ImpulseResponseModel model;
    Eigen::Index offset;  // into x_
  };
  // exact propagation over tau for one entry:
  // x(tau) = phi x + g0 v_j(0) + g1 (v_j(tau) - v_j(0)) / tau
  struct EntryPropagator {
    Eigen::MatrixXd phi;
    Eigen::VectorXd g0, g1;
    Eigen::RowVectorXd c_phi;  // c phi
    double c_g0 = 0.0, c_g1 = 0.0;
  };
  struct Propagator {
    double tau = -1.0;
    std::vector<EntryPropagator> entries;
  };
  const Propagator& propagator(double tau) const;

  std::vector<Entry> entries_;
  Eigen::VectorXd x_;
  Eigen::VectorXd scratch_;
  double t_last_ = 0.0;
  Vec6 v_last_ = Vec6::Zero();
  mutable std::array<Propagator, 4> cache_;
  mutable std::size_t next_slot_ = 0;
};

}  // namespace seaflex::hydro
