#pragma once
// Work-precision of a scene: every (level, stepper, rtol) against a reference computed to ~1e-13 by a
// different method (the other exact level, rk8pd at rtol 1e-13). Error against cost, not time alone.
#include <string>
#include <vector>

#include "rbcstab/core/progress.hpp"
#include "rbcstab/integrate/simulation.hpp"

namespace rbcstab {

struct WorkPrecisionOptions {
  std::vector<ModelLevel> levels{ModelLevel::modal, ModelLevel::full};  // exact levels to compare
  std::vector<Stepper> steppers{Stepper::rk8pd, Stepper::rkck, Stepper::rosenbrock, Stepper::msbdf};
  std::vector<double> rtols{1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12};
  double atol_ratio = 1e-4;  // atol = atol_ratio * rtol: the relative test dominates for O(1) states
  double max_seconds = 30;   // per run: an expensive combination ends as time_limit, not a stall
  double reference_rtol = 1e-13;
  ProgressCallback on_progress;  // runs done of all (the two references, then every row)
  void validate() const;
};

struct WorkPrecisionRow {
  ModelLevel level = ModelLevel::automatic;
  Stepper stepper = Stepper::rk8pd;
  double rtol = 0;
  IntegrationStatus status = IntegrationStatus::success;
  std::size_t rhs_evaluations = 0, jacobian_evaluations = 0, steps = 0;
  double seconds = 0;
  double error_Delta = 0;  // max over l with Delta_l(T) > 1e-8 Delta of |Delta_l(T) - ref| / ref
  double error_sigma = 0;  // |sigma(T) - ref| / max(1, |ref|)
  int l_Delta = 2;
  bool verdict_changed =
      false;           // l_Delta differs from the reference's (runs that reached T only: a stopped run has no verdict)
  std::string reason;  // the integrator's message when status is not success
};

struct WorkPrecisionTable {
  std::string scene_name;
  std::vector<double> reference_Delta;  // Delta_l(T), l = 2..L
  double reference_sigma = 0;
  int reference_l_Delta = 2;
  ModelLevel reference_level = ModelLevel::full;
  double reference_rtol = 1e-13;  // the references' tolerance (WorkPrecisionOptions::reference_rtol)
  double reference_spread = 0;    // max relative difference of the two references (full vs modal)
  // Not success: the reference run stopped (reference_reason says why) and the table has no rows.
  IntegrationStatus reference_status = IntegrationStatus::success;
  std::string reference_reason;
  std::vector<WorkPrecisionRow> rows;
};

// The scene must be one where two levels are exact (its stress-free shape ellipsoidal). A reference run that
// fails is a status (reference_status), not an exception: the input was valid.
WorkPrecisionTable work_precision(const Scene& scene, const WorkPrecisionOptions& options = {});

}  // namespace rbcstab
