#include "rbcstab/model/parameters.hpp"

#include <cmath>
#include <numbers>

#include "rbcstab/core/error.hpp"
#include "rbcstab/model/coefficients.hpp"

namespace rbcstab {

void Parameters::validate() const {
  require(std::isfinite(lambda) && lambda >= 0, "lambda", lambda, "finite and >= 0");
  require(std::isfinite(Delta) && Delta > 0 && Delta < 4 * std::numbers::pi, "Delta", Delta,
          "in (0, 4 pi)");
  require(std::isfinite(Delta0) && Delta0 >= 0 && Delta0 <= Delta, "Delta0", Delta0,
          "in [0, Delta] with Delta = " + format_value(Delta));
  require(std::isfinite(B) && B > 0, "B", B, "finite and > 0");
  require(!std::isnan(C) && C > 0, "C", C, "> 0 (inf allowed: the vesicle limit)");
}

std::vector<std::string> Parameters::warnings() const {
  std::vector<std::string> w;
  if (Delta > 1)
    w.push_back("Delta = " + format_value(Delta) +
                " > 1 lies outside the perturbative regime (Delta << 1); results are the model's, not the cell's");
  return w;
}

double Parameters::Lambda() const {
  return std::sqrt(Delta) * d_lambda_l(lambda, 2) / (8 * std::sqrt(30 * std::numbers::pi));
}

double Parameters::S() const {
  if (Delta0 == 0) return INFINITY;
  return C * std::sqrt(15 * std::numbers::pi / (2 * Delta0));
}

double Parameters::inv_Lambda_S() const { return 16 * std::sqrt(Delta0 / Delta) / (d_lambda_l(lambda, 2) * C); }

}  // namespace rbcstab
