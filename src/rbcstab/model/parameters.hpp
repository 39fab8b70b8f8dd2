#pragma once
// Material, flow and shape parameters of the model (paper Sec. II, Eqs. dimless_nums, Lambda_S).
#include <string>
#include <vector>

namespace rbcstab {

struct Parameters {
  double lambda = 5.0;   // viscosity ratio eta_in/eta_ex, >= 0
  double Delta = 1.0;    // excess area of the current shape, 0 < Delta < 4 pi
  double Delta0 = 0.01;  // excess area of the stress-free shape, 0 <= Delta0 <= Delta (0: vesicle limit)
  double B = 2.0;        // bending number eta gamma R^3 / kappa, > 0
  double C = 0.04;       // capillary number eta gamma R / mu, > 0; +inf is the vesicle limit

  // Throws InvalidArgument naming the first parameter out of range.
  void validate() const;
  // Values accepted but outside the perturbative regime (e.g. Delta > 1).
  std::vector<std::string> warnings() const;

  double alpha() const { return B / C; }    // mu R^2 / kappa; 0 when C = inf
  double inv_C() const { return 1.0 / C; }  // 0 when C = inf
  // Lambda = sqrt(Delta) (23 lambda + 32) / (8 sqrt(30 pi))   (Eq. Lambda_S)
  double Lambda() const;
  // S = C sqrt(15 pi / (2 Delta0)); +inf when Delta0 = 0 or C = inf (Eq. Lambda_S)
  double S() const;
  // (Lambda S)^-1 = 16 sqrt(Delta0/Delta) / (d(lambda,2) C): the elastic coupling of the reduced
  // system, finite and 0 in both vesicle limits, so the reduced model never divides by S.
  double inv_Lambda_S() const;
};

}  // namespace rbcstab
