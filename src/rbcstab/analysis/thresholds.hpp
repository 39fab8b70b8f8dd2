#pragma once
// Growth rates and instability thresholds of the paper (Sec. IV, Appendix D), each with its domain.
// Upsilon_l(sigma) and sigma_l^c live in model/coefficients.hpp and are reused here.
// Derivations and the printed-formula corrections: docs/theory.md, section "Analysis".
#include <vector>

#include "rbcstab/analysis/quantity.hpp"
#include "rbcstab/model/parameters.hpp"

namespace rbcstab {

// Continuous most dangerous mode l_* = (-1 + sqrt(1 + 8 sqrt(alpha)))/2 (Pi(l_*) = 2 sqrt(alpha)), alpha >= 0.
double l_star(double alpha);
// sigma_* = -4 sqrt(alpha) = sigma^c at l = l_* (Eq. inst and the text after it).
double sigma_star(double alpha);
// alpha at which l_* takes a given value: alpha = (Pi(l)/2)^2; l = 2.5 gives (35/8)^2.
double alpha_for_l_star(double l);
// The criterion l_* >= 2.5 <=> alpha >= (35/8)^2 (Sec. IV).
bool l_star_criterion(double alpha);

// Unstable band of continuous l at tension sigma: Pi^2 + sigma Pi + 4 alpha < 0 (Eq. inst).
struct UnstableBand {
  Quantity l_minus, l_plus;  // roots (outside_domain when sigma > sigma_*: no unstable l)
  Quantity l_c;              // the criterion's extremum l_c = (-1 + sqrt(1 - 2 sigma))/2, needs sigma < 0
};
UnstableBand unstable_band(double sigma, double alpha);

// Integer modes l in [3, L] with Upsilon_l(sigma) > 0, i.e. sigma < sigma_l^c, ascending.
std::vector<int> unstable_modes(double sigma, double alpha, int L);
// The integer mode in [3, L] with the largest sigma_l^c: the last one to stay unstable as sigma rises,
// hence the one that survives the instability (docs/theory.md, "Post-instability state"). Ties go to the lower l.
int surviving_mode(double alpha, int L);
// alpha at which the surviving mode changes from l to l + 1: sigma_l^c = sigma_{l+1}^c
// <=> alpha = Pi(l) Pi(l+1) / 4 (18 for 2 -> 3, 60 for 3 -> 4); l >= 2.
double alpha_mode_change(int l);

// sigma_R at the start, r, r0 -> 0 (or any equal orientation of f and g): -6 + (2 alpha/3)(sqrt(Delta0/Delta) - 1).
double sigma_R_initial(const Parameters& p);
// alpha_*^init = 9 / (1 - (Delta0/Delta)^(1/4))^2: sigma_R_initial = sigma_* (Sec. IV). Outside domain when
// Delta0 = Delta (sigma_R_initial > sigma_* for every alpha > 0 except the l_* < 2 range).
Quantity alpha_init(const Parameters& p);

// <sigma_R^-> (Eq. ss_st_red, Lambda < 1, S >> 1): -6 + (sqrt(30 pi)/3) sqrt((1 - Lambda^2)/Delta) B - 2 alpha/3.
Quantity mean_sigma_R_minus(const Parameters& p);
// <sigma_R^+> (Lambda > 1, S >> 1), corrected: -6 + (2 alpha/3)(sqrt(Delta0/Delta (1 - r0^2)) Lambda/sqrt(Lambda^2 - 1)
// - 1). The printed form drops the shear term B r sin Psi, which is O(alpha sqrt(Delta0)) because sin Psi = O(1/S)
// (docs/theory.md). Outside domain for Lambda <= 1. r0 enters through the Phi-average (w0 = sqrt(1 - r0^2)).
Quantity mean_sigma_R_plus(const Parameters& p, double r0);
// The printed <sigma_R^+> with (1 - Lambda^2)(1 - r0^2) under the root: negative for every Lambda > 1, r0 < 1.
Quantity mean_sigma_R_plus_printed(const Parameters& p, double r0);

// C_*^- = 2 B / (3 (sqrt 6 + sqrt(B A^-))^2), A^- = sqrt(30 pi (1 - Lambda^2)/Delta)/3 (Eq. c_crit, Lambda < 1).
// Unstable for C < C_*^- (p.C is ignored).
Quantity C_star_minus(const Parameters& p);
// C_*^+ = B (1 - sqrt(A^+))^2 / 9 with the corrected A^+ = sqrt(Delta0/Delta (1 - r0^2)) Lambda / sqrt(Lambda^2 - 1)
// (the coefficient of the corrected <sigma_R^+>). Lambda > 1; unstable for C < C_*^+; outside when sqrt(A^+) >= 1.
Quantity C_star_plus(const Parameters& p, double r0);
// The printed form, A^+ = sqrt(Delta0/Delta (1 - Lambda^2)/Lambda (r0^2 - 1)), kept to show the discrepancy.
Quantity C_star_plus_printed(const Parameters& p, double r0);
// lambda_*^- (Eq. ss_lambda_red; re-derived, the printed form is correct): <sigma_R^-> = sigma_* at fixed alpha,
// C, Delta; unstable for lambda > lambda_*^-. Outside domain when no lambda >= 0 with Lambda < 1 is stable.
Quantity lambda_star_minus(double alpha, double C, double Delta);

}  // namespace rbcstab
