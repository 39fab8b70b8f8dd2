#pragma once
// What one-parameter branch to continue from a scene (BranchSpec), and the bounds of its free parameter:
// closed domain edges are landed on exactly, a bound beyond one is refused.
#include <optional>
#include <string>
#include <vector>
#include "rbcstab/continuation/dense.hpp"

#include "rbcstab/continuation/continuation.hpp"
#include "rbcstab/continuation/continuation_parameter.hpp"
#include "rbcstab/continuation/monitors.hpp"
#include "rbcstab/continuation/orbit.hpp"
#include "rbcstab/continuation/scene_kinds.hpp"
#include "rbcstab/model/scene.hpp"

namespace rbcstab {

// A one-parameter branch from a scene.
struct BranchSpec {
  Scene scene;  // every parameter but the free one; modal_orbit: the scene that is simulated to relax
  ProblemKind kind = ProblemKind::equilibrium;
  ContinuationParameter parameter = ContinuationParameter::lambda;
  // Steps, tolerances, detection; p_min/p_max bound the free parameter (landed on exactly; lambda's and
  // beta's closed domain edges replace bounds beyond them) and the branch runs both ways by default.
  ContinuationOptions engine = [] {
    ContinuationOptions o;
    o.direction = Direction::both;
    return o;
  }();
  double relax_T = 200;  // relaxation that gives the start state (orbits: rounded up to a multiple of 2 pi)
  // Orbits: after relax_T, whole forcing periods are relaxed in chunks until the periodicity defect
  // |x(2 pi k) - x(2 pi (k - 1))|_2 (a unit-norm state) is below relax_tol or relax_max_periods more
  // have run; Newton then solves the orbit from there. Near an attracting orbit with leading multiplier
  // rho the distance to it is ~ defect / (1 - |rho|): 4e-5 at the default for |rho| = 0.977 (the
  // in-plane orbit at Lambda = 1.2, S = 200), 4e-4 for 0.9976 (S = 2000), well inside Newton's reach.
  double relax_tol = 1e-6;
  int relax_max_periods = 20000;
  // An orbit start certified unstable (not what the scene relaxes to) is refused (StartPoint::refused:
  // the branch is not continued) unless this is set. An unstable equilibrium start is reported only
  // (the modal and full kinds start on the symmetric branch by design, stable or not).
  bool allow_unstable_start = false;
  OrbitOptions orbit;  // orbit, modal_orbit: the shooting
  // Also follow the branch bifurcating at the first BP met from the start in the continuation direction
  // (direction both: the BP nearest the start in arclength, first_bp_met).
  bool switch_at_bp = false;
  int label_every = 10;  // label every N-th point (AUTO's NPR); 0: only the ends and the special points
  // A restart (restart_spec): the problem's unknowns at the scene's value of the free parameter replace
  // the kind's start, and the scene is the problem's scene as it is (modal_orbit: not rescaled to the
  // total excess area, which it already is).
  std::optional<Eigen::VectorXd> start_state;
  // Label (UZ) or stop where a parameter or measure reaches given values (monitors.hpp): on the branch and
  // its switched branch; with a curve, on the curve only (its two parameters and measures). Saved in a branch
  // file (but a function's), so a restart keeps them unless it replaces them (RestartChanges::monitors).
  std::vector<Monitor> monitors;
  // A restart in the labelled point's own parameter: that point's value, exactly as it was computed (a
  // composite parameter rebuilt from the scene, Lambda from Delta, can differ from it by an ulp, and a
  // bound set to the label's value would then refuse the start). Unset: the scene's value.
  std::optional<double> start_parameter;
  // Throws InvalidArgument naming the field: switch_at_bp for kinds that cannot switch, the orbit
  // options, the scene's model level against the kind (model), relax_T, relax_tol, relax_max_periods,
  // label_every, the engine options, the monitors (monitor: a duplicate target),
  // and a start value (the scene's parameter) outside the bounds (min).
  void validate() const;
};

// Where the branch starts: start_parameter, else the scene's value (modal_orbit: its total excess area's).
double start_value(const BranchSpec& spec);

// The bounds the engine uses for parameter q from the requested [lo, hi]: lambda >= 0 and beta in
// [0, pi] are closed domain edges, landed on exactly instead of failing beyond them.
void set_domain_bounds(ContinuationOptions& engine, ContinuationParameter q, double lo, double hi);
// A requested bound (lo_name, hi_name: the flags or keys that gave them) beyond a closed edge is a mistake, not
// a wish to stop there: InvalidArgument naming it, its value and the domain. An infinite bound (none) passes.
void require_bounds_in_domain(ContinuationParameter q, double lo, double hi, const std::string& lo_name,
                              const std::string& hi_name);

}  // namespace rbcstab
