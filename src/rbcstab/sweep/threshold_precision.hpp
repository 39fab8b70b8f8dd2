#pragma once
// Threshold precision against cost: the critical C at fixed B (the ln B - ln C plane of
// Fig. 4(b)) located by each predictor and each method, against that predictor's own converged boundary.
//  predictors: asymptotic (exact out-of-plane equilibrium, verdict/asymptotic.hpp asymptotic_verdict; its S >> 1
//              closed form C_*^+- is reported beside it), finite horizon (max_{l >= 3} G_l(T) > 0,
//              analysis/predictors.hpp), simulation (l_Delta >= 3 of a modal run to T);
//  methods:    root solve (bisection on the verdict, k halvings of the bracket), grid sampling (n points on
//              the bracket, boundary at the midpoint of the first cell where the verdict changes), and
//              continuation (sweep/trace.hpp trace_boundary on the strip ln B +- trace_half_width, the traced
//              curve interpolated linearly at ln B; asymptotic and finite horizon, whose criteria are smooth).
// References: the same predictor by bisection to bracket/2^reference_bisections at reference_rtol.
#include <string>
#include <vector>

#include "rbcstab/core/progress.hpp"
#include "rbcstab/model/scene.hpp"

namespace rbcstab {

struct ThresholdPrecisionOptions {
  double ln_C_lo = -5.5, ln_C_hi = 2.0;  // bracket in ln C (the Fig. 4(b) axis); the verdicts must differ at its ends
  std::vector<int> bisections{2, 4, 6, 8, 12, 16, 20, 24, 28, 32};  // root-solve budgets (halvings), each in [1, 60]
  std::vector<double> rtols{1e-4, 1e-6, 1e-8, 1e-10};               // integrator tolerances of the finite-horizon and
                                                                    // simulation predictors, each in [1e-14, 0.1]
  std::vector<int> grid_points{5, 9, 17, 33, 65, 129};              // n per axis of grid sampling, each in [2, 100000]
  double grid_rtol = 1e-8;                                          // tolerance of the grid runs (the CLI default)
  double reference_rtol = 1e-12;                               // in [1e-14, 1e-9]: the references' integrator tolerance
  int reference_bisections = 40;                               // in [10, 60]: 7.5 / 2^40 ~ 7e-12 in ln C
  std::vector<double> trace_max_steps{0.1, 0.05, 0.02, 0.01};  // continuation step caps (unit square), each in
                                                               // (0, 0.5]; empty: no continuation rows
  double trace_half_width = 0.5;                               // in (0, 10]: the traced strip is ln B +- this
  std::vector<std::string> predictors{"asymptotic", "finite_horizon", "simulation"};  // which to measure
  ProgressCallback on_progress;  // rows done (total not known in advance: 0)
  void validate() const;         // throws InvalidArgument naming the field
};

struct ThresholdRow {
  std::string predictor;            // "asymptotic", "finite_horizon", "simulation"
  std::string method;               // "bisection", "grid", "continuation", "closed_form"
  double rtol = 0;                  // integrator tolerance (0: no integration)
  int budget = 0;                   // halvings (bisection), points per axis (grid), 1 / max_step (continuation)
  double ln_C = 0;                  // located boundary
  double error = 0;                 // |ln_C - reference| of this predictor; NaN when the reference failed
  std::size_t evaluations = 0;      // verdict evaluations
  std::size_t rhs_evaluations = 0;  // summed over the runs (0 for the asymptotic predictor and continuation)
  double seconds = 0;
  std::string status = "ok";  // "ok", or why no boundary was located (no sign change, failed run)
};

struct ThresholdReference {
  std::string predictor;
  double ln_C = 0;
  double bracket = 0;  // final bisection bracket width in ln C
  std::string status = "ok";
};

struct ThresholdPrecision {
  double B = 0;
  std::vector<ThresholdReference> references;
  std::vector<ThresholdRow> rows;
};

// base: an out-of-plane scene (the asymptotic predictor needs the exact equilibrium); base.parameters.B is the
// fixed B, base.parameters.C is replaced.
ThresholdPrecision threshold_precision(const Scene& base, const ThresholdPrecisionOptions& options = {});

}  // namespace rbcstab
