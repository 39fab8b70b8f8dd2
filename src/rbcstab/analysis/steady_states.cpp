#include "rbcstab/analysis/steady_states.hpp"

#include <algorithm>
#include <cmath>

#include "rbcstab/analysis/thresholds.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/model/reduced_model.hpp"
#include "rbcstab/model/scene.hpp"

namespace rbcstab {

namespace {
// The reduced model of the out-of-plane start (beta = 0: r = r0 = 0), used for sigma_from_mu, rhs and Jacobian.
ReducedModel out_of_plane_model(const Parameters& p) {
  Scene s;
  s.parameters = p;
  s.beta = 0;
  s.L = 2;
  return ReducedModel(p, initial_state(s));
}
}  // namespace

OutOfPlaneEquilibrium out_of_plane_equilibrium(const Parameters& p) {
  p.validate();
  const ReducedModel model = out_of_plane_model(p);
  OutOfPlaneEquilibrium eq;
  const double Lambda = p.Lambda();
  const double L2 = Lambda * Lambda;
  const double S = p.S();
  const double s = std::isinf(S) ? 0.0 : 1 / (S * S);  // S^-2
  // Stable root u = 2/(b + sqrt(D)) of Lambda^2 u^2 - b u + 1 = 0, b = 1 + Lambda^2 + s, with
  // D = b^2 - 4 Lambda^2 = e^2 + s (2 + 2 Lambda^2 + s), e = |1 - Lambda^2|. 1 - u and 1 - Lambda^2 u are
  // formed from t = sqrt(D) - e = s (2 + 2 Lambda^2 + s)/(sqrt(D) + e) so neither cancels as S -> inf.
  const double e = std::abs(1 - L2);
  const double q = s * (2 + 2 * L2 + s);
  const double sqrtD = std::sqrt(e * e + q);
  const double t = sqrtD + e > 0 ? q / (sqrtD + e) : 0.0;
  const double den = 1 + L2 + s + sqrtD;
  const double u = 2 / den;
  const double small = (s + t) / den, large = (2 * e + s + t) / den;
  const double one_minus_u = L2 <= 1 ? small : large;
  const double one_minus_L2u = L2 <= 1 ? large : small;
  eq.r = std::sqrt(u);
  eq.w = std::sqrt(one_minus_u);
  const double sinPsi = std::sqrt(one_minus_L2u), cosPsi = Lambda * eq.r;
  eq.Psi = std::atan2(sinPsi, cosPsi);
  // mu = Im(z)/Lambda - kappa w with z = r e^{-i Psi} (ReducedModel::mu with z0 = 0, w0 = 1); regular at S = inf.
  eq.mu = -eq.r * sinPsi / Lambda - p.inv_Lambda_S() * eq.w;
  eq.sigma_R = model.sigma_from_mu(eq.mu);

  const std::vector<double> y = {eq.r * cosPsi, -eq.r * sinPsi, eq.w};
  std::vector<double> f(3), dfdt(3);
  model.rhs(0, y, f);
  eq.residual = std::max({std::abs(f[0]), std::abs(f[1]), std::abs(f[2])});

  // Every sphere |y| = const is invariant (y . F = 0), so y^T J = 0 at the equilibrium and J maps the tangent
  // plane into itself: its two eigenvalues there are those of E^T J E with E an orthonormal tangent basis.
  StructuredJacobian J;
  model.jacobian(0, y, J, dfdt);
  std::vector<double> Jd(9);
  J.to_dense(Jd);
  const double n[3] = {y[0], y[1], y[2]};
  int k = 0;
  for (int i = 1; i < 3; ++i)
    if (std::abs(n[i]) < std::abs(n[k])) k = i;
  double e1[3] = {0, 0, 0};
  e1[k] = 1;
  const double dot = n[k];
  for (int i = 0; i < 3; ++i) e1[i] -= dot * n[i];
  const double norm1 = std::sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
  for (double& c : e1) c /= norm1;
  const double e2[3] = {n[1] * e1[2] - n[2] * e1[1], n[2] * e1[0] - n[0] * e1[2], n[0] * e1[1] - n[1] * e1[0]};
  const double* E[2] = {e1, e2};
  double T[2][2];
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b) {
      double acc = 0;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) acc += E[a][i] * Jd[std::size_t(3 * i + j)] * E[b][j];
      T[a][b] = acc;
    }
  const double tr = T[0][0] + T[1][1], det = T[0][0] * T[1][1] - T[0][1] * T[1][0];
  const std::complex<double> root = std::sqrt(std::complex<double>(tr * tr / 4 - det, 0));
  eq.eigenvalues = {tr / 2 + root, tr / 2 - root};
  eq.stable = eq.eigenvalues[0].real() < 0 && eq.eigenvalues[1].real() < 0;

  if (Lambda <= 1) {
    eq.r_large_S = 1;
    eq.Psi_large_S = std::acos(Lambda);
    eq.sigma_R_large_S = mean_sigma_R_minus(p);
  } else {
    eq.r_large_S = 1 / Lambda;
    eq.Psi_large_S = 0;
    eq.sigma_R_large_S = mean_sigma_R_plus(p, 0);
  }
  return eq;
}

OutOfPlaneCriterion out_of_plane_criterion(const Parameters& p, int L) {
  require_L(L);
  OutOfPlaneCriterion c;
  c.equilibrium = out_of_plane_equilibrium(p);
  c.unstable_exact = unstable_modes(c.equilibrium.sigma_R, p.alpha(), L);
  if (c.equilibrium.sigma_R_large_S.valid())
    c.unstable_large_S = unstable_modes(c.equilibrium.sigma_R_large_S.value, p.alpha(), L);
  return c;
}

std::vector<double> exact_C_star(const Parameters& p, double C_min, double C_max, int n) {
  require(std::isfinite(C_min) && C_min > 0, "C_min", C_min, "finite and > 0");
  require(std::isfinite(C_max) && C_max > C_min, "C_max", C_max, "finite and > C_min");
  require(n >= 2, "n", n, "an integer >= 2");
  auto g = [&](double lnC) {
    Parameters q = p;
    q.C = std::exp(lnC);
    return out_of_plane_equilibrium(q).sigma_R - sigma_star(q.alpha());
  };
  std::vector<double> roots;
  const double a = std::log(C_min), b = std::log(C_max);
  double x0 = a, g0 = g(a);
  for (int i = 1; i < n; ++i) {
    const double x1 = a + (b - a) * i / (n - 1);
    const double g1 = g(x1);
    if (g0 == 0) {
      roots.push_back(std::exp(x0));
    } else if (g0 * g1 < 0) {
      double lo = x0, hi = x1, glo = g0;
      for (int it = 0; it < 200 && hi - lo > 1e-13 * std::max(1.0, std::abs(lo)); ++it) {
        const double mid = 0.5 * (lo + hi);
        const double gm = g(mid);
        if ((gm < 0) == (glo < 0)) {
          lo = mid;
          glo = gm;
        } else {
          hi = mid;
        }
      }
      roots.push_back(std::exp(0.5 * (lo + hi)));
    }
    x0 = x1;
    g0 = g1;
  }
  return roots;
}

}  // namespace rbcstab
