#pragma once
// The integral of g(t, y(t)) over one forcing period [0, 2 pi] along the trajectory of a System through
// y0 at t = 0: the periodic trapezoid rule on n uniform samples, spectrally accurate for a smooth periodic
// integrand (512 samples: ~1e-12 on the in-plane orbits), the trajectory integrated at rtol 1e-13. An
// oracle independent of the shooting code (its own integration, no variational equations).
#include <cmath>
#include <span>
#include <vector>

#include "rbcstab/integrate/integrator.hpp"
#include "rbcstab/model/system.hpp"

namespace rbcstab::test {

template <class G>
double period_integral(const System& system, std::span<const double> y0, const G& g, int n = 512) {
  const double two_pi = 2 * M_PI;
  std::vector<double> grid;
  for (int k = 1; k <= n; ++k) grid.push_back(two_pi * k / n);
  IntegratorOptions o;
  o.rtol = 1e-13;
  o.atol = 1e-14;
  double sum = 0;
  integrate(system, y0, 0.0, grid, o, [&](double t, std::span<const double> y) { sum += g(t, y); });
  return sum * two_pi / n;
}

}  // namespace rbcstab::test
