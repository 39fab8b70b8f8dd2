#pragma once
// The inverse problem: membrane properties from observed motion (docs/inverse.md). Weighted least squares over the
// free parameters (ln of the moduli and viscosities, the excess areas linearly) within the bounds of
// fit_parameter_info, solved by Ipopt from several starts; the Fisher information J^T J at the estimate gives the
// covariance, 95 % intervals and correlations, and names the directions the data cannot pin.
#include <atomic>
#include <functional>
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <vector>

#include "rbcstab/core/enum_table.hpp"
#include "rbcstab/inverse/constraints.hpp"
#include "rbcstab/inverse/forward.hpp"
#include "rbcstab/inverse/observations.hpp"
#include "rbcstab/inverse/sensitivity.hpp"

namespace rbcstab {

// How a profile point re-fits the other parameters: projected Gauss-Newton / Levenberg-Marquardt
// (inverse/detail/profile_refit.hpp) with Ipopt as the fallback when it fails or a regime row is active, or Ipopt.
enum class ProfileMethod { gauss_newton, ipopt };
template <>
struct EnumTable<ProfileMethod> {
  static constexpr EnumName<ProfileMethod> entries[] = {{ProfileMethod::gauss_newton, "gauss_newton"},
                                                        {ProfileMethod::ipopt, "ipopt"}};
};

// Profile likelihoods (docs/inverse.md "Profile likelihoods"): each free parameter held on a grid in its fitted
// coordinate while the others are re-optimised (warm-started from the neighbouring point); the 95 % interval
// is where Delta chi^2 = chi^2_profile - chi^2_min crosses 3.84 (chi^2 with 1 degree of freedom), located between
// grid points by the Illinois secant.
struct ProfileOptions {
  bool enabled = false;
  int points = 4;     // [1, 50]: grid points on each side of the estimate within `span`
  double span = 4.0;  // (0, 50]: the grid reaches span Fisher standard errors; beyond it, doubling steps to the bound
  double nonlinearity_tolerance = 0.1;  // (0, 1]: an end further than this * the Fisher half-width is reported
  ProfileMethod method = ProfileMethod::gauss_newton;
  void validate() const;  // throws InvalidArgument naming the field
};

// How far a fit has got (FitOptions::on_progress): reported after every Ipopt iteration, start and profile point.
struct FitProgress {
  int starts_done = 0, starts = 0;  // starts finished, of those asked
  int profile_points = 0;           // profile points finished, every parameter's (the total is not known in advance)
  int iterations = 0;               // iterations so far: Ipopt's and the profiles' Gauss-Newton's
};

struct FitOptions {
  int starts = 4;                       // [1, 64]: the given start, then starts spread in the box (fixed seed)
  double start_spread = 1.0;            // (0, 10]: half-width of the spread in the fitted coordinate (ln for moduli)
  unsigned seed = 1;                    // of the spread starts: a fit is deterministic
  int max_iterations = 100;             // [1, 10000]: Ipopt iterations per start
  double tol = 1e-8;                    // (0, 1e-2]: Ipopt's tol (scaled KKT error of 1/2 chi^2)
  double fd_step = 1e-4;                // (0, 0.1]: central-difference step in the fitted coordinate (docs/inverse.md)
  double identifiability_ratio = 1e-8;  // (0, 1): a Fisher eigenvalue below ratio * largest is a flat direction
  ForwardOptions forward;
  ProfileOptions profiles;
  // The in-plane rows' Jacobian: variational equations (the other rows by central differences) or differences.
  JacobianMethod jacobian = JacobianMethod::variational;
  // In-plane regime rows as Ipopt constraints (inverse/constraints.hpp), in the profiles' re-fits too; false:
  // compared only.
  bool regime_constraints = true;
  // Set (e.g. by Ctrl-C: core/interrupt.hpp) to stop: the fit returns within an Ipopt iteration with the status
  // interrupted and the best start so far, if any (null: never stops).
  const std::atomic<bool>* stop = nullptr;
  std::function<void(const FitProgress&)> on_progress;  // on the calling thread; empty: none
  void validate() const;                                // throws InvalidArgument naming the field
};

enum class FitStatus { converged, infeasible, maximum_iterations, failed, interrupted };
template <>
struct EnumTable<FitStatus> {
  static constexpr EnumName<FitStatus> entries[] = {{FitStatus::converged, "converged"},
                                                    {FitStatus::infeasible, "infeasible"},
                                                    {FitStatus::maximum_iterations, "maximum_iterations"},
                                                    {FitStatus::failed, "failed"},
                                                    {FitStatus::interrupted, "interrupted"}};
};

struct FitStart {
  std::vector<double> start, end;  // fitted coordinates
  FitStatus status = FitStatus::failed;
  std::string ipopt_status;  // Ipopt's return ("Solve_Succeeded")
  double chi2 = kNotGiven;
  int iterations = 0;
};

// One parameter's profile. An end is NaN where Delta chi^2 stays below 3.84 up to the bound (or up to where the
// model gives no prediction: `reason`).
struct Profile {
  bool computed = false;
  std::vector<double> coordinate;  // fitted coordinate, ascending, the estimate included (crossings included)
  std::vector<double> delta_chi2;  // chi^2 of the re-optimised fit there minus the fit's chi^2
  double lo95 = kNotGiven, hi95 = kNotGiven;  // SI
  bool flat = false;                          // Delta chi^2 < 3.84 over the whole bounded range: not identifiable
  bool nonlinear = false;                     // an end differs from the Fisher one by more than the tolerance
  double max_shift = kNotGiven;               // largest |profile end - Fisher end| / Fisher half-width (coordinate)
  std::string statement;  // plain sentence: interval or flat, and its agreement with the Fisher statement
  std::string reason;     // why a side stopped short of its bound without crossing
  int solves = 0;         // re-optimisations (evaluations of chi^2 alone with one free parameter)
  int iterations = 0;     // iterations over them (Gauss-Newton Jacobians and Ipopt iterations)
  int fallbacks = 0;      // Gauss-Newton re-fits handed to Ipopt (failed, or a regime row active there)
};

struct FitEstimate {
  FitParameterInfo parameter;
  double value = kNotGiven;                   // SI
  double standard_error = kNotGiven;          // of the fitted coordinate (ln value for a log parameter)
  double lo95 = kNotGiven, hi95 = kNotGiven;  // SI: coordinate +- 1.96 se mapped back; NaN when not identifiable
  bool identifiable = true;
  // Within 1e-3 of the box's width (coordinate) of a bound, or its 95 % interval reaches past one: the interval
  // assumes an interior optimum, which the bound then breaks.
  bool at_bound = false;
  Profile profile;  // when FitOptions::profiles.enabled
};

struct RowResidual {
  int line = 0;
  Observable observable = Observable::inclination_angle;
  double observed = kNotGiven, predicted = kNotGiven, uncertainty = kNotGiven;
  double residual = kNotGiven;  // (predicted - observed)/uncertainty
  Regime observed_regime = Regime::undetermined, predicted_regime = Regime::undetermined;
  bool regime_agrees = true;  // where the row names a regime: predicted == observed (regime rows: see constraints)
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
  // The regime rows fitted as constraints, at the estimate.
  std::vector<ConstraintResult> constraints;
};
// The regime constraints at the estimate res.cell: margins, `multipliers` (the best start's), active and violated
// rows; violated rows make the status infeasible, named in the message (inverse/constraints.cpp).
void apply_constraints(FitResult& res, const std::vector<RegimeConstraint>& constraints,
                       std::span<const FitParameter> free, const ForwardOptions& options,
                       const std::vector<double>& multipliers);

// The free parameters by name (fit_parameter_from_string), each once; `cell` holds the fixed values and the first
// start. Throws InvalidArgument for no numeric rows, a free parameter named twice, lambda and inner_viscosity both
// free, a start outside the bounds. Non-convergence is a status.
FitResult fit(const ObservationData& data, const std::vector<std::string>& free, const CellModel& cell,
              const FitOptions& options = {});

// Gauss-Newton quantities at one point: residuals (predicted - observed)/sigma of the numeric rows and their
// Jacobian in the fitted coordinates by options.jacobian (central differences at `step`); ok false with the reason
// when a prediction fails.
struct Linearisation {
  bool ok = false;
  std::string reason;
  std::vector<double> r;               // per numeric row
  std::vector<std::vector<double>> J;  // rows x free
};
Linearisation linearise(std::span<const ObservedRow> rows, std::span<const FitParameter> free, const CellModel& cell,
                        const FitOptions& options, double step);
// The variational route of linearise (inverse/sensitivity.cpp).
Linearisation variational_linearise(std::span<const ObservedRow> rows, std::span<const FitParameter> free,
                                    const CellModel& cell, const FitOptions& options, double step);

nlohmann::json to_json(const FitResult& r);
std::string fit_text(const FitResult& r);

}  // namespace rbcstab
