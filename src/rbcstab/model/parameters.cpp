#include "rbcstab/model/parameters.hpp"

#include <cmath>
#include <numbers>

#include "rbcstab/core/constants.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/model/coefficients.hpp"
#include "rbcstab/model/parameter_table.hpp"

namespace rbcstab {

void Parameters::validate() const {
  Scene s;
  s.parameters = *this;
  validate_table(s, "parameters");
}

std::vector<std::string> Parameters::warnings() const {
  std::vector<std::string> w;
  if (Delta > 1)
    w.push_back("Delta = " + format_value(Delta) +
                " > 1 lies outside the perturbative regime (Delta << 1); results are the model's, not the cell's");
  return w;
}

double Parameters::Lambda() const { return std::sqrt(Delta) * d_lambda_l(lambda, 2) / (8 * std::sqrt(30 * kPi)); }

double Parameters::S() const {
  if (Delta0 == 0) return INFINITY;
  return C * std::sqrt(15 * kPi / (2 * Delta0));
}

double Parameters::inv_Lambda_S() const { return 16 * std::sqrt(Delta0 / Delta) / (d_lambda_l(lambda, 2) * C); }

}  // namespace rbcstab
