#pragma once
// Exact out-of-plane (r0 = 0) equilibrium of the reduced system for every S (derived in docs/theory.md),
// its linear stability on the sphere, sigma_R at it, and the exact finite-S instability criterion,
// beside the paper's S >> 1 forms (Eq. ss_red, Eq. ss_st_red).
#include <array>
#include <cmath>
#include <complex>
#include <string>
#include <vector>

#include "rbcstab/analysis/quantity.hpp"
#include "rbcstab/model/parameters.hpp"

namespace rbcstab {

struct OutOfPlaneEquilibrium {
  // Lambda^2 u^2 - (1 + Lambda^2 + S^-2) u + 1 = 0, u = r^2 in (0, 1]; cos Psi = Lambda r,
  // sqrt(1 - r^2) sin Psi = r / S, sin Psi >= 0.
  double r = 0, Psi = 0;
  double w = 0;                                     // sqrt(1 - r^2) (computed without cancellation)
  double mu = 0;                                    // Upsilon_2 at the equilibrium (the reduced model's multiplier)
  double sigma_R = 0;                               // Eq. st_red at the equilibrium
  std::array<std::complex<double>, 2> eigenvalues;  // of the reduced Jacobian on the sphere's tangent plane
  bool stable = false;                              // both eigenvalues have negative real part
  // False when the eigenvalues are not finite (inputs so extreme that the Jacobian overflows): `stable` then
  // says nothing and the outputs write "n/a" / null with the reason.
  bool stability_known() const {
    return std::isfinite(std::abs(eigenvalues[0])) && std::isfinite(std::abs(eigenvalues[1]));
  }
  double residual = 0;  // max |rhs| of ReducedModel at the equilibrium (an O(eps) check)
  // The paper's S >> 1 forms (Eq. ss_red): r_ss, Psi_ss, <sigma_R^-+> (Eq. ss_st_red).
  double r_large_S = 0, Psi_large_S = 0;
  Quantity sigma_R_large_S;
};

OutOfPlaneEquilibrium out_of_plane_equilibrium(const Parameters& p);

// Which integer l in [3, L] are unstable at the exact equilibrium (sigma_R < sigma_l^c) and with the S >> 1
// <sigma_R> of Eq. ss_st_red.
struct OutOfPlaneCriterion {
  OutOfPlaneEquilibrium equilibrium;
  std::vector<int> unstable_exact, unstable_large_S;
};
OutOfPlaneCriterion out_of_plane_criterion(const Parameters& p, int L);

// Exact finite-S critical capillary numbers at fixed B: the roots in C of sigma_R^eq(C) = sigma_*(B/C) on
// [C_min, C_max], bracketed on a log grid of n points and refined by bisection to relative 1e-13.
std::vector<double> exact_C_star(const Parameters& p, double C_min, double C_max, int n = 400);

}  // namespace rbcstab
