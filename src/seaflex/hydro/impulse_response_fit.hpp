// State-space realization of a sampled scalar impulse response y(t) ~ c e^{A t} b:
// - poles by the Eigensystem Realization Algorithm (Kung 1978, "A new identification and
//   model reduction algorithm via singular value decomposition", 12th Asilomar Conf.;
//   Juang & Pappa 1985, J. Guidance 8(5)): SVD of the Hankel matrix H0 of the samples,
//   order n = number of singular values above relative_tolerance * sigma_1 (at most
//   max_order), discrete state matrix Ad = S^-1/2 U^T H1 V S^-1/2 (H1 the shifted
//   Hankel matrix); continuous poles s = log(lambda(Ad)) / dt_era, i.e. the eigenvalues
//   of A = log(Ad) / dt_era, taken one eigenvalue at a time (principal logarithm).
// - unstable or marginal discrete poles (|lambda| >= 1) and poles on the negative real
//   axis (no real continuous counterpart) are discarded and counted;
// - the residues of the kept poles are then fitted by linear least squares to all
//   samples (not ERA's b and c): this minimizes the L2 error for the kept poles and makes
//   discarding a pole harmless to the rest of the fit;
// - the realization is real and block diagonal: a real pole s gives A = [s], b = [1],
//   c = [r]; a pair sigma +- i w gives A = [sigma w; -w sigma], b = [0; 1],
//   c = [r_sin r_cos], whose impulse response is e^{sigma t} (r_sin sin wt + r_cos cos wt).
// The Hankel matrix is at most kMaxHankel x kMaxHankel (120): the samples are decimated by
// a stride when the response (to 1e-4 of its peak) is longer than 2 kMaxHankel samples.
// The residues are fitted to at most kMaxResidueRows (8192) samples, every s-th one when
// there are more (fit_error still covers all): time O(samples), memory O(8192 x order).
#pragma once

#include <Eigen/Dense>
#include <vector>

namespace seaflex::hydro {

/// y(t) ~ c e^{a t} b for t >= 0 (units: those of y; a in 1/s).
struct ImpulseResponseModel {
  Eigen::MatrixXd a;        ///< n x n, block diagonal (1x1 real poles, 2x2 pairs)
  Eigen::VectorXd b;        ///< n
  Eigen::RowVectorXd c;     ///< n
  double fit_error = 0.0;   ///< ||y_fit - y||_2 / ||y||_2 over the samples (0 if y = 0)
  int discarded_poles = 0;  ///< unstable / negative-real poles dropped

  /// Model order n.
  int order() const { return static_cast<int>(a.rows()); }
  /// c e^{a t} b at t (s).
  double evaluate(double t) const;
};

/// Fits y_k = y(k dt), k = 0 .. y.size() - 1 (dt in s). relative_tolerance (> 0) and
/// max_order (>= 1) choose the order (see the file comment). An all-zero y gives order 0.
/// Throws std::invalid_argument for dt <= 0, relative_tolerance <= 0, max_order < 1.
ImpulseResponseModel fit_impulse_response(const std::vector<double>& y, double dt,
                                          double relative_tolerance, int max_order);

}  // namespace seaflex::hydro
