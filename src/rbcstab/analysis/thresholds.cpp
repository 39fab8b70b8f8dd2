#include "rbcstab/analysis/thresholds.hpp"

#include <cmath>
#include <numbers>

#include "rbcstab/core/constants.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/model/coefficients.hpp"
#include "rbcstab/model/scene.hpp"

namespace rbcstab {

namespace {
// l from Pi = l(l+1), Pi >= 0.
double l_from_Pi(double Pi) { return 0.5 * (-1 + std::sqrt(1 + 4 * Pi)); }
void require_alpha(double alpha) { require(std::isfinite(alpha) && alpha >= 0, "alpha", alpha, "finite and >= 0"); }
}  // namespace

double l_star(double alpha) {
  require_alpha(alpha);
  return l_from_Pi(2 * std::sqrt(alpha));
}

double sigma_star(double alpha) {
  require_alpha(alpha);
  return alpha > 0 ? -4 * std::sqrt(alpha) : 0.0;  // +0, not -0, in the vesicle limit alpha = 0
}

double alpha_for_l_star(double l) {
  require(std::isfinite(l) && l >= 0, "l", l, "finite and >= 0");
  const double half_Pi = 0.5 * l * (l + 1);
  return half_Pi * half_Pi;
}

bool l_star_criterion(double alpha) { return l_star(alpha) >= 2.5; }

UnstableBand unstable_band(double sigma, double alpha) {
  require_alpha(alpha);
  require_finite("sigma", sigma);
  UnstableBand b;
  const double disc = sigma * sigma - 16 * alpha;
  if (sigma > 0 || disc < 0) {
    const std::string why = "sigma = " + format_value(sigma) + " > sigma_* = " + format_value(sigma_star(alpha)) +
                            ": Pi^2 + sigma Pi + 4 alpha > 0 for every l, no unstable band";
    b.l_minus = Quantity::outside(why);
    b.l_plus = Quantity::outside(why);
  } else {
    const double root = std::sqrt(disc);
    const double Pi_plus = 0.5 * (-sigma + root);
    // Pi_- Pi_+ = 4 alpha: no cancellation when alpha << sigma^2.
    const double Pi_minus = Pi_plus > 0 ? 4 * alpha / Pi_plus : 0.0;
    b.l_minus = Quantity::of(l_from_Pi(Pi_minus));
    b.l_plus = Quantity::of(l_from_Pi(Pi_plus));
  }
  if (sigma < 0)
    b.l_c = Quantity::of(l_from_Pi(-0.5 * sigma));
  else
    b.l_c = Quantity::outside("l_c needs sigma < 0 (Pi_c = -sigma/2 > 0)");
  return b;
}

std::vector<int> unstable_modes(double sigma, double alpha, int L) {
  require_alpha(alpha);
  std::vector<int> modes;
  for (int l = 3; l <= L; ++l)
    if (sigma < sigma_c(l, alpha)) modes.push_back(l);
  return modes;
}

int surviving_mode(double alpha, int L) {
  require_alpha(alpha);
  require_L(L, 3, kMaxL, "a surviving mode l >= 3");
  int best = 3;
  for (int l = 4; l <= L; ++l)
    if (sigma_c(l, alpha) > sigma_c(best, alpha)) best = l;
  return best;
}

double alpha_mode_change(int l) {
  require(l >= 2, "l", l, "an integer >= 2");
  return Pi_l(l) * Pi_l(l + 1) / 4;
}

double sigma_R_initial(const Parameters& p) {
  p.validate();
  return -6 + (2 * p.alpha() / 3) * (std::sqrt(p.Delta0 / p.Delta) - 1);
}

Quantity alpha_init(const Parameters& p) {
  p.validate();
  const double q = std::sqrt(std::sqrt(p.Delta0 / p.Delta));
  if (q >= 1)
    return Quantity::outside(
        "Delta0 = Delta: sigma_R(0) = -6 never reaches sigma_* = -4 sqrt(alpha) for alpha > 9/4, "
        "alpha_*^init is infinite");
  return Quantity::of(9 / ((1 - q) * (1 - q)));
}

Quantity mean_sigma_R_minus(const Parameters& p) {
  p.validate();
  const double Lambda = p.Lambda();
  if (Lambda > 1) return Quantity::outside("Lambda = " + format_value(Lambda) + " > 1: <sigma_R^-> needs Lambda <= 1");
  const double value =
      -6 + std::sqrt(30 * kPi) / 3 * std::sqrt((1 - Lambda * Lambda) / p.Delta) * p.B - 2 * p.alpha() / 3;
  return Quantity::of(value);
}

namespace {
// Corrected Lambda > 1 coefficient a = sqrt(Delta0/Delta) w0 / w_ss with w_ss = sqrt(Lambda^2 - 1)/Lambda:
// at an equilibrium the f_{2,0} balance gives mu = -kappa w0/w exactly, hence
// sigma_R = -6 + (2 alpha/3)(sqrt(Delta0/Delta) w0/w - 1) (docs/theory.md). The paper sets Psi = 0 and drops
// the shear term B r sin Psi, but sin Psi = r/(S w) and B/S = alpha sqrt(2 Delta0/(15 pi)): the dropped term
// is as large as the elastic one.
Quantity plus_coefficient(const Parameters& p, double r0) {
  p.validate();
  require(std::isfinite(r0) && r0 >= 0 && r0 <= 1, "r0", r0, "in [0, 1]");
  const double Lambda = p.Lambda();
  if (Lambda <= 1)
    return Quantity::outside("Lambda = " + format_value(Lambda) + " <= 1: the Lambda > 1 forms need Lambda > 1");
  return Quantity::of(std::sqrt(p.Delta0 / p.Delta * (1 - r0 * r0)) * Lambda / std::sqrt(Lambda * Lambda - 1));
}

Quantity mean_sigma_R_plus_impl(const Parameters& p, double r0, bool printed) {
  const Quantity a = plus_coefficient(p, r0);
  if (!a.valid()) return a;
  const double Lambda = p.Lambda(), L2 = Lambda * Lambda;
  if (printed) {
    const double radicand = p.Delta0 / p.Delta * (1 - L2) * (1 - r0 * r0) / L2;
    if (radicand < 0)
      return Quantity::outside("printed <sigma_R^+>: (1 - Lambda^2)(1 - r0^2) = " +
                               format_value((1 - L2) * (1 - r0 * r0)) + " < 0 under the square root");
    return Quantity::of(-6 + (2 * p.alpha() / 3) * (std::sqrt(radicand) - 1));
  }
  return Quantity::of(-6 + (2 * p.alpha() / 3) * (a.value - 1));
}

Quantity C_star_plus_impl(const Parameters& p, double r0, bool printed) {
  const Quantity a = plus_coefficient(p, r0);
  if (!a.valid()) return a;
  const double Lambda = p.Lambda(), L2 = Lambda * Lambda;
  // printed: A^+ = sqrt(Delta0/Delta (1 - Lambda^2)/Lambda (r0^2 - 1)); corrected: A^+ = a.
  const double A = printed ? std::sqrt(p.Delta0 / p.Delta * (L2 - 1) * (1 - r0 * r0) / Lambda) : a.value;
  const double s = std::sqrt(A);
  if (s >= 1)
    return Quantity::outside("sqrt(A^+) = " + format_value(s) +
                             " >= 1: <sigma_R^+> > sigma_* for every C (never unstable at the steady state)");
  return Quantity::of(p.B * (1 - s) * (1 - s) / 9);
}
}  // namespace

Quantity mean_sigma_R_plus(const Parameters& p, double r0) { return mean_sigma_R_plus_impl(p, r0, false); }
Quantity mean_sigma_R_plus_printed(const Parameters& p, double r0) { return mean_sigma_R_plus_impl(p, r0, true); }
Quantity C_star_plus(const Parameters& p, double r0) { return C_star_plus_impl(p, r0, false); }
Quantity C_star_plus_printed(const Parameters& p, double r0) { return C_star_plus_impl(p, r0, true); }

Quantity C_star_minus(const Parameters& p) {
  p.validate();
  const double Lambda = p.Lambda();
  if (Lambda > 1) return Quantity::outside("Lambda = " + format_value(Lambda) + " > 1: C_*^- needs Lambda <= 1");
  const double A = std::sqrt(30 * kPi * (1 - Lambda * Lambda) / p.Delta) / 3;
  const double d = std::sqrt(6.0) + std::sqrt(p.B * A);
  return Quantity::of(2 * p.B / (3 * d * d));
}

Quantity lambda_star_minus(double alpha, double C, double Delta) {
  require(std::isfinite(alpha) && alpha > 0, "alpha", alpha, "finite and > 0");
  require(std::isfinite(C) && C > 0, "C", C, "finite and > 0");
  require(std::isfinite(Delta) && Delta > 0, "Delta", Delta, "finite and > 0");
  const double q = std::sqrt(alpha) - 3;
  const double radicand = 30 * kPi * C * C * alpha * alpha / Delta - 4 * q * q * q * q;
  if (radicand < 0)
    return Quantity::outside(
        "<sigma_R^-> < sigma_* for every Lambda in [0, 1): every lambda with Lambda < 1 is "
        "unstable (radicand " +
        format_value(radicand) + " < 0)");
  const double value = 8.0 / 23.0 * (std::sqrt(radicand) / (C * alpha) - 4);
  if (value < 0)
    return Quantity::outside("lambda_*^- = " + format_value(value) +
                             " < 0: every lambda >= 0 with Lambda < 1 is unstable");
  return Quantity::of(value);
}

}  // namespace rbcstab
