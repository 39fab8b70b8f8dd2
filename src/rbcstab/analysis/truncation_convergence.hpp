#pragma once
// The truncation study (`rbcstab bench truncation`): how Delta_l(T), sigma(T) and l_Delta converge with the
// truncation L. The scene runs to T at each L of a list, at tight tolerances, and each run is compared with the
// run at the last L (the reference). The modal level is exact at every L, so the differences are truncation alone.
#include <string>
#include <vector>

#include "rbcstab/core/progress.hpp"
#include "rbcstab/integrate/simulation.hpp"
#include "rbcstab/model/scene.hpp"

namespace rbcstab {

struct TruncationConvergenceOptions {
  std::vector<int> Ls{4, 6, 8, 10, 12, 16, 20, 24, 30, 40};  // each in [kMinL, kMaxL]; the last is the reference
  ProgressCallback on_progress;                              // runs done of Ls.size()
  void validate() const;                                     // throws InvalidArgument naming the field ("Ls")
};

struct TruncationConvergenceRow {
  int L = 0;
  IntegrationStatus status = IntegrationStatus::success;
  std::string reason;  // the run's message when status is not success
  int l_Delta = 2;
  double sigma_final = 0;
  // max_l |Delta_l(T) - reference| / Delta, the modes beyond L counted at the reference's value; NaN when the
  // reference stopped (an error against it would measure nothing).
  double error_Delta = 0;
  double error_sigma = 0;  // |sigma(T) - reference| / max(1, |reference|); NaN when the reference stopped
  std::size_t rhs_evaluations = 0;
  double seconds = 0;
};

struct TruncationConvergence {
  std::vector<TruncationConvergenceRow> rows;  // one per L of the options, in their order: the last is the reference
  const TruncationConvergenceRow& reference() const { return rows.back(); }
  bool reference_ok() const { return reference().status == IntegrationStatus::success; }
};

// Every run simulates scene at one L with options' integrator, its tolerances capped at rtol 1e-10 and atol 1e-14,
// sampled at T only (the final state is compared). A run that stops is a row's status, not an exception.
TruncationConvergence truncation_convergence(const Scene& scene, const SimulationOptions& options,
                                             const TruncationConvergenceOptions& study = {});

}  // namespace rbcstab
