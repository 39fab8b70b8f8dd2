#pragma once
// Errors at the library's edge. Invalid input is an exception naming the parameter, its value and
// the allowed range; numerical non-convergence is never an exception but a status in a result.
#include <stdexcept>
#include <string>
#include <string_view>

namespace rbcstab {

class InvalidArgument : public std::invalid_argument {
 public:
  InvalidArgument(std::string parameter, const std::string& message);
  const std::string& parameter() const noexcept { return parameter_; }

 private:
  std::string parameter_;
};

// Formats a value the way messages show it (shortest round-trip form, "inf", "nan").
std::string format_value(double value);
// Formats a memory size for messages, three significant digits: "870 bytes", "6.66 GB".
std::string format_bytes(double bytes);

// Throws InvalidArgument("parameter = value is out of range: must be <range>") unless ok.
void require(bool ok, std::string_view parameter, double value, std::string_view range);

// Throws unless value is finite.
void require_finite(std::string_view parameter, double value);

}  // namespace rbcstab
