// A sink for output rows: one value per channel at each output time.
#pragma once

#include <span>
#include <string>
#include <vector>

namespace seaflex {

class Recorder {
 public:
  virtual ~Recorder() = default;
  /// Called once with the channel names, before the first row.
  virtual void begin(const std::vector<std::string>& channels) = 0;
  virtual void record(double t, std::span<const double> values) = 0;
  /// Makes every recorded row durable (called on failure and at the end).
  virtual void flush() = 0;
};

}  // namespace seaflex
