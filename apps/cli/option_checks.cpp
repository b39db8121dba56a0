#include "option_checks.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <optional>
#include <thread>

namespace seaflex::cli {

namespace {

// the whole text as a long; nullopt for anything else ("nan", "1.5", "", "12abc")
std::optional<long> parse_long(const std::string& text) {
  long value = 0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (ec != std::errc() || ptr != end) return std::nullopt;
  return value;
}

}  // namespace

int hardware_threads() {
  const unsigned n = std::thread::hardware_concurrency();
  return n > 0 ? static_cast<int>(n) : 1;
}

CLI::Validator thread_count() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        const int hw = hardware_threads();
        const auto n = parse_long(text);
        if (!n || *n < 1)
          return fmt::format(
              "must be a whole number from 1 to {} (the hardware threads of this "
              "machine), got '{}'",
              hw, text);
        if (*n > hw)
          return fmt::format(
              "{} is more than the {} hardware thread{} of this machine "
              "(std::thread::hardware_concurrency); use at most {}",
              text, hw, hw == 1 ? "" : "s", hw);
        return {};
      },
      "1..hardware threads", "THREADS");
}

CLI::Validator whole_number(long max) {
  return CLI::Validator(
      [max](std::string& text) -> std::string {
        const auto n = parse_long(text);
        if (!n || *n < 1 || *n > max)
          return fmt::format("must be a whole number from 1 to {}, got '{}'", max, text);
        return {};
      },
      fmt::format("1..{}", max), "WHOLE");
}

CLI::Validator finite_positive(double max, const std::string& unit) {
  return CLI::Validator(
      [max, unit](std::string& text) -> std::string {
        // strtod reads "nan", "inf" and hex floats; the whole text must be the number
        const char* begin = text.c_str();
        char* end = nullptr;
        const double x = std::strtod(begin, &end);
        if (text.empty() || end != begin + text.size())
          return fmt::format("expected a number in {}, got '{}'", unit, text);
        if (!std::isfinite(x))
          return fmt::format("must be a finite number in {}, got '{}'", unit, text);
        if (!(x > 0.0) || x > max)
          return fmt::format("must be above 0 and at most {:g} {}, got {:g} {}", max, unit, x,
                             unit);
        return {};
      },
      fmt::format("0 < x <= {:g}", max), "POSITIVE");
}

}  // namespace seaflex::cli
