#include "rbcstab/core/error.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>

namespace rbcstab {

InvalidArgument::InvalidArgument(std::string parameter, const std::string& message)
    : std::invalid_argument(message), parameter_(std::move(parameter)) {}

std::string format_value(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char buf[64];
  auto res = std::to_chars(buf, buf + sizeof buf, value);
  return std::string(buf, res.ptr);
}

std::string format_bytes(double bytes) {
  char buf[64];
  if (bytes < 1e6)
    std::snprintf(buf, sizeof buf, "%.3g bytes", bytes);
  else
    std::snprintf(buf, sizeof buf, "%.3g %s", bytes < 1e9 ? bytes / 1e6 : bytes / 1e9, bytes < 1e9 ? "MB" : "GB");
  return buf;
}

void require(bool ok, std::string_view parameter, double value, std::string_view range) {
  if (ok) return;
  throw InvalidArgument(std::string(parameter), std::string(parameter) + " = " + format_value(value) +
                                                    " is out of range: must be " + std::string(range));
}

void require_finite(std::string_view parameter, double value) {
  require(std::isfinite(value), parameter, value, "a finite number");
}

}  // namespace rbcstab
