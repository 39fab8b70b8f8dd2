#include "rbcstab/report/detail/parameter_labels.hpp"

#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>

namespace rbcstab::detail {

std::string tex_value(SceneParameter q, double value) {
  std::ostringstream ss;
  ss << std::setprecision(4) << "$" << parameter_row(q).symbol << " = ";
  if (std::isinf(value)) {
    ss << (value < 0 ? "-" : "") << "\\infty";
  } else {
    std::ostringstream number;
    number << std::setprecision(4) << value;
    std::string text = number.str();
    // Scientific notation as mathematics: 1e-10 -> 10^{-10}, 2.5e+06 -> 2.5 \times 10^{6}.
    if (const auto e = text.find('e'); e != std::string::npos) {
      const std::string mantissa = text.substr(0, e);
      const int exponent = std::stoi(text.substr(e + 1));
      text = (mantissa == "1"    ? ""
              : mantissa == "-1" ? "-"
                                 : mantissa + " \\times ") +
             "10^{" + std::to_string(exponent) + "}";
    }
    ss << text;
  }
  ss << "$";
  return ss.str();
}

std::string plain_value(SceneParameter q, double value) {
  std::ostringstream ss;
  ss << std::setprecision(4) << parameter_row(q).name << " = " << value;
  return ss.str();
}

}  // namespace rbcstab::detail
