// Envelopes of results over time: the minimum, maximum and mean of every entry of a
// table (stations x quantities) over the output rows it is given, and optionally the
// minimum and maximum also over the steps between the rows (extend). An entry that is NaN
// in any row or step (a quantity that does not apply, or one that could not be computed)
// is NaN in the minimum and maximum, and, when in a row, in the mean (the mean is over the
// rows only; a step before the first row is ignored, as every value is).
#pragma once

#include "seaflex/core/types.hpp"

namespace seaflex::post {

class Envelope {
 public:
  /// Adds one output row's table; every table must have the size of the first.
  void add(const MatX& values);
  /// Takes a table between two rows into the minimum and maximum only (the mean stays over
  /// the rows); ignored before the first row, with which the envelope starts.
  void extend(const MatX& values);

  long count() const { return count_; }
  const MatX& min() const { return min_; }
  const MatX& max() const { return max_; }
  /// The mean over the rows added (the sum divided by count()).
  MatX mean() const;
  const MatX& sum() const { return sum_; }
  /// Takes back a saved envelope (restart files).
  void restore(long count, MatX min, MatX max, MatX sum);

 private:
  long count_ = 0;
  MatX min_, max_, sum_;
};

}  // namespace seaflex::post
