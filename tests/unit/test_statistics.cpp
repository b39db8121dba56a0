// post/statistics: the streaming accumulator against exact results (a sampled sine) and
// against the batch formulas on a rough random record.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "seaflex/post/statistics.hpp"

using seaflex::post::RecordStatistics;
using seaflex::post::StatisticsAccumulator;

namespace {

// batch statistics: two-pass central moments and a direct scan for up-crossings of the
// mean (x_i < mean <= x_{i+1}) and the maxima between them
struct Batch {
  double mean = 0, std = 0, skewness = 0, kurtosis = 0;
  long up = 0;
  std::vector<double> peaks;
};
Batch batch(const std::vector<double>& x) {
  Batch b;
  const double n = static_cast<double>(x.size());
  for (double v : x) b.mean += v;
  b.mean /= n;
  double m2 = 0, m3 = 0, m4 = 0;
  for (double v : x) {
    const double d = v - b.mean;
    m2 += d * d;
    m3 += d * d * d;
    m4 += d * d * d * d;
  }
  m2 /= n, m3 /= n, m4 /= n;
  b.std = std::sqrt(m2);
  b.skewness = m3 / std::pow(m2, 1.5);
  b.kurtosis = m4 / (m2 * m2);
  double highest = 0;
  for (std::size_t i = 0; i + 1 < x.size(); ++i) {
    if (x[i] < b.mean && b.mean <= x[i + 1]) {
      if (b.up > 0) b.peaks.push_back(highest);
      ++b.up;
      highest = x[i + 1];
    } else if (b.up > 0) {
      highest = std::max(highest, x[i + 1]);
    }
  }
  return b;
}

}  // namespace

// x = c + A sin(2 pi t / T + phi) sampled 64 times a period for 50 whole periods (the
// last sample one step before the end): the discrete sums of sin, sin^2, sin^3, sin^4
// over whole periods are exact (sum of the M-th roots of unity is 0 for harmonics 1..4,
// all below 64), so mean = c, std = A / sqrt(2), skewness = 0, kurtosis = 3/8 / (1/4) =
// 1.5 hold to round-off. The phase 0.3 rad keeps every sample 0.005 A or more from the
// mean, so each period has exactly one up-crossing: N_up = 50 and Tz = n dt / 50 = T.
// Tolerance 1e-9 (round-off of 3200 additions is ~1e-13).
TEST(Statistics, SineIsExact) {
  const double A = 2.0, c = 5.0, T = 10.0, phi = 0.3;
  const int per = 64, periods = 50;
  const double dt = T / per;
  StatisticsAccumulator acc;
  std::vector<double> x;
  for (int k = 0; k < per * periods; ++k) {
    const double t = k * dt;
    x.push_back(c + A * std::sin(2.0 * std::numbers::pi * t / T + phi));
    acc.add(t, x.back());
  }
  const RecordStatistics s = acc.result();
  EXPECT_EQ(s.count, per * periods);
  EXPECT_NEAR(s.duration, periods * T, 1e-9);
  EXPECT_NEAR(s.mean, c, 1e-9);
  EXPECT_NEAR(s.std, A / std::sqrt(2.0), 1e-9);
  EXPECT_NEAR(s.skewness, 0.0, 1e-9);
  EXPECT_NEAR(s.kurtosis, 1.5, 1e-9);
  EXPECT_EQ(s.up_crossings, periods);
  EXPECT_NEAR(s.period, T, 1e-9);
  EXPECT_EQ(s.peaks, periods - 1);
  // the peaks: the largest sample of each period, at the sample phase closest to pi/2
  // (k = 13: 2 pi 13/64 + 0.3 = 1.5763 rad)
  const double top = c + A * std::sin(2.0 * std::numbers::pi * 13 / 64 + phi);
  for (double p : acc.peaks()) EXPECT_NEAR(p, top, 1e-12);
  EXPECT_NEAR(s.max, top, 1e-12);
}

// a rough random record (random walk plus noise, plateaus of equal values) against the
// batch formulas: moments to 1e-10 relative, up-crossings and peaks exactly
TEST(Statistics, RandomRecordMatchesBatchFormulas) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> noise(0.0, 1.0);
  std::vector<double> x;
  StatisticsAccumulator acc;
  double walk = 100.0;
  for (int k = 0; k < 20000; ++k) {
    walk += 0.1 * noise(rng);
    double v = walk + noise(rng);
    if (k % 7 == 3) v = x.back();  // plateaus
    x.push_back(v);
    acc.add(0.1 * k, v);
  }
  const Batch b = batch(x);
  const RecordStatistics s = acc.result();
  EXPECT_NEAR(s.mean, b.mean, 1e-10 * std::abs(b.mean));
  EXPECT_NEAR(s.std, b.std, 1e-10 * b.std);
  EXPECT_NEAR(s.skewness, b.skewness, 1e-8 * std::max(1.0, std::abs(b.skewness)));
  EXPECT_NEAR(s.kurtosis, b.kurtosis, 1e-8 * b.kurtosis);
  EXPECT_EQ(s.up_crossings, b.up);
  ASSERT_GT(b.up, 100);
  EXPECT_EQ(acc.peaks(), b.peaks);
  EXPECT_EQ(s.peaks, static_cast<long>(b.peaks.size()));
}

// restart files: an accumulator saved half way and restored continues to the same
// numbers, bit for bit, as one that was never stopped
TEST(Statistics, SaveRestoreContinuesExactly) {
  std::mt19937_64 rng(11);
  std::normal_distribution<double> noise(0.0, 1.0);
  StatisticsAccumulator whole(10, 100.0), first(10, 100.0), second(10, 100.0);
  for (int k = 0; k < 10000; ++k) {
    const double t = 0.1 * k, v = std::sin(0.7 * t) + 0.3 * noise(rng);
    whole.add(t, v);
    if (k < 4321) {
      first.add(t, v);
      if (k == 4320) second.restore(first.save());
    } else {
      second.add(t, v);
    }
  }
  const RecordStatistics a = whole.result(), b = second.result();
  EXPECT_EQ(a.count, b.count);
  EXPECT_EQ(a.mean, b.mean);
  EXPECT_EQ(a.std, b.std);
  EXPECT_EQ(a.skewness, b.skewness);
  EXPECT_EQ(a.kurtosis, b.kurtosis);
  EXPECT_EQ(a.up_crossings, b.up_crossings);
  EXPECT_EQ(whole.peaks(), second.peaks());
  EXPECT_EQ(whole.block_maxima(), second.block_maxima());
  EXPECT_THROW(StatisticsAccumulator(3, 1.0).restore(whole.save()), std::invalid_argument);
}

// block maxima: blocks of 100 s from the first row; NaN rows are skipped everywhere
TEST(Statistics, BlockMaximaAndNaN) {
  StatisticsAccumulator acc(3, 100.0);
  for (int k = 0; k < 300; ++k) acc.add(50.0 + k, k == 120 ? NAN : std::fmod(k, 100.0) + k / 100);
  const std::vector<double> m = acc.block_maxima();
  ASSERT_EQ(m.size(), 3u);
  EXPECT_EQ(m[0], 99.0);
  EXPECT_EQ(m[1], 100.0);
  EXPECT_EQ(m[2], 101.0);
  EXPECT_EQ(acc.result().count, 299);
}
