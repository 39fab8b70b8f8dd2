#pragma once
// The whole bifurcation diagram of a scene in one call (`rbcstab continue --diagram DEPTH`, Python's
// rbcstab.bifurcation_diagram): the start branch as continue_scene follows it, then at every located BP every
// emanating branch (both halves), recursively to `depth`, each with the start branch's engine options (steps,
// bounds, certificates, monitors): grow_tree (branch_tree.hpp) on the scene's problem. A branch reached twice is
// marked as a duplicate of the first, not followed again; a BP met again is not switched at again. HB, PD and NS
// points are listed as not followed (switching not available) with the reason: a scene's HB is refused by
// orbit_switch_start (a multiple Hopf point, or a problem kind without an orbit switch; the full model's l >= 3
// onset: outcome rotating_wave, its orbits the BP branch's states turned), a scene's PD because the
// doubled orbit has no scene kind yet, NS because tori are not continued. Labels are unique over the diagram (the
// start branch numbered first, then each branch in breadth-first order), so every branch, saved as a branch file
// (diagram_branch_file), restarts and switches from its labels like any run.
#include <atomic>
#include <cstddef>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "rbcstab/continuation/branch_spec.hpp"
#include "rbcstab/continuation/branch_tree.hpp"
#include "rbcstab/continuation/scene_branch.hpp"
#include "rbcstab/continuation/scene_measures.hpp"
#include "rbcstab/continuation/scene_run.hpp"

namespace rbcstab {

struct BifurcationDiagramSpec {
  BranchSpec start;  // the start branch (switch_at_bp must be false: the diagram switches at every BP)
  int depth = 1;     // 0: the start branch only; 1: and the branches emanating from its BPs; ... In [0, 20]
  double amplitude = kDefaultSwitchAmplitude;   // the predictor step off a BP (branch_switch.hpp)
  double duplicate_tol = kDefaultDuplicateTol;  // same point / same branch (branch_tree.hpp)
  std::size_t max_branches = kDefaultMaxBranches;
  std::function<void(std::size_t done, std::size_t pending)> on_branch = {};  // progress, after each branch
  // A checkpoint journal (empty: none): each branch continued to its end is recorded as soon as it ends; run again
  // with the same journal, the recorded branches are read back instead of continued and the rest goes on, to the
  // same diagram. A journal of another configuration (diagram_config_hash) is refused; a torn or edited record
  // is reported (BifurcationDiagram::rejected) and its branch continued again.
  std::string journal = {};
  // Ctrl-C (core/interrupt.hpp): the rest is marked interrupted. Last: a front end sets start, depth and stop.
  const std::atomic<bool>* stop = nullptr;
  void validate() const;  // throws InvalidArgument naming the field (and as BranchSpec::validate)
};

struct DiagramBranch {
  int number = 1;        // BR: 1 the start branch, then breadth first
  int parent = 0;        // the number of the branch it emanates from; 0: the start branch
  int parent_label = 0;  // the label of that special point on the parent
  int side = 0;          // BP: +1 / -1, the half of the bifurcating branch
  int depth = 0;
  MeasuredBranch branch;  // labelled after the branches before it
};

// What was done at a branching special point (side 0) or with one branch emanating from it (side +-1).
struct DiagramEmanation {
  int branch = 1;  // the branch the point lies on (number)
  int label = 0;   // the point's label
  SpecialPointType type = SpecialPointType::BP;
  int side = 0;
  EmanationOutcome outcome = EmanationOutcome::followed;
  int branch_to = 0;  // followed: the new branch; duplicate, symmetric: the earlier branch; already_switched:
  int label_to = 0;   // the branch and label of the point switched at before; rotating_wave: the branch from the
                      // BP of label label_to (on this point's branch) whose states, turned, are the orbits (0: not
                      // followed)
  std::string message;
};

struct BifurcationDiagram {
  SceneBranch start;  // the start branch as continue_scene returns it (spec, scene, start point, branch)
  int depth = 1;
  std::vector<DiagramBranch> branches;  // [0]: the start branch
  std::vector<DiagramEmanation> emanations;
  bool interrupted = false;
  std::string journal;                // the journal it was run with; empty: none
  std::size_t resumed = 0;            // branches read back from the journal instead of continued
  std::vector<std::string> rejected;  // "journal:line: why" of each record dropped (its branch continued again)
  // No branch point left unfollowed for want of time or room (interrupted, branch_limit): the depth's tree.
  bool complete() const;
};

BifurcationDiagram bifurcation_diagram(const BifurcationDiagramSpec& spec);
// FNV-1a hash (16 hex digits) of everything that decides the diagram: the start spec as its branch file holds it
// (scene, kind, parameter, engine and orbit options, monitors), depth, amplitude, duplicate_tol, max_branches.
// Not the journal, the progress or the stop (a function monitor is not in it: keep it the same on resuming).
std::string diagram_config_hash(const BifurcationDiagramSpec& spec);

// How it ended, for a front end (scene_run.hpp): no output when the start failed; a failure when the diagram is
// incomplete (interrupted, max_branches), a branch stopped before a normal end or a switch failed.
RunOutcome outcome(const BifurcationDiagram& d);

// Branch k (0-based) as a run of its own, for restarts, plots and branch files: the start branch is `start`;
// an emanating branch has the start branch's spec with its first point as the start (StartMethod::restart)
// and its direction away from the BP.
SceneBranch diagram_run(const BifurcationDiagram& d, std::size_t k);

// The tree as one JSON: "format" "rbcstab-diagram", "version" 1, "kind", "free_parameter", "depth", "complete",
// "interrupted", "start" (the start point), "branches" [{"branch", "parent", "parent_label", "side", "depth",
// "status", "message", "points", "labels" [first, last], "range" [min, max of the free parameter], "data" (the
// branch JSON of branch_io.hpp)}], "special_points" [{"branch", "label", "type", the parameter by name, "mode_l",
// "mode_m", "side", "outcome", "branch_to", "label_to", "message"}] (the branching points: BP, HB, PD, NS).
nlohmann::json to_json(const BifurcationDiagram& d);
// The branch file of branch k (branch_file.hpp) plus "diagram": {"branch", "parent", "parent_label", "side",
// "depth"}, which restarts ignore.
nlohmann::json diagram_branch_file(const BifurcationDiagram& d, std::size_t k);
// The summary: one line per branch (where it comes from, its range and status) and per branching point (what
// was done on each side).
std::string to_text(const BifurcationDiagram& d);
// `path` (to_json) and beside it one branch file per branch, "<stem>.b<K>.json" (K = 1, 2, ...), all written
// atomically together (io/files.hpp); returns the branch files' paths. Branch files "<stem>.b<K>.json" beyond
// these left by an earlier save of a larger diagram (files with a "diagram" key) are removed.
std::vector<std::string> save_diagram(const std::string& path, const BifurcationDiagram& d,
                                      const std::string& flag = "save");
// The diagram back from its tree JSON and its branch files (in branch order), each checked (parse_branch_file);
// to_json of the result equals the saved tree. Throws InvalidArgument(name, ...) naming what is wrong.
BifurcationDiagram parse_diagram(const std::string& tree, const std::vector<std::string>& branch_files,
                                 const std::string& source, const std::string& name = "diagram");
// save_diagram's files read back.
BifurcationDiagram load_diagram(const std::string& path, const std::string& name = "diagram");

}  // namespace rbcstab
