#pragma once
// Pseudo-arclength continuation of F(x, p) = 0 (Keller): tangent predictor, Newton corrector on the
// bordered system [F; t.(X - X0) - ds], adaptive step, both directions, parameter bounds, stop
// conditions, bifurcation test functions and user events located by a safeguarded secant
// (Illinois) on the arclength. Results are plain data (docs/continuation.md).
#include <complex>
#include <cstddef>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>
#include "rbcstab/continuation/dense.hpp"

#include "rbcstab/continuation/normal_form.hpp"
#include "rbcstab/continuation/problem.hpp"
#include "rbcstab/continuation/stability_certificate.hpp"
#include "rbcstab/core/enum_table.hpp"
#include "rbcstab/core/progress.hpp"

namespace rbcstab {

// AUTO-07p labels. LP/BP/HB on equilibrium branches; LPC/PD/NS on orbit branches (multipliers);
// UZ a zero of a user function; EP the end points of a branch.
enum class SpecialPointType { LP, BP, HB, LPC, PD, NS, UZ, EP };
template <>
struct EnumTable<SpecialPointType> {
  static constexpr EnumName<SpecialPointType> entries[] = {{SpecialPointType::LP, "LP"}, {SpecialPointType::BP, "BP"},
                                                           {SpecialPointType::HB, "HB"}, {SpecialPointType::LPC, "LPC"},
                                                           {SpecialPointType::PD, "PD"}, {SpecialPointType::NS, "NS"},
                                                           {SpecialPointType::UZ, "UZ"}, {SpecialPointType::EP, "EP"}};
};

enum class LocationStatus { located, guess };  // guess: bracketed but the secant did not converge
template <>
struct EnumTable<LocationStatus> {
  static constexpr EnumName<LocationStatus> entries[] = {{LocationStatus::located, "located"},
                                                         {LocationStatus::guess, "guess"}};
};

enum class ContinuationStatus {
  completed,       // a stop condition was met (bound, max points, user stop)
  step_too_small,  // the corrector failed down to min_step
  outside_domain,  // the problem rejected a parameter value (message says which)
  start_failed,    // Newton did not converge at the starting point
  branch_lost      // every step down to min_step reached a point that no located special point joins to the
                   // last one (a jump to a nearby branch): the message says after which point
};
template <>
struct EnumTable<ContinuationStatus> {
  static constexpr EnumName<ContinuationStatus> entries[] = {{ContinuationStatus::completed, "completed"},
                                                             {ContinuationStatus::step_too_small, "step_too_small"},
                                                             {ContinuationStatus::outside_domain, "outside_domain"},
                                                             {ContinuationStatus::start_failed, "start_failed"},
                                                             {ContinuationStatus::branch_lost, "branch_lost"}};
};

enum class Direction { forward, backward, both };  // forward: p increasing at the start
template <>
struct EnumTable<Direction> {
  static constexpr EnumName<Direction> entries[] = {
      {Direction::forward, "forward"}, {Direction::backward, "backward"}, {Direction::both, "both"}};
};

// A zero of g(x, p) along the branch is reported as a UZ point named `name`; a stop event also ends the
// direction at it (the located point is the branch's last; message "stopped at NAME").
struct UserEvent {
  std::string name;
  std::function<double(const Eigen::VectorXd& x, double p)> g;
  bool stop = false;
};

struct ContinuationOptions {
  double initial_step = 1e-2;  // first arclength step |ds|: small enough for Newton from the tangent
  double min_step = 1e-10;     // give up below this: the branch is lost (or the problem ends here)
  double max_step = 0.5;       // caps the step so test functions are sampled densely enough
  double step_growth = 1.5;    // after an easy corrector (<= easy_iterations), grow ds by this
  double step_shrink = 0.5;    // after a failed or hard corrector, shrink ds by this
  int easy_iterations = 3;     // Newton iterations counted as easy
  int max_newton = 12;         // Newton iterations per corrector before declaring failure
  double newton_tol = 1e-12;   // on max|dX| and max|F| (absolute; states here are O(1))
  double p_min = -std::numeric_limits<double>::infinity();  // stop at this parameter bound, exactly
  double p_max = std::numeric_limits<double>::infinity();
  std::size_t max_points = 1000;  // per direction, start point included
  Direction direction = Direction::forward;
  bool detect_bifurcations = true;   // evaluate LP/BP/HB (LPC/PD/NS) test functions
  bool compute_stability = true;     // spectrum at every point (needed for detection)
  double location_tol = 1e-11;       // stop locating when the bracket spans < this in (x, p) (max norm)
  int max_location_iterations = 60;  // secant/bisection steps per special point
  double stability_tol = 1e-9;       // Re(lambda) or |mu| - 1 below this counts as neutral
  // Stability certificates: a point whose cheap certificate has |margin| below this also gets the
  // problem's refinement check (orbits: ~2.4 shootings) and the state-error term (the margin at the
  // state moved by its error: one more corrector step, at least newton_tol; one more spectrum); special
  // points always do. 0: never (special points still do); inf: every point.
  double certificate_refine_margin = 1e-6;
  // Branch-jump guard: a step whose test functions or unstable count change is accepted only when every
  // special point found in it is located (a jump to a nearby branch leaves an unlocatable change); else it is
  // halved and retried, down to min_step (then status branch_lost). false: the old rule (for diagnosis).
  bool confirm_special_points = true;
  // The normal form of every located LP, BP and HB of an equilibrium branch (normal_form_analysis.hpp): a few
  // hundred residuals and one dense SVD or eigen-decomposition per point.
  bool normal_forms = true;
  std::vector<UserEvent> events;  // user zero crossings -> UZ
  // Optional user stop: return true to end the branch after this point.
  std::function<bool(const Eigen::VectorXd& x, double p)> stop;
  ProgressCallback on_progress;  // points of this direction so far, of max_points

  void validate() const;  // throws InvalidArgument naming the field
};

struct BranchPoint {
  Eigen::VectorXd x;
  double p = 0;
  std::vector<double> parameters;  // problem.parameter_values(x, p)
  Eigen::VectorXcd spectrum;       // eigenvalues or Floquet multipliers
  int n_unstable = 0;
  bool stable = true;  // n_unstable == 0 (values within stability_tol of the boundary count as stable)
  Stability stability = Stability::uncertain;  // the certified label (certify); margin and its error:
  double margin = std::numeric_limits<double>::quiet_NaN();
  double margin_error = std::numeric_limits<double>::quiet_NaN();
  CertificateTerm uncertain_because = CertificateTerm::spectrum;
  double arclength = 0;  // signed arclength from the start point
  int newton_iterations = 0;
};

struct SpecialPoint {
  SpecialPointType type = SpecialPointType::UZ;
  std::string name;  // the event name for UZ; the label otherwise
  Eigen::VectorXd x;
  double p = 0;
  std::vector<double> parameters;
  double p_lo = 0, p_hi = 0;  // parameter bracket at the end of location
  double precision = 0;       // max-norm distance in (x, p) of the final bracket
  LocationStatus status = LocationStatus::guess;
  int unstable_before = 0, unstable_after = 0;  // change in the unstable count across the point
  double test_value = 0;                        // the test function at the reported point
  std::size_t after_index = 0;                  // lies between branch points after_index and after_index + 1
  std::complex<double> eigenvalue;              // HB: the crossing pair (+ i omega); NS/PD: the critical multiplier
  // The point's certified stability; margin_error also covers the margin's change across the final
  // bracket (the point is located only to within it).
  Stability stability = Stability::uncertain;
  double margin = std::numeric_limits<double>::quiet_NaN();
  double margin_error = std::numeric_limits<double>::quiet_NaN();
  CertificateTerm uncertain_because = CertificateTerm::spectrum;
  // A BP or HB of modal/full equilibria: the mode (l, and m where the coordinates resolve it) carrying the
  // critical eigenvector (HB: its pair's); unset where no mode carries 90 % of it (or for other problems).
  std::optional<int> mode_l, mode_m;
  // LP, BP, HB of equilibrium branches with ContinuationOptions::normal_forms (unset otherwise, and in files
  // written before it was computed).
  std::optional<NormalForm> normal_form;
};

struct ContinuationCounters {
  std::size_t steps = 0, rejected_steps = 0, newton_iterations = 0, residual_evaluations = 0, jacobian_evaluations = 0,
              spectra = 0, location_iterations = 0;
  std::size_t unconfirmed_steps = 0;  // of rejected_steps: by the branch-jump guard (confirm_special_points)
};

struct Branch {
  std::vector<std::string> parameter_names;
  std::vector<BranchPoint> points;  // ordered along the branch (backward part reversed first)
  std::vector<SpecialPoint> special_points;
  ContinuationStatus status = ContinuationStatus::completed;
  std::string message;
  ContinuationCounters counters;
};

// The k-th (k >= 1) special point of `type` along b, in branch order; nullptr if b has fewer.
const SpecialPoint* find_special_point(const Branch& b, SpecialPointType type, int k = 1);

// Newton on F(x, p) = 0 at fixed p from x0. Returns whether it converged; x holds the last iterate.
struct NewtonResult {
  Eigen::VectorXd x;
  bool converged = false;
  int iterations = 0;
  double residual_norm = 0;
};
// Newton at fixed p. An x0 that already solves F = 0 to 1e-2 tol (1 + |x0|) (max norms; a labelled point, stored
// as computed) is returned as it is, with 0 iterations: at a fold or BP a Newton step through the singular
// Jacobian would throw it off.
NewtonResult solve_fixed_parameter(const ContinuationProblem& problem, const Eigen::VectorXd& x0, double p,
                                   double tol = 1e-12, int max_iterations = 30);

// Continues the branch through (x0, p0). x0 must solve F(x0, p0) = 0 to within Newton's reach.
Branch continue_branch(const ContinuationProblem& problem, const Eigen::VectorXd& x0, double p0,
                       const ContinuationOptions& options);

}  // namespace rbcstab
