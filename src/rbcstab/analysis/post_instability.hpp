#pragma once
// Post-instability state (paper Sec. V; docs/theory.md): after the instability the l = 2 mode and
// one surviving mode l_s hold the excess area and sigma -> sigma_s with Upsilon_{l_s}(sigma_s) = 0.
// Delta~2 follows from dDelta_2/dt = 0 (Eq. ss, re-derived in docs/theory.md) with the l = 2 shape of
// Eq. subs_ss and r~, Psi~ of Eq. rss_postinst. Two variants: the paper's continuous l_* with sigma_* = -4 sqrt(alpha),
// and the integer surviving mode (largest sigma_l^c) with its sigma_l^c.
#include <array>
#include <string>

#include "rbcstab/analysis/quantity.hpp"
#include "rbcstab/model/parameters.hpp"

namespace rbcstab {

struct Delta2Prediction {
  std::string variant;            // "continuous" (l_*, sigma_*) or "integer" (l_s, sigma_{l_s}^c)
  double l = 0;                   // l_* or l_s
  double sigma_s = 0;             // the saturated tension
  double mu_tilde = 0;            // Upsilon_2(sigma_s) <= 0: the l = 2 decay rate at saturation
  Quantity Delta2_tilde;          // the selected root
  Quantity r_tilde, Psi_tilde;    // Eq. rss_postinst at the selected Delta2 (Psi~ = arctan(-mu~) needs no Delta2)
  double K1 = 0, K2 = 0, c = 0;   // Eq. ss with Eq. subs_ss: Delta2 = K1 + K2 sqrt(Delta2 - c)
  std::array<double, 2> roots{};  // of the squared quadratic (Delta2 - K1)^2 = K2^2 (Delta2 - c), ascending
  std::string selection;          // which root was kept and why
};

// Delta~2 at saturated tension sigma_s for a stress-free shape with w0 = sqrt(1 - r0^2) (r0 = 0 out of plane;
// an in-plane g is used through its Phi-average, which drops the rotating g_{2,+-2} term).
Delta2Prediction post_instability_Delta2(const Parameters& p, double sigma_s, double r0 = 0);

struct PostInstability {
  int surviving_mode = 3;
  Delta2Prediction continuous, integer_mode;
};
PostInstability post_instability(const Parameters& p, int L, double r0 = 0);

}  // namespace rbcstab
