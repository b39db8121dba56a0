#include "seaflex/post/statistics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace seaflex::post {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
}  // namespace

StatisticsAccumulator::StatisticsAccumulator(int blocks, double block_length)
    : block_length_(block_length), blocks_(static_cast<std::size_t>(std::max(blocks, 0)), kNaN) {
  if (blocks > 0 && !(block_length > 0.0))
    throw std::invalid_argument("StatisticsAccumulator: blocks need a positive block length");
}

void StatisticsAccumulator::add(double t, double x) {
  if (std::isnan(x)) return;
  if (n_ == 0) {
    t_first_ = t;
    min_ = max_ = x;
    turning_.assign(1, x);
    end_ = x;
  } else {
    min_ = std::min(min_, x);
    max_ = std::max(max_, x);
    // turning points: a change of direction makes the previous sample an extreme
    if (direction_ == 0) {
      direction_ = x > end_ ? 1 : x < end_ ? -1 : 0;
    } else if ((direction_ > 0 && x < end_) || (direction_ < 0 && x > end_)) {
      turning_.push_back(end_);
      direction_ = -direction_;
    }
    end_ = x;
  }
  t_last_ = t;
  // Terriberry (2007) one-pass central moments (file header)
  const double n1 = static_cast<double>(n_);
  ++n_;
  const double n = static_cast<double>(n_);
  const double d = x - mean_, dn = d / n, dn2 = dn * dn, term = d * dn * n1;
  mean_ += dn;
  M4_ += term * dn2 * (n * n - 3.0 * n + 3.0) + 6.0 * dn2 * M2_ - 4.0 * dn * M3_;
  M3_ += term * dn * (n - 2.0) - 3.0 * dn * M2_;
  M2_ += term;
  if (!blocks_.empty()) {
    const double k = std::floor((t - t_first_) / block_length_ + 1e-9);
    const auto b = static_cast<std::size_t>(
        std::min(std::max(k, 0.0), static_cast<double>(blocks_.size() - 1)));
    if (std::isnan(blocks_[b]) || x > blocks_[b]) blocks_[b] = x;
  }
}

RecordStatistics StatisticsAccumulator::result() const {
  RecordStatistics s;
  s.count = n_;
  if (n_ == 0) {
    s.min = s.max = s.mean = s.std = s.skewness = s.kurtosis = s.period = s.duration = kNaN;
    return s;
  }
  const double n = static_cast<double>(n_);
  s.duration = n_ > 1 ? (t_last_ - t_first_) * n / (n - 1.0) : 0.0;
  s.min = min_;
  s.max = max_;
  s.mean = mean_;
  s.std = std::sqrt(M2_ / n);
  s.skewness = M2_ > 0.0 ? std::sqrt(n) * M3_ / std::pow(M2_, 1.5) : kNaN;
  s.kurtosis = M2_ > 0.0 ? n * M4_ / (M2_ * M2_) : kNaN;
  // up-crossings of the mean from the turning points (file header)
  long up = 0;
  double prev = turning_.front();
  auto visit = [&](double next) {
    if (prev < mean_ && mean_ <= next) ++up;
    prev = next;
  };
  for (std::size_t i = 1; i < turning_.size(); ++i) visit(turning_[i]);
  visit(end_);
  s.up_crossings = up;
  s.period = up > 0 ? s.duration / static_cast<double>(up) : kNaN;
  s.peaks = up > 1 ? up - 1 : 0;
  return s;
}

std::vector<double> StatisticsAccumulator::peaks() const {
  std::vector<double> out;
  if (n_ == 0) return out;
  bool started = false;  // after the first up-crossing
  double highest = -std::numeric_limits<double>::infinity();
  double prev = turning_.front();
  auto visit = [&](double next) {
    if (prev < mean_ && mean_ <= next) {
      if (started) out.push_back(highest);
      started = true;
      highest = next;
    } else if (started) {
      highest = std::max(highest, next);
    }
    prev = next;
  };
  for (std::size_t i = 1; i < turning_.size(); ++i) visit(turning_[i]);
  visit(end_);
  return out;
}

std::vector<double> StatisticsAccumulator::block_maxima() const {
  return blocks_;
}

std::vector<double> StatisticsAccumulator::save() const {
  // header of 13 numbers, then the blocks, then the turning points
  std::vector<double> out = {static_cast<double>(n_),
                             mean_,
                             M2_,
                             M3_,
                             M4_,
                             min_,
                             max_,
                             t_first_,
                             t_last_,
                             static_cast<double>(direction_),
                             end_,
                             static_cast<double>(blocks_.size()),
                             block_length_};
  out.insert(out.end(), blocks_.begin(), blocks_.end());
  out.insert(out.end(), turning_.begin(), turning_.end());
  return out;
}

void StatisticsAccumulator::restore(const std::vector<double>& saved) {
  constexpr std::size_t kHeader = 13;
  if (saved.size() < kHeader) throw std::invalid_argument("statistics: a short saved state");
  // a damaged state must not become a huge or negative count (a cast of NaN or 1e300 to an
  // integer is undefined)
  if (saved[11] != static_cast<double>(blocks_.size()) || saved.size() < kHeader + blocks_.size())
    throw std::invalid_argument("statistics: the saved state has another number of blocks");
  const auto blocks = blocks_.size();
  if (!(saved[0] >= 0.0 && saved[0] <= 9e15 && saved[0] == std::floor(saved[0])))
    throw std::invalid_argument("statistics: the saved count is not a whole number");
  if (saved[9] != -1.0 && saved[9] != 0.0 && saved[9] != 1.0)
    throw std::invalid_argument("statistics: the saved direction is not -1, 0 or 1");
  n_ = static_cast<long>(saved[0]);
  mean_ = saved[1];
  M2_ = saved[2];
  M3_ = saved[3];
  M4_ = saved[4];
  min_ = saved[5];
  max_ = saved[6];
  t_first_ = saved[7];
  t_last_ = saved[8];
  direction_ = static_cast<int>(saved[9]);
  end_ = saved[10];
  block_length_ = saved[12];
  blocks_.assign(saved.begin() + kHeader, saved.begin() + static_cast<long>(kHeader + blocks));
  turning_.assign(saved.begin() + static_cast<long>(kHeader + blocks), saved.end());
}

}  // namespace seaflex::post
