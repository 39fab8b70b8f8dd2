#pragma once
// Small helpers for the integration tests.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "rbcstab/integrate/simulation.hpp"

namespace rbcstab::testing {

inline SimulationResult run(Scene s, ModelLevel level, double rtol, Stepper stepper = Stepper::rk8pd,
                            double atol = -1) {
  s.model = level;
  SimulationOptions o;
  o.integrator.stepper = stepper;
  o.integrator.rtol = rtol;
  // Absolute tolerance well below rtol * Delta so the relative control governs the O(Delta) components.
  o.integrator.atol = atol >= 0 ? atol : rtol * 1e-4;
  return simulate(s, o);
}

struct Deviation {
  double Delta = 0, sigma = 0, r = 0, Psi = 0;
};

// Largest differences over the common output grid: Delta_l (absolute, all l), sigma, r, Psi (mod 2 pi).
inline Deviation max_deviation(const SimulationResult& a, const SimulationResult& b) {
  Deviation d;
  const std::size_t n = std::min(a.trajectory.t.size(), b.trajectory.t.size());
  for (std::size_t k = 0; k < n; ++k) {
    for (std::size_t j = 0; j < a.trajectory.Delta_l[k].size(); ++j)
      d.Delta = std::max(d.Delta, std::abs(a.trajectory.Delta_l[k][j] - b.trajectory.Delta_l[k][j]));
    d.sigma = std::max(d.sigma, std::abs(a.trajectory.sigma[k] - b.trajectory.sigma[k]));
    d.r = std::max(d.r, std::abs(a.trajectory.r[k] - b.trajectory.r[k]));
    if (a.trajectory.r[k] > 1e-6 && b.trajectory.r[k] > 1e-6)
      d.Psi =
          std::max(d.Psi, std::abs(std::remainder(a.trajectory.Psi[k] - b.trajectory.Psi[k], 2 * std::numbers::pi)));
  }
  return d;
}

inline bool all_finite(const SimulationResult& r) {
  auto fin = [](const std::vector<double>& v) {
    return std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); });
  };
  bool ok = fin(r.Delta_final) && fin(r.Delta_tail_mean) && fin(r.Delta_initial) && fin(r.y_final) &&
            std::isfinite(r.sigma_final) && std::isfinite(r.sigma_tail_mean) && std::isfinite(r.r_final) &&
            std::isfinite(r.Psi_final) && std::isfinite(r.excess_area_drift);
  for (std::size_t k = 0; k < r.trajectory.t.size(); ++k)
    ok = ok && fin(r.trajectory.Delta_l[k]) && std::isfinite(r.trajectory.sigma[k]) &&
         std::isfinite(r.trajectory.r[k]) && std::isfinite(r.trajectory.Psi[k]);
  return ok;
}

}  // namespace rbcstab::testing
