#pragma once
// A profile point's re-fit by projected Gauss-Newton / Levenberg-Marquardt (docs/inverse.md "Profile likelihoods"):
// 1-3 free coordinates, the residuals r/sigma and their Jacobian from linearise; Ipopt stays the fallback.
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "rbcstab/inverse/fit.hpp"

namespace rbcstab::detail {

// The cell at fitted coordinates x.
CellModel cell_at(const CellModel& base, std::span<const FitParameterInfo> info, std::span<const double> x);
// The residuals of the numeric rows at a cell; false with the reason of the first row without a prediction.
bool residuals_at(std::span<const ObservedRow> rows, const CellModel& cell, const ForwardOptions& options,
                  std::vector<double>& r, std::string& reason);

struct LeastSquaresRefit {
  bool converged = false;
  std::string reason;     // why not
  std::vector<double> x;  // fitted coordinates (the held one unchanged)
  double chi2 = 0;
  int iterations = 0, evaluations = 0;  // Jacobians; residual evaluations (Jacobians included)
};
// Minimises chi^2 over every coordinate but `held`, from `start`, within [lo, hi] (fitted coordinates): a
// Levenberg-Marquardt step on the coordinates not held at a bound by the gradient, clipped to the box. Converged
// when the undamped Gauss-Newton step predicts a chi^2 decrease below 1e-9 max(chi^2, 1). `keep_going` is called
// once per iteration (false: stop, not converged).
LeastSquaresRefit least_squares_refit(std::span<const ObservedRow> rows, std::span<const FitParameter> free,
                                      const CellModel& cell, const FitOptions& options, std::vector<double> start,
                                      int held, std::span<const double> lo, std::span<const double> hi,
                                      const std::function<bool()>& keep_going);

}  // namespace rbcstab::detail
