#include "rbcstab/report/detail/parameter_labels.hpp"

#include <cmath>
#include <iomanip>
#include <sstream>

namespace rbcstab::detail {

std::string tex_value(SceneParameter q, double value) {
  std::ostringstream ss;
  ss << std::setprecision(4) << "$" << parameter_row(q).symbol << " = ";
  if (std::isinf(value))
    ss << (value < 0 ? "-" : "") << "\\infty";
  else
    ss << value;
  ss << "$";
  return ss.str();
}

std::string plain_value(SceneParameter q, double value) {
  std::ostringstream ss;
  ss << std::setprecision(4) << parameter_row(q).name << " = " << value;
  return ss.str();
}

}  // namespace rbcstab::detail
