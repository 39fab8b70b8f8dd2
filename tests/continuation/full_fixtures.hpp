#pragma once
// Shared by the full-equilibrium tests and benchmarks: the forced scene and the closed-form equilibrium
// with a constant (m = 0) drive.
//
// Closed form with an m = 0 forcing (beta = 0). At fixed sigma every (l, m) obeys
// f' = (i m/2 + Upsilon_l(sigma)) f + S_{l,m} alone (Eq. eom), with the constant drive
// S_{l,m} = C_{l,m} - Gamma3_l/C g_{l,m} (C_{l,m}: shear, only l = 2, m = +-2; g: the stress-free shape,
// only m = 0 at beta = 0). Its equilibrium is f_{l,m} = -S_{l,m} / (i m/2 + Upsilon_l(sigma)), and the
// area constraint becomes ONE equation for sigma:
//   Phi(sigma) = sum_{l,m} a_l |S_{l,m}|^2 / (m^2/4 + Upsilon_l(sigma)^2) = Delta.
// Upsilon_l = (Gamma2/B)(Pi_l + sigma + 4 alpha/Pi_l) with Gamma2 < 0: on sigma > max over forced m = 0
// modes of sigma_l^c every Upsilon_l is < 0 and falls with sigma, so Phi decreases from +inf to 0 there:
// exactly one root on that interval (solved by bisection), the branch connected to the stable
// ellipsoid (other roots, with some forced Upsilon_l > 0, lie below that sigma_l^c). That
// sigma is also what the tension formula (Eq. st) returns at this f (it is the unique sigma with
// Re <f, f'> = 0), so the state is an equilibrium of the full model.
#include <algorithm>
#include <cmath>
#include <complex>
#include <vector>

#include "continuation/modal_fixtures.hpp"
#include "rbcstab/continuation/full_equilibrium.hpp"
#include "rbcstab/model/coefficients.hpp"

namespace rbcstab::full_fixtures {

using cd = std::complex<double>;

// The modal tests' scene (lambda = 1, B = 1, Delta = 1, Delta0 = 0.01, beta = 0) with an optional
// stress-free l = 3 content and no perturbation of the current shape.
inline Scene forced_scene(double C, int L, double rest3) {
  Scene s = modal_fixtures::scene(C, L);
  s.delta = 0;
  if (rest3 > 0) s.rest_delta_l[3] = rest3;
  return s;
}

// ---- the closed form of the header comment, from the paper's definitions only ----
struct ClosedForm {
  double sigma = 0;
  std::vector<cd> f;  // f_{l,m}, ModeAmplitudes::index
  std::vector<double> Delta_l;
};

inline cd drive(const Scene& s, const Parameters& q, int l, int m) {
  // beta = 0: D^(l)_{m,0}(0) = delta_{m,0}, so g_{l,0} = -sqrt(Delta0/a2) (l = 2), +sqrt(Delta0_l/a_l).
  double g = 0;
  if (m == 0) g = l == 2 ? -std::sqrt(q.Delta0 / a_l(2)) : std::sqrt(s.rest_perturbation(l) / a_l(l));
  return shear_drive(q.lambda, l, m) - Gamma3(q.lambda, l) * q.inv_C() * g;
}

inline double area_at(const Scene& s, const Parameters& q, double sigma) {
  double A = 0;
  for (int l = 2; l <= s.L; ++l) {
    const double Y = Upsilon_l(q, l, sigma);
    for (int m = -l; m <= l; ++m) A += a_l(l) * std::norm(drive(s, q, l, m)) / (0.25 * m * m + Y * Y);
  }
  return A;
}

inline ClosedForm closed_form(const Scene& s, const Parameters& q) {
  double lo = -1e300;
  for (int l = 2; l <= s.L; ++l)
    if (std::abs(drive(s, q, l, 0)) > 0) lo = std::max(lo, sigma_c(l, q.alpha()));
  double hi = lo + 1;
  while (area_at(s, q, hi) > q.Delta) hi = lo + 2 * (hi - lo);
  for (int it = 0; it < 400; ++it) {
    const double mid = 0.5 * (lo + hi);
    if (mid == lo || mid == hi) break;
    (area_at(s, q, mid) > q.Delta ? lo : hi) = mid;
  }
  ClosedForm c;
  c.sigma = 0.5 * (lo + hi);
  c.f.resize(ModeAmplitudes::count(s.L));
  c.Delta_l.assign(static_cast<std::size_t>(s.L - 1), 0.0);
  for (int l = 2; l <= s.L; ++l)
    for (int m = -l; m <= l; ++m) {
      const cd f = -drive(s, q, l, m) / cd(Upsilon_l(q, l, c.sigma), 0.5 * m);
      c.f[ModeAmplitudes::index(l, m)] = f;
      c.Delta_l[static_cast<std::size_t>(l - 2)] += a_l(l) * std::norm(f);
    }
  return c;
}

// Largest |closed form - state| over the stored f_{l,m}.
inline double state_error(const FullEquilibriumProblem& pr, const Eigen::VectorXd& x, double p, const ClosedForm& c) {
  const std::vector<double> y = pr.to_full_state(x, p);
  double e = 0;
  for (std::size_t k = 0; k < c.f.size(); ++k) e = std::max(e, std::abs(cd(y[2 * k], y[2 * k + 1]) - c.f[k]));
  return e;
}

}  // namespace rbcstab::full_fixtures
