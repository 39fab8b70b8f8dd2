#pragma once
// Recursive branch switching on one problem, the generic core of bifurcation diagrams (bifurcation_diagram.hpp):
// from a continued start branch, at every located special point of a branching type (BP, HB, PD) every emanating
// branch is started, checked against the branches already found (a duplicate or a symmetric copy is marked, not
// followed) and continued with the same engine options, to a given depth. One dispatch point maps a special
// point's type to its switcher (TreeOptions::switchers): BP (switch_start), HB and PD (orbit_switch_start: the
// periodic orbits of an AutonomousEquilibriumProblem's HB, the doubled orbit of a PeriodicOrbitProblem's PD, each
// with its own problem). A switcher's refusal (a multiple point, a problem kind it does not handle) and a type
// without a switcher (NS) are listed as not followed, with the reason.
#include <atomic>
#include <cstddef>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "rbcstab/continuation/branch_switch.hpp"
#include "rbcstab/continuation/continuation.hpp"
#include "rbcstab/continuation/orbit.hpp"
#include "rbcstab/core/enum_table.hpp"

namespace rbcstab {

// The start of one branch emanating from a special point, before it is continued.
struct EmanatingStart {
  bool found = false;  // false: message says why (not a simple BP, the corrector failed)
  // Not found because the switch does not apply here (a multiple HB, an HB or PD of a problem kind without an orbit
  // switch): listed as not_available with the message, not as a failure.
  bool refused = false;
  std::string message;
  int side = 0;  // which of the emanating branches (BP: +1 / -1, the two halves +d / -d; HB, PD: +1, the one orbit)
  Eigen::VectorXd x;
  double p = 0;
  Direction away = Direction::forward;  // the continuation direction that leaves the special point
  // The problem the branch belongs to; null: the same as the branch it emanates from (BP). An HB's periodic
  // orbits and a PD's doubled orbit bring their own.
  std::shared_ptr<const ContinuationProblem> problem;
  // >= 0 (refused): the orbits born here are rotating waves of the branch from this special point of the same
  // branch (the full model's l >= 3 onset, its BP (l, m = 0)): listed as rotating_wave, not as not_available.
  int rotating_wave_of = -1;
};
using Switcher = std::function<std::vector<EmanatingStart>(const ContinuationProblem&, const Branch&,
                                                           const SpecialPoint&, const BranchSwitchOptions&)>;
// The switchers available: BP (both halves of the bifurcating branch, switch_start); HB and PD (one start each,
// orbit_switch_start with the switching amplitude, corrector and engine options; hb_orbit: the HB orbit problem's
// shooting options). The HB's orbit problem refers to the AutonomousSystem of the branch's problem, which must
// outlive the tree.
std::map<SpecialPointType, Switcher> default_switchers(const OrbitOptions& hb_orbit = {});
// Whether other branches emanate from a special point of this type (BP, HB, PD, NS), switcher or not.
bool is_branching(SpecialPointType type);

// What was done with one emanating branch (or with a branching point as a whole, side 0).
enum class EmanationOutcome {
  followed,          // continued: TreeEmanation::branch_to is the new branch
  duplicate,         // its first point lies on branch_to (found before, or the closed branch from the same point
                     // whose loop passes through it from the other side): not followed again
  symmetric,         // a symmetry maps its first point onto branch_to: the copy is not followed
  already_switched,  // the same point (within duplicate_tol) was switched at before, on branch_to
  not_available,     // no switcher for this type (NS), or the switcher refused (message says why)
  rotating_wave,     // an HB whose orbits are exact rotating waves of the branch from another special point of the
                     // same branch (point_to; branch_to: its branch when followed, else -1): not followed separately
  not_located,       // the special point is a guess (its bracket did not converge): not switched at
  depth_limit,       // the branch is at the maximal depth
  failed,            // the switcher found no start (message says why)
  interrupted,       // stopped (options.stop) before it was reached
  branch_limit       // max_branches reached
};
template <>
struct EnumTable<EmanationOutcome> {
  static constexpr EnumName<EmanationOutcome> entries[] = {{EmanationOutcome::followed, "followed"},
                                                           {EmanationOutcome::duplicate, "duplicate"},
                                                           {EmanationOutcome::symmetric, "symmetric"},
                                                           {EmanationOutcome::already_switched, "already_switched"},
                                                           {EmanationOutcome::not_available, "not_available"},
                                                           {EmanationOutcome::rotating_wave, "rotating_wave"},
                                                           {EmanationOutcome::not_located, "not_located"},
                                                           {EmanationOutcome::depth_limit, "depth_limit"},
                                                           {EmanationOutcome::failed, "failed"},
                                                           {EmanationOutcome::interrupted, "interrupted"},
                                                           {EmanationOutcome::branch_limit, "branch_limit"}};
};

struct TreeBranch {
  Branch branch;
  std::shared_ptr<const ContinuationProblem> problem;  // null: the start branch's problem
  int parent = -1;                                     // index of the branch it emanates from; -1: the start branch
  int parent_point = -1;                               // index of that special point in the parent's special_points
  int side = 0;
  int depth = 0;        // 0: the start branch
  bool closed = false;  // it came back through its first point (a loop): ended there
};

// One entry per emanating branch tried (side != 0) or per branching point not switched at (side 0).
struct TreeEmanation {
  int branch = 0;         // the branch the special point lies on
  std::size_t point = 0;  // index in its special_points
  int side = 0;
  EmanationOutcome outcome = EmanationOutcome::followed;
  int branch_to = -1;  // followed: the new branch; duplicate/symmetric/already_switched: the earlier one
  int point_to = -1;   // already_switched: the earlier special point's index on branch_to; rotating_wave: on branch
  std::string message;
};

inline constexpr double kDefaultDuplicateTol = 1e-7;     // TreeOptions::duplicate_tol (why: there)
inline constexpr std::size_t kDefaultMaxBranches = 200;  // TreeOptions::max_branches

struct TreeOptions {
  int depth = 1;  // switch on branches of depth < depth; 0: the start branch only. In [0, 20]
  // Amplitude and kernel check of the BP switch; continuation: the engine options of every emanating branch
  // (the direction is set per branch, away from its point).
  BranchSwitchOptions switching;
  // Two points are the same when their (x, p) max-norm distance is below this (1 + |X|). Points are solved
  // to newton_tol (1e-12) and special points located to location_tol (1e-11), so the same point found twice
  // agrees to ~1e-10; a new branch's first point lies switching.amplitude (1e-3) from its BP, the distance
  // to the branch it leaves: the default is far from both. Must be below amplitude / 10.
  double duplicate_tol = kDefaultDuplicateTol;
  // Maps of the state that leave F invariant (x -> g x at the same p, e.g. a mirror): a branch whose first
  // point one of them maps onto an earlier branch is that branch's copy (EmanationOutcome::symmetric).
  std::vector<std::function<Eigen::VectorXd(const Eigen::VectorXd&)>> symmetries;
  std::size_t max_branches = kDefaultMaxBranches;                        // the start branch included, in [1, 10000]
  std::map<SpecialPointType, Switcher> switchers = default_switchers();  // the dispatch point
  // Events of an emanating branch (monitors), built at its first point.
  std::function<std::vector<UserEvent>(const Eigen::VectorXd& x0, double p0)> events;
  const std::atomic<bool>* stop = nullptr;  // set: stop (between points) and mark the rest interrupted
  // After each branch is continued (or recalled): branches so far, branches known to be pending.
  std::function<void(std::size_t done, std::size_t pending)> on_branch;
  // Resume (a journal): before branch k (>= 1) is continued, recall(k, b) with b's problem, parent, parent_point,
  // side and depth set may fill b.branch and b.closed from an earlier run and return true: the branch is not
  // continued again. on_followed(k, b) is called after branch k was continued to its end (not when stopped).
  std::function<bool(std::size_t k, TreeBranch& b)> recall;
  std::function<void(std::size_t k, const TreeBranch& b)> on_followed;
  void validate() const;  // throws InvalidArgument naming the field
};

struct BranchTree {
  std::vector<TreeBranch> branches;  // [0]: the start branch, then breadth first
  std::vector<TreeEmanation> emanations;
  bool interrupted = false;
};

// The tree grown from `root` (a branch of `problem`, continued already).
BranchTree grow_tree(const ContinuationProblem& problem, Branch root, const TreeOptions& options);

// Whether the solution X = (x, p) lies on branch b within tol (1 + |X|) (max norm): the nearest segment of
// b's polyline, then Newton from its foot on F = 0 in the hyperplane through X normal to the segment.
bool lies_on(const ContinuationProblem& problem, const Branch& b, const Eigen::VectorXd& X, double tol);

}  // namespace rbcstab
