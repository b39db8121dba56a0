#include "seaflex/model/table_motion.hpp"

#include <algorithm>
#include <stdexcept>

namespace seaflex {

TableMotion::TableMotion(std::vector<double> times, std::vector<Vec6> values)
    : times_(std::move(times)), values_(std::move(values)) {
  const std::size_t n = times_.size();
  if (n < 2 || values_.size() != n)
    throw std::invalid_argument("TableMotion: at least two rows of time and six values");
  for (std::size_t i = 1; i < n; ++i)
    if (!(times_[i] > times_[i - 1]))
      throw std::invalid_argument("TableMotion: times must increase strictly");
  second_.assign(n, Vec6::Zero());
  if (n < 3) return;
  // natural spline: Thomas algorithm on the interior second derivatives
  const std::size_t m = n - 2;
  std::vector<double> diag(m), upper(m);
  std::vector<Vec6> rhs(m);
  for (std::size_t k = 0; k < m; ++k) {
    const std::size_t i = k + 1;
    const double h0 = times_[i] - times_[i - 1], h1 = times_[i + 1] - times_[i];
    diag[k] = 2.0 * (h0 + h1);
    upper[k] = h1;
    rhs[k] = 6.0 * ((values_[i + 1] - values_[i]) / h1 - (values_[i] - values_[i - 1]) / h0);
    if (k > 0) {  // eliminate the sub-diagonal h0
      const double f = h0 / diag[k - 1];
      diag[k] -= f * upper[k - 1];
      rhs[k] -= f * rhs[k - 1];
    }
  }
  for (std::size_t k = m; k-- > 0;) {
    Vec6 r = rhs[k];
    if (k + 1 < m) r -= upper[k] * second_[k + 2];
    second_[k + 1] = r / diag[k];
  }
}

MotionSample TableMotion::sample(double t) const {
  MotionSample s;
  if (t <= times_.front()) {
    s.x = values_.front();
    return s;
  }
  if (t >= times_.back()) {
    s.x = values_.back();
    return s;
  }
  const auto it = std::upper_bound(times_.begin(), times_.end(), t);
  const std::size_t i = static_cast<std::size_t>(it - times_.begin()) - 1;
  const double h = times_[i + 1] - times_[i];
  const double a = (times_[i + 1] - t) / h, b = (t - times_[i]) / h;
  const Vec6 &y0 = values_[i], &y1 = values_[i + 1], &M0 = second_[i], &M1 = second_[i + 1];
  // de Boor (1978) ch. IV: the cubic on [t_i, t_i+1] in terms of y and M
  s.x = a * y0 + b * y1 + ((a * a * a - a) * M0 + (b * b * b - b) * M1) * (h * h / 6.0);
  s.x_t = (y1 - y0) / h + ((1.0 - 3.0 * a * a) * M0 + (3.0 * b * b - 1.0) * M1) * (h / 6.0);
  s.x_tt = a * M0 + b * M1;
  return s;
}

}  // namespace seaflex
