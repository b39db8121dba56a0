// Statistics of one time record, accumulated row by row (a run does not keep its rows):
// minimum, maximum, mean, standard deviation, skewness, kurtosis, the mean up-crossing
// period and the peaks between up-crossings, and the maxima of equal time blocks (for the
// Gumbel fit of post/extremes.hpp).
//
// Moments: the one-pass updates of the central sums M2, M3, M4 (Terriberry 2007, after
// Welford 1962; Pebay 2008, eq. (1.5)), stable for a record with a large mean:
//   n' = n + 1, d = x - mean, d_n = d / n', t = d d_n n,
//   mean' = mean + d_n,
//   M4' = M4 + t d_n^2 (n'^2 - 3 n' + 3) + 6 d_n^2 M2 - 4 d_n M3,
//   M3' = M3 + t d_n (n' - 2) - 3 d_n M2,
//   M2' = M2 + t.
// Population moments (divisor n, as the record is the whole sample):
//   std = sqrt(M2 / n), skewness = sqrt(n) M3 / M2^1.5, kurtosis = n M4 / M2^2 (not the
//   excess: 3 for a Gaussian record, 1.5 for a sine).
// Up-crossings of the mean: sample i up-crosses level L when x_i < L <= x_{i+1}. The level
// (the mean) is known only at the end, so the accumulator keeps the record's turning
// points (its local extremes, with the first and last samples): between two turning points
// the samples are monotone, so a rising pair (a, b) holds exactly one up-crossing of L when
// a < L <= b and a falling pair none. The count is then exact for the final mean, and the
// memory is that of the turning points (about two per cycle of a smooth signal; a noisy
// signal sampled finer than its noise keeps more).
// Peaks: the maximum of the record between two successive up-crossings of the mean (so
// there are up_crossings - 1 of them); the amplitudes above the mean feed the Weibull fit.
// Mean up-crossing period: Tz = T / N_up with T = n dt the record's duration (n rows of
// the output interval dt = (t_last - t_first) / (n - 1)).
#pragma once

#include <vector>

#include "seaflex/core/types.hpp"

namespace seaflex::post {

/// The statistics of a record (see the file header for the definitions).
struct RecordStatistics {
  long count = 0;         ///< rows
  double duration = 0.0;  ///< n dt (s)
  double min = 0.0, max = 0.0, mean = 0.0;
  double std = 0.0;       ///< population standard deviation
  double skewness = 0.0;  ///< NaN when std is 0
  double kurtosis = 0.0;  ///< not the excess; NaN when std is 0
  long up_crossings = 0;  ///< of the mean
  double period = 0.0;    ///< mean up-crossing period Tz (s); NaN without up-crossings
  long peaks = 0;         ///< maxima between successive up-crossings of the mean
};

class StatisticsAccumulator {
 public:
  /// blocks: the number of equal time blocks of block_length seconds, counted from the
  /// first row, whose maxima are kept (0: none); a row beyond the last block goes to it.
  explicit StatisticsAccumulator(int blocks = 0, double block_length = 0.0);

  /// Adds the row at time t (increasing) with value x. NaN values are counted nowhere
  /// (a quantity that does not apply is NaN in every row).
  void add(double t, double x);

  RecordStatistics result() const;
  /// The peaks: maxima between successive up-crossings of the mean (absolute values).
  std::vector<double> peaks() const;
  /// The maxima of the blocks (NaN for a block without rows).
  std::vector<double> block_maxima() const;
  double block_length() const { return block_length_; }

  /// Restart files: the complete state as numbers, and back.
  std::vector<double> save() const;
  /// Throws std::invalid_argument when the numbers are not from save().
  void restore(const std::vector<double>& saved);

 private:
  long n_ = 0;
  double mean_ = 0.0, M2_ = 0.0, M3_ = 0.0, M4_ = 0.0;
  double min_ = 0.0, max_ = 0.0;
  double t_first_ = 0.0, t_last_ = 0.0;
  int direction_ = 0;            // +1 rising, -1 falling, 0 not yet known
  double end_ = 0.0;             // the last sample, the provisional end of the turning points
  std::vector<double> turning_;  // first sample, then every local extreme
  double block_length_;
  std::vector<double> blocks_;
};

}  // namespace seaflex::post
