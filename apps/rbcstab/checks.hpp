#pragma once
// Range checks for numeric flags whose messages read like the library's ("--step: -1 must be > 0").
// (CLI11's PositiveNumber prints its bound as the 300-digit DBL_MAX.)
#include <CLI/CLI.hpp>
#include <cmath>
#include <string>

namespace rbcstab::cli {

// Finite numbers above `bound` (strict) or at least `bound`.
inline CLI::Validator number_above(double bound, bool strict) {
  const std::string range = (strict ? "> " : ">= ") + CLI::detail::to_string(bound);
  return CLI::Validator(
      [bound, strict, range](std::string& text) -> std::string {
        double v = 0;
        std::size_t pos = 0;
        try {
          v = std::stod(text, &pos);
        } catch (const std::exception&) {
          pos = 0;
        }
        if (pos == 0 || pos != text.size()) return text + " is not a number (must be " + range + ")";
        if (!std::isfinite(v) || (strict ? !(v > bound) : !(v >= bound)))
          return text + " is out of range: must be finite and " + range;
        return {};
      },
      range, "RANGE");
}
inline CLI::Validator positive() { return number_above(0, true); }
inline CLI::Validator non_negative() { return number_above(0, false); }

}  // namespace rbcstab::cli
