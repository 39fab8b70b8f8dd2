#pragma once
// The homogeneous membrane tension sigma: the Lagrange multiplier that keeps the excess area constant
// (Eq. st). Every level and every continuation problem gets sigma here, from its own sums.
//
// With Delta_l = a_l sum_m |f_{l,m}|^2 and Eq. eom, the area balance is
//   (1/2) dDelta/dt = sum_l Upsilon_l(sigma) Delta_l + W,   W = Re sum_{l,m} a_l S_{l,m} conj(f_{l,m}),
// affine in sigma because every Upsilon_l is (GrowthRate): N + sigma D with
//   N = sum_l Upsilon_l(0) Delta_l + W,   D = sum_l (dUpsilon_l/dsigma) Delta_l  (< 0 while Delta > 0),
// and dDelta/dt = 0 gives sigma = -N/D. Times B/B this is Eq. st with the real part the paper omits:
//   sigma = -[sum_l (Gamma_1 + alpha Gamma_3) Delta_l + B W] / sum_l Gamma_2 Delta_l.
// A common positive factor of N and D (normalised coordinates) leaves sigma unchanged, and a level whose
// multiplier is a growth rate itself (the reduced model's mu = Upsilon_2: slope 1, zero 0) uses the same sums.
#include "rbcstab/model/coefficients.hpp"

namespace rbcstab {

struct AreaBalance {
  double N = 0;  // sum_l Upsilon_l(0) Delta_l + W
  double D = 0;  // sum_l (dUpsilon_l/dsigma) Delta_l

  void add_mode(const GrowthRate& Upsilon, double Delta_l) {
    N += Upsilon(0.0) * Delta_l;
    D += Upsilon.slope * Delta_l;
  }
  void add_work(double W) { N += W; }
  // Eq. st: the zero of N + sigma D.
  double sigma() const { return -N / D; }
  // The first-order change of sigma when the sums change by dN and dD (a gradient or a time or parameter
  // derivative): d(-N/D) = -(dN + sigma dD)/D.
  double sigma_change(double dN, double dD) const { return -(dN + sigma() * dD) / D; }
};

}  // namespace rbcstab
