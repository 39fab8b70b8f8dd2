// bifurcation_diagram on the paper's scenes: the modal walk-through of docs/continuation.md (lambda = 1, B = 1,
// Delta = 1, Delta0 = 0.01, L = 6, C over [0.01, 0.1] from 0.04), where `--switch-at BP:l=3` reaches the
// post-instability branch by hand. The full model's onset (L = 4), whose HBs are the rotating waves of its BP's branch,
// is checked through the CLI (cli.continue.diagram_hb) and Python.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <set>
#include <string>

#include "continuation/modal_fixtures.hpp"
#include "continuation/scene_spec_fixture.hpp"
#include "rbcstab/continuation/bifurcation_diagram.hpp"
#include "rbcstab/continuation/branch_file.hpp"
#include "rbcstab/continuation/branch_labels.hpp"
#include "rbcstab/continuation/scene_restart.hpp"
#include "rbcstab/io/files.hpp"
#include "test_files.hpp"

namespace rbcstab {
namespace {

using P = ContinuationParameter;

double diagram_sigma_crit(int l, double alpha) {
  const double Pi = l * (l + 1.0);
  return -(Pi + 4 * alpha / Pi);
}

BranchSpec diagram_onset_spec() {
  return test::spec_of(modal_fixtures::scene(0.04, 6), ProblemKind::modal, P::C, 0.01, 0.1, Direction::both);
}

const BifurcationDiagram& onset_diagram() {
  static const BifurcationDiagram d = [] {
    BifurcationDiagramSpec s;
    s.start = diagram_onset_spec();
    s.depth = 1;
    return bifurcation_diagram(s);
  }();
  return d;
}

// Depth 1: the start branch is continue_scene's, bit for bit; each of its four BPs (l = 6, 5, 4, 3) gives two
// branches (a_l and -a_l), and the l = 3 BP's + half is exactly the branch `switch_at_bp` reaches by hand (the same
// computation: the same options and side), with sigma pinned at sigma_3^c on both halves (closed form, 1e-10 as
// BranchSwitch's tests).
TEST(BifurcationDiagram, ModalOnsetDepthOneReproducesTheSwitchByHand) {
  const BifurcationDiagram& d = onset_diagram();
  const SceneBranch by_hand = continue_scene(diagram_onset_spec());
  ASSERT_EQ(d.branches.size(), 9u);
  EXPECT_TRUE(d.complete());
  const Branch& root = d.branches[0].branch.branch;
  ASSERT_EQ(root.points.size(), by_hand.branch.branch.points.size());
  for (std::size_t i = 0; i < root.points.size(); ++i) EXPECT_EQ(root.points[i].x, by_hand.branch.branch.points[i].x);
  const SwitchedBranch sw = switch_at_bp(by_hand, 4);  // the 4th BP along C: l = 3
  ASSERT_TRUE(sw.switched) << sw.message;
  int found = 0;
  for (const DiagramBranch& b : d.branches) {
    if (b.parent != 1 || b.parent_label != sw.bp_label) continue;
    ++found;
    for (std::size_t i = 0; i < b.branch.branch.points.size(); ++i)
      EXPECT_NEAR(b.branch.number(i, "sigma"), diagram_sigma_crit(3, 1.0 / b.branch.branch.points[i].p), 1e-10);
    if (b.side != 1) continue;
    ASSERT_EQ(b.branch.branch.points.size(), sw.branch.branch.points.size());
    for (std::size_t i = 0; i < sw.branch.branch.points.size(); ++i)
      EXPECT_EQ(b.branch.branch.points[i].x, sw.branch.branch.points[i].x) << i;
  }
  EXPECT_EQ(found, 2);
  // Labels are unique over the diagram, and every branch records where it came from.
  std::set<int> labels;
  std::size_t n = 0;
  for (const DiagramBranch& b : d.branches) {
    for (int l : b.branch.point_labels) n += l > 0 ? 1 : 0, labels.insert(l);
    for (int l : b.branch.special_labels) n += l > 0 ? 1 : 0, labels.insert(l);
    if (b.number > 1) {
      EXPECT_EQ(b.parent, 1);
    }
  }
  labels.erase(0);
  EXPECT_EQ(labels.size(), n);
  // The children's own BPs (sigma_3^c = sigma_l^c on the l = 3 branch, C = 1/60 and 1/90) are listed, not followed.
  int depth_limited = 0;
  for (const DiagramEmanation& e : d.emanations) depth_limited += e.outcome == EmanationOutcome::depth_limit;
  EXPECT_GE(depth_limited, 4);
}

// The JSON tree and the branch files: each branch file loads as a run (restartable), carries its parent, and a
// switch at a child's own BP from its file reaches the same branch a depth-2 diagram would follow from there.
TEST(BifurcationDiagram, TreeJsonAndBranchFilesRestart) {
  const BifurcationDiagram& d = onset_diagram();
  const nlohmann::json j = to_json(d);
  EXPECT_EQ(j.at("format"), "rbcstab-diagram");
  ASSERT_EQ(j.at("branches").size(), 9u);
  EXPECT_TRUE(j.at("branches").at(0).at("parent").is_null());
  EXPECT_EQ(j.at("branches").at(3).at("parent"), 1);
  EXPECT_EQ(j.at("special_points").at(0).at("type"), "BP");
  const std::string text = to_text(d);
  EXPECT_NE(text.find("bifurcation diagram in C to depth 1: 9 branches"), std::string::npos) << text;
  EXPECT_NE(text.find("side +: followed: branch"), std::string::npos) << text;
  // A child of the l = 3 BP, saved and loaded: its label of the l = 4 BP (C = 1/60) switches like any run's.
  std::size_t child = 0;
  for (std::size_t k = 1; k < d.branches.size(); ++k)
    if (d.branches[k].side == 1 &&
        std::abs(d.branches[k].branch.number(0, "sigma") - diagram_sigma_crit(3, 1 / 0.0361689)) < 1e-3)
      child = k;
  ASSERT_GT(child, 0u);
  const nlohmann::json file = diagram_branch_file(d, child);
  EXPECT_EQ(file.at("diagram").at("parent"), 1);
  const ContinuationRun run = parse_branch_file(file.dump(1), "d.b.json");
  const int l4 = resolve_label(run, "BP:l=4", "switch_at");
  RestartChanges few;
  few.max_points = 5;  // the set bifurcating there is vertical (C = 1/60 fixed: docs/continuation.md, Limits)
  const SceneBranch s = switch_at_label(run, l4, few);
  ASSERT_TRUE(s.switched && s.switched->switched) << (s.switched ? s.switched->message : "");
  EXPECT_NEAR(s.branch.branch.special_points[0].p, 1.0 / 60, 1e-9);
}

// save_diagram then load_diagram gives the same tree; a save of a smaller diagram under the same name removes the
// larger one's extra branch files (plot <stem>.b*.json would draw them) but no other file.
TEST(BifurcationDiagram, SaveLoadAndASmallerSaveLeavesNoStaleBranchFile) {
  const std::filesystem::path dir = test::fresh_dir("diagram_test", "save");
  const std::string path = (dir / "d.json").string();
  const BifurcationDiagram& d = onset_diagram();
  ASSERT_EQ(save_diagram(path, d).size(), 9u);
  EXPECT_EQ(to_json(load_diagram(path)), to_json(d));
  BifurcationDiagram small = d;
  small.branches.resize(7);
  small.emanations.clear();
  write_file_atomic((dir / "d.b11.json").string(), "not a branch file\n");  // after a gap, and not a diagram's
  save_diagram(path, small);
  EXPECT_TRUE(std::filesystem::exists(dir / "d.b7.json"));
  EXPECT_FALSE(std::filesystem::exists(dir / "d.b8.json"));
  EXPECT_FALSE(std::filesystem::exists(dir / "d.b9.json"));
  EXPECT_TRUE(std::filesystem::exists(dir / "d.b11.json"));
  std::filesystem::remove_all(dir);
}

// Bad input names the field; a spec that asks for switch_at_bp as well is refused.
TEST(BifurcationDiagram, BadInputNamesTheField) {
  BifurcationDiagramSpec s;
  s.start = diagram_onset_spec();
  s.depth = -1;
  try {
    bifurcation_diagram(s);
    FAIL();
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.parameter(), "depth");
  }
  s.depth = 1;
  s.start.switch_at_bp = true;
  try {
    bifurcation_diagram(s);
    FAIL();
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.parameter(), "switch_at_bp");
  }
}

}  // namespace
}  // namespace rbcstab
