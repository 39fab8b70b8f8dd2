#include "rbcstab/core/error.hpp"

#include <charconv>
#include <cmath>

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

void require(bool ok, std::string_view parameter, double value, std::string_view range) {
  if (ok) return;
  throw InvalidArgument(std::string(parameter), std::string(parameter) + " = " + format_value(value) +
                                                    " is out of range: must be " + std::string(range));
}

void require_finite(std::string_view parameter, double value) {
  require(std::isfinite(value), parameter, value, "a finite number");
}

}  // namespace rbcstab
