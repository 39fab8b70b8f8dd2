#include "rbcstab/analysis/truncation_convergence.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "rbcstab/core/error.hpp"

namespace rbcstab {

void TruncationConvergenceOptions::validate() const {
  if (Ls.empty()) throw InvalidArgument("Ls", "Ls is empty: must list at least one L (the last is the reference)");
  for (int L : Ls) require_L(L, kMinL, kMaxL, {}, "Ls");
}

TruncationConvergence truncation_convergence(const Scene& scene, const SimulationOptions& options,
                                             const TruncationConvergenceOptions& study) {
  study.validate();
  std::vector<SimulationResult> runs;
  for (int L : study.Ls) {
    Scene s = scene;
    s.L = L;
    s.dt = s.T;
    SimulationOptions so = options;
    so.integrator.rtol = std::min(so.integrator.rtol, 1e-10);
    so.integrator.atol = std::min(so.integrator.atol, 1e-14);
    so.record_trajectory = false;
    runs.push_back(simulate(s, so));
    if (study.on_progress) study.on_progress(double(runs.size()), double(study.Ls.size()));
  }
  const SimulationResult& ref = runs.back();
  const bool reference_ok = ref.status == IntegrationStatus::success;
  TruncationConvergence out;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const SimulationResult& r = runs[i];
    // A mode one of the two runs does not hold counts at the other's value (an unsorted list may put a smaller L
    // last).
    double e = 0;
    for (std::size_t k = 0; k < std::max(r.Delta_final.size(), ref.Delta_final.size()); ++k) {
      const double a = k < r.Delta_final.size() ? r.Delta_final[k] : 0;
      const double b = k < ref.Delta_final.size() ? ref.Delta_final[k] : 0;
      e = std::max(e, std::abs(a - b));
    }
    e /= scene.parameters.Delta;
    double es = std::abs(r.sigma_final - ref.sigma_final) / std::max(1.0, std::abs(ref.sigma_final));
    if (!reference_ok) e = es = std::numeric_limits<double>::quiet_NaN();
    out.rows.push_back(
        {study.Ls[i], r.status, r.reason, r.l_Delta, r.sigma_final, e, es, r.counters.rhs_evaluations, r.seconds});
  }
  return out;
}

}  // namespace rbcstab
