#include "rbcstab/analysis/post_instability.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "rbcstab/analysis/thresholds.hpp"
#include "rbcstab/core/constants.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/model/coefficients.hpp"
#include "rbcstab/model/scene.hpp"

namespace rbcstab {

Delta2Prediction post_instability_Delta2(const Parameters& p, double sigma_s, double r0) {
  p.validate();
  require_finite("sigma_s", sigma_s);
  require(std::isfinite(r0) && r0 >= 0 && r0 <= 1, "r0", r0, "in [0, 1]");
  Delta2Prediction d;
  d.sigma_s = sigma_s;
  const double d2 = d_lambda_l(p.lambda, 2);
  const double sqrt30pi = std::sqrt(30 * kPi);
  const double c_Lambda = d2 / (8 * sqrt30pi);  // Lambda~ = c_Lambda sqrt(Delta2)     (Eq. ssr)
  const double a2 = a_l(2);
  d.mu_tilde = Upsilon_l(p, 2, sigma_s);
  const double mu = d.mu_tilde;
  // Eq. rss_postinst: tan Psi~ = K = -mu~ and r~ = rho / sqrt(Delta2) with rho = 1/(c_Lambda sqrt(1 + mu~^2)).
  const double Psi = std::atan(-mu);
  const double rho = 1 / (c_Lambda * std::sqrt(1 + mu * mu));
  d.Psi_tilde = Quantity::of(Psi);
  if (!(mu < 0)) {
    d.Delta2_tilde = Quantity::outside("Upsilon_2(sigma_s) = " + format_value(mu) +
                                       " >= 0: the l = 2 mode is not damped at sigma_s, Eq. ss has no steady state");
    d.r_tilde = Quantity::outside(d.Delta2_tilde.reason);
    return d;
  }
  // Eq. ss: Delta2 mu~ = -a2 Re sum_m S_{2,m} conj(f~_{2,m}) with Eq. subs_ss and g's Phi-average:
  //   Re sum = A_f rho sin Psi~ + A_g w0 sqrt(Delta2 - rho^2),
  //   A_f = 4 sqrt(30 pi)/d2 (shear drive), A_g = -Gamma_3^2 sqrt(Delta0)/(2 C) (stress-free shape).
  const double A_f = 4 * sqrt30pi / d2;
  const double A_g = -Gamma3(p.lambda, 2) * p.inv_C() * std::sqrt(p.Delta0) / 2;
  const double w0 = std::sqrt(std::max(0.0, 1 - r0 * r0));
  d.c = rho * rho;
  d.K1 = -a2 * A_f * rho * std::sin(Psi) / mu;
  d.K2 = -a2 * A_g * w0 / mu;
  // Squared: D^2 - (2 K1 + K2^2) D + K1^2 + K2^2 c = 0, discriminant K2^2 (K2^2 + 4 (K1 - c)).
  const double Bq = 2 * d.K1 + d.K2 * d.K2;
  const double Cq = d.K1 * d.K1 + d.K2 * d.K2 * d.c;
  const double disc = d.K2 * d.K2 * (d.K2 * d.K2 + 4 * (d.K1 - d.c));
  const double root = std::sqrt(std::max(0.0, disc));
  const double hi = 0.5 * (Bq + root);
  const double lo = hi > 0 ? Cq / hi : 0.5 * (Bq - root);
  d.roots = {std::min(lo, hi), std::max(lo, hi)};
  // Root selection: keep the roots that satisfy the unsquared equation (D >= c and the sign of the root term);
  // of those, the largest: it has w~ = sqrt(1 - r~^2) = -kappa~ w0/mu~ > 0, the balance of the f_{2,0} equation,
  // while the other (D = c, w~ = 0) violates it whenever Delta0 > 0 (the two coincide when K2 = 0).
  double chosen = -1;
  for (double D : d.roots) {
    if (D < d.c * (1 - 1e-12)) continue;
    const double res = D - d.K1 - d.K2 * std::sqrt(std::max(0.0, D - d.c));
    if (std::abs(res) <= 1e-9 * std::max(1.0, std::abs(D))) chosen = std::max(chosen, D);
  }
  if (chosen < 0) {
    d.Delta2_tilde = Quantity::outside("no root of the Delta~2 quadratic satisfies Eq. ss unsquared with Delta2 >= c");
    d.r_tilde = Quantity::outside(d.Delta2_tilde.reason);
    return d;
  }
  d.selection = "largest root satisfying the unsquared Eq. ss (w~ > 0, consistent with the f_{2,0} balance)";
  if (chosen >= p.Delta) {
    d.Delta2_tilde = Quantity::outside("Delta~2 = " + format_value(chosen) + " >= Delta = " + format_value(p.Delta) +
                                       ": no excess area left for the surviving mode, no post-instability state");
    d.r_tilde = Quantity::outside(d.Delta2_tilde.reason);
    return d;
  }
  d.Delta2_tilde = Quantity::of(chosen);
  d.r_tilde = Quantity::of(rho / std::sqrt(chosen));
  return d;
}

PostInstability post_instability(const Parameters& p, int L, double r0) {
  p.validate();
  require_L(L, 3, kMaxL, "a post-instability state needs a mode l >= 3");
  PostInstability out;
  const double alpha = p.alpha();
  out.surviving_mode = surviving_mode(alpha, L);
  out.continuous = post_instability_Delta2(p, sigma_star(alpha), r0);
  out.continuous.variant = "continuous";
  out.continuous.l = l_star(alpha);
  if (!l_star_criterion(alpha) && out.continuous.Delta2_tilde.valid()) {
    const std::string why = "l_* = " + format_value(out.continuous.l) +
                            " < 2.5 (alpha < (35/8)^2): no integer mode l >= 3 near l_*, the continuous variant "
                            "does not apply";
    out.continuous.Delta2_tilde = Quantity::outside(why);
    out.continuous.r_tilde = Quantity::outside(why);
  }
  out.integer_mode = post_instability_Delta2(p, sigma_c(out.surviving_mode, alpha), r0);
  out.integer_mode.variant = "integer";
  out.integer_mode.l = out.surviving_mode;
  return out;
}

}  // namespace rbcstab
