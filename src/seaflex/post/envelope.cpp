#include "seaflex/post/envelope.hpp"

#include <stdexcept>

#include "seaflex/math/vector_clones.hpp"

namespace seaflex::post {

namespace {
// lo = min(lo, v), hi = max(hi, v) entry by entry. cwiseMin/Max would drop NaN in favour of
// the number: NaN is kept wherever it comes, first or later (a quantity that does not apply,
// or a value that could not be computed: the extreme is then unknown, not the extreme of the
// other rows). A NaN extreme stays (a comparison with NaN is false); a NaN value replaces the
// number (v != v). Selects, not conditional stores, and the conditions joined by a bitwise |
// (|| is a branch), so that the loop is vectorized; compiled also for AVX2
// (math/vector_clones.hpp)
SEAFLEX_VECTOR_CLONES
void extremes(const double* v, double* lo, double* hi, Index size) {
  for (Index i = 0; i < size; ++i) {
    const double x = v[i];
    const bool nan = x != x;
    lo[i] = ((x < lo[i]) | nan) ? x : lo[i];
    hi[i] = ((x > hi[i]) | nan) ? x : hi[i];
  }
}
}  // namespace

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
  extremes(values.data(), min_.data(), max_.data(), values.size());
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
