#include "seaflex/post/envelope.hpp"

#include <stdexcept>

namespace seaflex::post {

void Envelope::add(const MatX& values) {
  if (count_ == 0) {
    min_ = max_ = sum_ = values;
  } else {
    extend(values);  // checks the size
    sum_ += values;
  }
  ++count_;
}

void Envelope::extend(const MatX& values) {
  if (count_ == 0) return;
  if (values.rows() != min_.rows() || values.cols() != min_.cols())
    throw std::invalid_argument("Envelope: the table changed size");
  // cwiseMin/Max would drop NaN in favour of the number: keep NaN where it applies
  for (Index j = 0; j < values.cols(); ++j)
    for (Index i = 0; i < values.rows(); ++i) {
      const double v = values(i, j);
      if (v < min_(i, j)) min_(i, j) = v;
      if (v > max_(i, j)) max_(i, j) = v;
    }
}

MatX Envelope::mean() const {
  return count_ > 0 ? MatX(sum_ / static_cast<double>(count_)) : MatX();
}

void Envelope::restore(long count, MatX min, MatX max, MatX sum) {
  count_ = count;
  min_ = std::move(min);
  max_ = std::move(max);
  sum_ = std::move(sum);
}

}  // namespace seaflex::post
