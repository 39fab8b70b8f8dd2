#pragma once
// Module-private: the problem behind a scene branch (SceneProblem, make_problem: scene_problem.cpp) and the
// starts every kind shares (scene_start.cpp).
#include <functional>
#include <memory>
#include <string>
#include <vector>
#include "rbcstab/continuation/dense.hpp"

#include "rbcstab/continuation/branch_spec.hpp"
#include "rbcstab/continuation/continuation.hpp"
#include "rbcstab/continuation/detail/scene_measures.hpp"
#include "rbcstab/continuation/monitors.hpp"
#include "rbcstab/continuation/problem.hpp"
#include "rbcstab/continuation/scene_branch.hpp"
#include "rbcstab/continuation/scene_start.hpp"
#include "rbcstab/model/scene.hpp"

namespace rbcstab::detail {

// A kind's problem with its own start and its measures (Equilibrium, Orbit in scene_problem.cpp).
struct ShapeMode {
  int l = 0, m = -1;
};

class SceneProblem {
 public:
  virtual ~SceneProblem() = default;
  virtual const ContinuationProblem& problem() const = 0;
  virtual StartPoint start(const BranchSpec& spec) const = 0;
  virtual Values measures(const Eigen::VectorXd& x, double p) const = 0;
  virtual std::vector<UserEvent> events() const { return {}; }
  virtual const char* solution_name() const { return "equilibrium"; }
  // The shape mode of each unknown, (l, m) with m = -1 where the coordinates do not resolve m; empty for
  // a problem whose unknowns are not shape modes (the BP's mode is then not reported).
  virtual std::vector<ShapeMode> unknown_modes() const { return {}; }
};

// A BP's or HB's critical mode: the mode carrying >= 90 % of the eigenvector of the Jacobian's eigenvalue nearest
// 0 (BP) or the HB's pair (sp.eigenvalue), m unset where the coordinates do not resolve it. Sets
// sp.mode_l/mode_m; leaves them unset when no mode dominates. An HB whose pair coincides with another eigenvalue
// is told apart at the neighbouring point of `branch` (the branch sp lies on), where the crossing pair is off the
// axis; without the branch such an HB gets the nearest eigenvalue's mode.
void identify_mode(const ContinuationProblem& problem, const std::vector<ShapeMode>& modes, SpecialPoint& sp,
                   const Branch* branch = nullptr);

std::unique_ptr<SceneProblem> make_problem(const BranchSpec& spec, const Scene& scene);
MeasuredBranch measure_branch(const SceneProblem& sp, const SceneBranch& r, Branch b);

// What a monitor may read at a point (x, p) of a branch or curve: its parameters and its measures by name.
struct MonitoredPoint {
  std::vector<std::string> parameters;
  std::function<std::vector<double>(const Eigen::VectorXd& x, double p)> parameter_values;
  std::vector<std::string> measure_names;  // aligned with measures' values
  Measure measures;
};
// The events of `monitors` over q; (x0, p0), the start, shows which measures are numbers. Throws
// InvalidArgument("monitor", ...) for an unknown name or one that is not a continuous number.
std::vector<UserEvent> monitor_events(const MonitoredPoint& q, const std::vector<Monitor>& monitors,
                                      const Eigen::VectorXd& x0, double p0);
// The same over sp's parameters and measures (measure_names: aligned with sp.measures); sp outlives the events.
std::vector<UserEvent> monitor_events(const SceneProblem& sp, const std::vector<std::string>& measure_names,
                                      const std::vector<Monitor>& monitors, const Eigen::VectorXd& x0, double p0);

StartPoint given_start(StartMethod method, Eigen::VectorXd x, double p);
// Newton at fixed p from `guess`; `what` names the solution sought in the failure message.
StartPoint newton_start(const ContinuationProblem& problem, StartMethod method, const Eigen::VectorXd& guess, double p,
                        const std::string& what, const std::string& hint = "try a longer --relax-T");
// The start with its certified stability; an orbit certified unstable is refused unless allowed.
// A restart from a labelled state is the user's explicit choice: reported, never refused.
StartPoint assessed_start(const SceneProblem& sp, const BranchSpec& spec, const Scene& scene);

}  // namespace rbcstab::detail
