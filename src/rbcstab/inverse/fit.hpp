#pragma once
// The inverse problem: membrane properties from observed motion (docs/inverse.md). Weighted least squares over the
// free parameters (ln of the moduli and viscosities, the excess areas linearly) within the bounds of
// fit_parameter_info, solved by Ipopt from several starts; the Fisher information J^T J at the estimate gives the
// covariance, 95 % intervals and correlations, and names the directions the data cannot pin.
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <vector>

#include "rbcstab/core/enum_table.hpp"
#include "rbcstab/inverse/forward.hpp"
#include "rbcstab/inverse/observations.hpp"

namespace rbcstab {

struct FitOptions {
  int starts = 4;                       // [1, 64]: the given start, then starts spread in the box (fixed seed)
  double start_spread = 1.0;            // (0, 10]: half-width of the spread in the fitted coordinate (ln for moduli)
  unsigned seed = 1;                    // of the spread starts: a fit is deterministic
  int max_iterations = 100;             // [1, 10000]: Ipopt iterations per start
  double tol = 1e-8;                    // (0, 1e-2]: Ipopt's tol (scaled KKT error of 1/2 chi^2)
  double fd_step = 1e-4;                // (0, 0.1]: central-difference step in the fitted coordinate (docs/inverse.md)
  double identifiability_ratio = 1e-8;  // (0, 1): a Fisher eigenvalue below ratio * largest is a flat direction
  ForwardOptions forward;
  void validate() const;  // throws InvalidArgument naming the field
};

enum class FitStatus { converged, infeasible, maximum_iterations, failed };
template <>
struct EnumTable<FitStatus> {
  static constexpr EnumName<FitStatus> entries[] = {{FitStatus::converged, "converged"},
                                                    {FitStatus::infeasible, "infeasible"},
                                                    {FitStatus::maximum_iterations, "maximum_iterations"},
                                                    {FitStatus::failed, "failed"}};
};

struct FitStart {
  std::vector<double> start, end;  // fitted coordinates
  FitStatus status = FitStatus::failed;
  std::string ipopt_status;  // Ipopt's return ("Solve_Succeeded")
  double chi2 = kNotGiven;
  int iterations = 0;
};

struct FitEstimate {
  FitParameterInfo parameter;
  double value = kNotGiven;                   // SI
  double standard_error = kNotGiven;          // of the fitted coordinate (ln value for a log parameter)
  double lo95 = kNotGiven, hi95 = kNotGiven;  // SI: coordinate +- 1.96 se mapped back; NaN when not identifiable
  bool identifiable = true;
  bool at_bound = false;  // within 1e-6 (coordinate) of a bound: the interval assumes an interior optimum
};

struct RowResidual {
  int line = 0;
  Observable observable = Observable::inclination_angle;
  double observed = kNotGiven, predicted = kNotGiven, uncertainty = kNotGiven;
  double residual = kNotGiven;  // (predicted - observed)/uncertainty
  Regime observed_regime = Regime::undetermined, predicted_regime = Regime::undetermined;
  bool regime_agrees = true;  // where the row names a regime: predicted == observed (not part of chi^2 yet)
  std::string reason;         // why no prediction
};

struct FitResult {
  FitStatus status = FitStatus::failed;
  std::string message;  // why not converged; the identifiability statement when a direction is flat
  CellModel cell;       // fixed values and the estimates
  std::vector<FitEstimate> estimates;
  double chi2 = kNotGiven;
  int rows = 0, dof = 0;  // rows in chi^2; rows - free parameters
  std::vector<RowResidual> residuals;
  std::vector<std::vector<double>> covariance;   // of the fitted coordinates (pseudo-inverse on flat directions)
  std::vector<std::vector<double>> correlation;  // NaN where a parameter is not identifiable
  std::vector<double> fisher_eigenvalues;        // ascending
  std::vector<std::string> unidentifiable;       // one plain sentence per flat direction
  std::vector<FitStart> starts;
  int evaluations = 0;  // forward evaluations of all rows
};

// The free parameters by name (fit_parameter_from_string), each once; `cell` holds the fixed values and the first
// start. Throws InvalidArgument for no numeric rows, a free parameter named twice, lambda and inner_viscosity both
// free, a start outside the bounds. Non-convergence is a status.
FitResult fit(const ObservationData& data, const std::vector<std::string>& free, const CellModel& cell,
              const FitOptions& options = {});

// Gauss-Newton quantities at one point: residuals (predicted - observed)/sigma of the numeric rows and their
// Jacobian in the fitted coordinates by central differences (options.fd_step); ok false with the reason when a
// prediction fails.
struct Linearisation {
  bool ok = false;
  std::string reason;
  std::vector<double> r;               // per numeric row
  std::vector<std::vector<double>> J;  // rows x free
};
Linearisation linearise(std::span<const ObservedRow> rows, std::span<const FitParameter> free, const CellModel& cell,
                        const FitOptions& options, double step);

nlohmann::json to_json(const FitResult& r);
std::string fit_text(const FitResult& r);

}  // namespace rbcstab
