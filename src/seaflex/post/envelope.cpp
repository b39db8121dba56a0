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
  // cwiseMin/Max would drop NaN in favour of the number: NaN is kept wherever it comes,
  // first or later (a quantity that does not apply, or a value that could not be computed:
  // the extreme is then unknown, not the extreme of the other rows). A NaN extreme stays (a
  // comparison with NaN is false); a NaN value replaces a number (v != v). Written as
  // selects over the whole storage, not as conditional stores, so that the compiler can
  // vectorize them
  const double* v = values.data();
  double* lo = min_.data();
  double* hi = max_.data();
  const Index size = values.size();
  for (Index i = 0; i < size; ++i) {
    const bool nan = v[i] != v[i];
    lo[i] = (v[i] < lo[i] || nan) ? v[i] : lo[i];
    hi[i] = (v[i] > hi[i] || nan) ? v[i] : hi[i];
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
