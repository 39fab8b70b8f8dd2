#pragma once
// Shared scenes and closed forms of the modal-equilibrium tests.
#include <cmath>

#include "rbcstab/analysis/steady_states.hpp"
#include "rbcstab/continuation/continuation_parameter.hpp"
#include "rbcstab/model/coefficients.hpp"
#include "rbcstab/model/scene.hpp"

namespace rbcstab::modal_fixtures {

// lambda = 1, B = 1, Delta = 1, Delta0 = 0.01 (the paper's Fig. 6 family): the ellipsoidal state is
// stable at C = 0.08 and unstable to l = 3 (then l = 4) as C decreases (alpha = B/C grows).
inline Scene scene(double C = 0.08, int L = 6) {
  Scene s;
  s.beta = 0;
  s.parameters.lambda = 1;
  s.parameters.B = 1;
  s.parameters.Delta = 1;
  s.parameters.Delta0 = 0.01;
  s.parameters.C = C;
  s.L = L;
  return s;
}

// Exact post-instability state with surviving mode l at parameters q: sigma = sigma_l^c, the l = 2
// block from its linear equations (z = 1/(Lambda (1 - i Y2)), w = -kappa w0/Y2, v = 0), and
// Delta_l = Delta - Delta_2 (closed form, independent of the continuation).
struct PostState {
  double sigma, Delta2, Delta_l;
};
inline PostState exact_post_state(const Parameters& q, int l) {
  const double sigma = sigma_c(l, q.alpha());
  const double Y2 = Upsilon_l(q, 2, sigma);
  const double L = q.Lambda();
  const double z2 = 1 / (L * L * (1 + Y2 * Y2));
  const double w = -q.inv_Lambda_S() / Y2;
  const double Delta2 = q.Delta * (z2 + w * w);
  return {sigma, Delta2, q.Delta - Delta2};
}

// sigma at the exact ellipsoidal equilibrium minus sigma_l^c: the asymptotic criterion mu_l = 0
// of trace.hpp (analysis/steady_states closed form); its root in C by bisection to the last bit.
inline double threshold_margin(const Parameters& p, int l) {
  return out_of_plane_equilibrium(p).sigma_R - sigma_c(l, p.alpha());
}
inline double threshold_root(Parameters p, ContinuationParameter q, int l, double lo, double hi) {
  double glo = threshold_margin(with_parameter(p, q, lo), l);
  for (int it = 0; it < 200 && hi - lo > 1e-15 * std::abs(hi); ++it) {
    const double mid = 0.5 * (lo + hi);
    const double g = threshold_margin(with_parameter(p, q, mid), l);
    if ((g > 0) == (glo > 0))
      lo = mid, glo = g;
    else
      hi = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace rbcstab::modal_fixtures
