// The motion of a vessel driven by displacement RAOs in the model's own waves: every wave
// component (its own frequency, heading, amplitude and phase) gives a response
//   x_j(t) = sum_k Re{ H_j(w_k, beta_k) A_k e^{i w_k t} }
//   A_k = a_k e^{i (phi_k - k_k (o_x cos beta_k + o_y sin beta_k))}   (reference: RAO origin)
//   A_k = a_k e^{i phi_k}                                            (reference: global origin)
// about the RAO origin o, with H interpolated in frequency and heading (rao_table.hpp) and
// the wave elevation eta = a cos(w t - k (x cos b + y sin b) + phi) of wave_field.hpp. So
// in a regular wave of amplitude a the response is a |H_j| cos(w t + arg H_j - k.o + phi):
// its amplitude a |H_j|, its crest (maximum) leading the wave crest at o by arg H_j.
// The RAO frame is the global frame: the vessel's headings are the wave directions (the
// loader refuses a vessel turned in yaw).
#pragma once

#include <complex>
#include <limits>
#include <mutex>
#include <vector>

#include "seaflex/hydro/rao_table.hpp"
#include "seaflex/hydro/wave_component.hpp"
#include "seaflex/model/motion.hpp"

namespace seaflex::hydro {

class RaoMotion : public Motion {
 public:
  /// The table is interpolated once per component here. *clamped (if given) is set to the
  /// number of components whose heading lies outside the table's headings (clamped).
  RaoMotion(const RaoTable& table, const std::vector<WaveComponent>& components, const Vec3& origin,
            RaoPhaseReference reference, int* clamped = nullptr);
  MotionSample sample(double t) const override;

  /// The complex amplitude H A of component k (x_j = Re{c_j e^{i w t}}).
  Vec6c complex_amplitude(std::size_t k) const;

 private:
  // per component: its frequency; and sample()'s sums as one matrix-vector product,
  // [x; x_t; x_tt] = sums_ [cos(w t); sin(w t)], with the complex amplitude c_jk = re_jk +
  // i im_jk of H A: row j of x_j holds (re_jk, -im_jk), of x_t,j (-w_k im_jk, -w_k re_jk), of
  // x_tt,j (-w_k^2 re_jk, w_k^2 im_jk) (18 x 2K, row-major, summed by math::row_sums;
  // complex_amplitude() reads c from the rows of x)
  std::vector<double> omega_;
  std::vector<double> sums_;
  // the last sample: the constraints ask for the same t several times per Newton iteration,
  // and each sample costs a sine and cosine per wave component (issue 21)
  mutable std::mutex memo_mutex_;
  mutable double memo_t_ = std::numeric_limits<double>::quiet_NaN();
  mutable MotionSample memo_;
};

/// The sum of two motions' displacements (a slow drift added to a wave-frequency motion;
/// the angles add, which is exact for rotations about one axis and a small-angle
/// approximation otherwise).
class SumMotion : public Motion {
 public:
  SumMotion(std::shared_ptr<const Motion> a, std::shared_ptr<const Motion> b)
      : a_(std::move(a)), b_(std::move(b)) {}
  MotionSample sample(double t) const override;

 private:
  std::shared_ptr<const Motion> a_, b_;
};

}  // namespace seaflex::hydro
