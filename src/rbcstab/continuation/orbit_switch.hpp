#pragma once
// Starting periodic-orbit branches at special points (AUTO-07p's restarts from HB and PD labels):
//  - HB of an autonomous equilibrium branch: the orbit x(t) ~ x_HB + eps Re(q e^{i omega t}) (J q = i omega q) with
//    period 2 pi / omega, the predictor along that direction at fixed p and T; AutonomousOrbitProblem then.
//  - PD of a forced orbit branch (periods k): the doubled orbit (periods 2 k, twice the segments) from the orbit
//    repeated plus eps times the linearised solution through the -1 Floquet vector v (+v over the first k periods,
//    -v over the second): the period-1 orbit repeated is a solution of the doubled problem, from which the doubled
//    orbit leaves in a pitchfork along that direction. PD of an autonomous orbit branch: the same with the period
//    2 T as an unknown (AutonomousOrbitProblem, twice the segments, the same phase component).
// Either way Newton on the hyperplane d.(X - X_0) = h (newton_on_hyperplane) gives the first point and the engine
// continues away from the special point. At an HB or PD whose normal form (normal_form_analysis.hpp,
// period_map_normal_form.hpp) gives an amplitude law, Newton starts at the parameter that law predicts for the
// predictor's amplitude (at the point's p otherwise, and again there when that fails). A multiple point (another
// eigenvalue on the imaginary axis, another multiplier on the unit circle) is refused with the critical values named:
// the simple-pair direction would be one arbitrary member of a larger family (docs/continuation.md "Orbits from HB and
// PD points").
#include <limits>
#include <memory>
#include <string>
#include "rbcstab/continuation/dense.hpp"

#include "rbcstab/continuation/autonomous_orbit.hpp"
#include "rbcstab/continuation/continuation.hpp"
#include "rbcstab/continuation/orbit.hpp"

namespace rbcstab {

struct OrbitSwitchOptions {
  double amplitude = 1e-3;           // eps: the predictor's amplitude in state units (max over the orbit ~ eps)
  double critical_tol = 1e-6;        // |Re lambda| (|mu| - 1) below this, relative to max(1, |lambda|): on the boundary
  int max_newton = 20;               // corrector iterations for the first point
  OrbitOptions orbit;                // HB: the orbit problem's (PD: the parent's, twice its segments)
  ContinuationOptions continuation;  // for the new branch (its direction is chosen away from the point)
  void validate() const;             // throws InvalidArgument naming the field
};

struct OrbitSwitchResult {
  bool switched = false;  // false: message says why (multiple point, corrector failed, unsupported problem)
  std::string message;
  Eigen::VectorXd direction;  // d in (X, p), unit
  double period = 0;          // the start's period: 2 pi / omega (HB), 4 pi k (PD)
  // The problem the new branch solves (it refers to the system, which must outlive it): continue or restart the
  // branch with it (a diagram's next level). Null when nothing was switched.
  std::unique_ptr<ContinuationProblem> problem;
  Branch branch;  // the new branch, starting next to the special point
  // >= 0: refused because the orbits born here are rotating waves of the branch from this special point of the
  // same branch (the full model's l >= 3 onset: its BP (l, m = 0); model/rotating_wave.hpp).
  int rotating_wave_of = -1;
};

// The first point of the orbit branch and the problem it solves, before it is continued: what a diagram checks for
// duplicates and follows (branch_tree.hpp). switch_at = orbit_switch_start, then continued.
struct OrbitSwitchStart {
  bool found = false;
  // Not found because the point is not one this switch starts from (a multiple point, off the boundary, a problem
  // kind or type it does not handle): message says which. Otherwise (found false, refused false) the corrector failed.
  bool refused = false;
  std::string message;
  Eigen::VectorXd direction;  // d in (X, p), unit
  double period = 0;
  // p* + side (peak / amplitude)^2 from the point's normal form for the predictor's peak |x - x*|_2 (HB) or its
  // distance eps at t = 0 (PD), where Newton starts; NaN without a usable law (no normal form, degenerate).
  double predicted_p = std::numeric_limits<double>::quiet_NaN();
  std::unique_ptr<ContinuationProblem> problem;  // refers to the system, which must outlive it; null unless found
  Eigen::VectorXd x;                             // the first point, of `problem`
  double p = 0;
  Direction away = Direction::forward;  // the continuation direction that leaves the special point
  int rotating_wave_of = -1;            // as OrbitSwitchResult's
};
OrbitSwitchStart orbit_switch_start(const ContinuationProblem& problem, const Branch& branch, const SpecialPoint& point,
                                    const OrbitSwitchOptions& options = {});

// hb: an HB special point of a branch of AutonomousEquilibriumProblem(system).
OrbitSwitchResult switch_at_hopf(const AutonomousSystem& system, const SpecialPoint& hb,
                                 const OrbitSwitchOptions& options = {});
// pd: a PD special point of a branch continued with `problem`.
OrbitSwitchResult switch_at_period_doubling(const PeriodicOrbitProblem& problem, const SpecialPoint& pd,
                                            const OrbitSwitchOptions& options = {});
// The one entry for diagrams: HB on AutonomousEquilibriumProblem branches, PD on PeriodicOrbitProblem and
// AutonomousOrbitProblem branches.
// Any other HB is checked for multiplicity (refused naming the critical pairs and the branch's labels there) and
// otherwise refused as not supported for the problem kind; other types are refused (BP: switch_branch).
OrbitSwitchResult switch_at(const ContinuationProblem& problem, const Branch& branch, const SpecialPoint& point,
                            const OrbitSwitchOptions& options = {});

}  // namespace rbcstab
