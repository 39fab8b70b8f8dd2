#pragma once
// The curve of a special point of a scene branch in a second parameter (CurveSpec, continue_curve) and the
// system that continues it (curve_system).
#include <limits>
#include <optional>
#include <string>
#include "rbcstab/continuation/dense.hpp"

#include "rbcstab/continuation/continuation.hpp"
#include "rbcstab/continuation/continuation_parameter.hpp"
#include "rbcstab/continuation/scene_branch.hpp"
#include "rbcstab/continuation/scene_kinds.hpp"
#include "rbcstab/continuation/scene_measures.hpp"
#include "rbcstab/model/scene.hpp"

namespace rbcstab {

// The curve of the point-th located special point of type `type` of a one-parameter branch, in
// (branch parameter, parameter2) with parameter2 free, both directions, the branch's engine options
// (without its events) and [p2_min, p2_max] as bounds (set_domain_bounds).
struct CurveSpec {
  CurveKind type = CurveKind::LP;
  std::optional<ContinuationParameter> parameter2;  // required; independent of the branch's parameter
  double p2_min = -std::numeric_limits<double>::infinity(), p2_max = std::numeric_limits<double>::infinity();
  int point = 1;
  // A BP of a modal orbit whose v~ and every a_l are below this (max norm) lies on the in-plane
  // ellipsoidal orbit, which the Z2-reduced system continues: those entries are exactly 0 there on a
  // continued branch (an invariant subspace), while an orbit with l >= 3 content has them O(1).
  double symmetric_tol = 1e-8;
  // Throws InvalidArgument naming the field: the type against the branch's kind (curve), parameter2
  // (missing, or coupled to the branch's parameter), min2 >= max2, point < 1, switch_at_bp set.
  void validate(const BranchSpec& branch) const;
};

// Which system continues the curve of `start` (a special point of a branch of `kind` in q1, with the
// problem's scene at the start: parameter q1 set to start.p): BP of modal equilibria -> the symmetry-
// breaking ModalBranchPointCurve; BP of a modal orbit on the ellipsoidal orbit (v~ = 0, a_l = 0 within
// symmetric_tol, an untilted rest shape, beta fixed) -> the Z2-reduced system; any other BP -> generic.
CurveSystem curve_system(ProblemKind kind, CurveKind type, const Scene& scene, ContinuationParameter q1,
                         ContinuationParameter q2, const SpecialPoint& start, double symmetric_tol = 1e-8);

struct SceneCurve {
  CurveSpec spec;        // as run: the bounds set by set_domain_bounds
  SceneBranch one;       // the one-parameter branch the curve starts from
  bool started = false;  // false: no start (the branch's start failed, or no located point); message says why
  std::string message;
  SpecialPoint start;   // the special point of `one`
  double start_p2 = 0;  // parameter2 at the start (the scene's value)
  CurveSystem system = CurveSystem::fold;
  MeasuredBranch curve;  // points carry (parameter, parameter2)
};

// Validates both specs (before any work), runs the branch (without branch.monitors), then its curve (with them).
SceneCurve continue_curve(const BranchSpec& branch, const CurveSpec& curve);
// The curve from a branch already run (no re-run; its switched branch, if any, does not matter).
SceneCurve continue_curve(const SceneBranch& one, const CurveSpec& curve);
// The state of the problem a curve augments (c.one's) at a point X of the curve (c.curve's unknowns);
// throws InvalidArgument("x", ...) when X is too short for the curve's system.
Eigen::VectorXd curve_point_state(const SceneCurve& c, const Eigen::VectorXd& X);

}  // namespace rbcstab
