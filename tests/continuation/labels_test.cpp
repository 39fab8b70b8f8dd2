// Labels that carry their meaning and restart exactly: a BP's mode (l, m, direction) on the modal and full
// equilibrium branches, labels selected by type and mode (resolve_label), the docs' switch at the onset,
// and restarts from a label in its own (composite) parameter.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "continuation/fig2_fixture.hpp"
#include "continuation/modal_fixtures.hpp"
#include "continuation/scene_spec_fixture.hpp"
#include "rbcstab/continuation/branch_file.hpp"
#include "rbcstab/continuation/branch_io.hpp"
#include "rbcstab/continuation/branch_labels.hpp"
#include "rbcstab/continuation/scene_curve.hpp"
#include "rbcstab/continuation/scene_restart.hpp"
#include "rbcstab/io/json.hpp"

namespace rbcstab {
namespace {

using P = ContinuationParameter;

// sigma_l^c = -(Pi + 4 alpha / Pi), Pi = l (l + 1): where Upsilon_l(sigma) = 0 (closed form).
double sigma_crit(int l, double alpha) {
  const double Pi = l * (l + 1.0);
  return -(Pi + 4 * alpha / Pi);
}

// docs/continuation.md's walk-through: modal equilibria, lambda = 1, B = 1, Delta = 1, Delta0 = 0.01, L = 6,
// both ways from C = 0.04 over [0.01, 0.1] (`rbcstab continue --kind modal --parameter C ...`).
const SceneBranch& onset_run() {
  static const SceneBranch r = continue_scene(
      test::spec_of(modal_fixtures::scene(0.04, 6), ProblemKind::modal, P::C, 0.01, 0.1, Direction::both));
  return r;
}

ContinuationRun round_trip(const ContinuationRun& run) {
  return parse_branch_file(branch_file_json(run).dump(1), "t.json");
}

// Each BP names the mode whose sigma_l^c sigma crosses: sigma at the BP equals the closed-form sigma_l^c of
// the reported l to 1e-8 (the BP is located to ~1e-11 in C; d sigma/dC ~ 1e3), and the neighbouring modes'
// thresholds differ from it by > 1 there, so a wrong l cannot pass. m is not reported (a_l is every m's
// amplitude at the modal level); the direction is the unstable count's along C: one mode stabilises at each.
TEST(BranchPointMode, ModalBPsNameTheCrossedThreshold) {
  const MeasuredBranch& m = onset_run().branch;
  const Branch& b = m.branch;
  ASSERT_EQ(b.special_points.size(), 4u);
  const std::vector<int> expected{6, 5, 4, 3};  // along C increasing
  for (std::size_t k = 0; k < 4; ++k) {
    const SpecialPoint& sp = b.special_points[k];
    ASSERT_EQ(sp.type, SpecialPointType::BP);
    ASSERT_TRUE(sp.mode_l.has_value()) << k;
    EXPECT_EQ(*sp.mode_l, expected[k]) << k;
    EXPECT_FALSE(sp.mode_m.has_value()) << k;
    const double sigma = std::get<double>(m.special_measures[k][2]);  // r, Psi, sigma, ...
    ASSERT_EQ(m.measure_names[2], "sigma");
    EXPECT_NEAR(sigma, sigma_crit(*sp.mode_l, 1.0 / sp.p), 1e-8) << k;
    EXPECT_EQ(sp.unstable_before - sp.unstable_after, 1) << k;
  }
  const nlohmann::json j = to_json(onset_run());
  const nlohmann::json& onset = j.at("special_points").at(3);
  EXPECT_EQ(onset.at("mode_l"), 3);
  EXPECT_TRUE(onset.at("mode_m").is_null());
  EXPECT_EQ(onset.at("mode_direction"), "stable");
  const std::string text = to_text(ContinuationRun(onset_run()));
  EXPECT_NE(text.find("unstable 1 -> 0, mode l = 3 becoming stable)"), std::string::npos) << text;
  EXPECT_NE(text.find("unstable 1 -> 0 (l = 3)"), std::string::npos) << text;
}

// The full model at Delta0 = 0 (lambda = 5, Delta = 1, C = 0.04, L = 4) in B: the l = 3 onset at B = 0.72 and the
// l = 4 one at B = 1.2 are a BP (m = 0) and l Hopf pairs i m / 2 each. The l = 2, m = 1 pair sits on the axis at
// i / 2 all along, where each onset's m = 1 pair crosses: the nearest eigenvalue at the HB was that pair and the
// m = 1 HB was reported as l = 2. Every HB names the onset's l, and the m = 1 .. l of an onset once each.
TEST(BranchPointMode, HopfPairCoincidingWithANeutralPairNamesTheCrossingMode) {
  Scene scene;
  scene.parameters.Delta0 = 0;
  scene.parameters.B = 1.5;
  scene.L = 4;
  const Branch b =
      continue_scene(test::spec_of(scene, ProblemKind::full, P::B, 0.5, 1.5, Direction::backward)).branch.branch;
  std::vector<std::vector<int>> ms(5);
  int hbs = 0;
  for (const SpecialPoint& sp : b.special_points) {
    if (sp.type != SpecialPointType::HB) continue;
    ++hbs;
    const int l = std::abs(sp.p - 0.72) < 1e-6 ? 3 : std::abs(sp.p - 1.2) < 1e-6 ? 4 : 0;
    ASSERT_NE(l, 0) << sp.p;
    ASSERT_TRUE(sp.mode_l.has_value() && sp.mode_m.has_value()) << sp.p;
    EXPECT_EQ(*sp.mode_l, l) << sp.p << " m = " << *sp.mode_m;
    ms[static_cast<std::size_t>(l)].push_back(*sp.mode_m);
  }
  EXPECT_EQ(hbs, 3 + 4);
  for (auto& v : ms) std::sort(v.begin(), v.end());
  EXPECT_EQ(ms[3], (std::vector<int>{1, 2, 3}));
  EXPECT_EQ(ms[4], (std::vector<int>{1, 2, 3, 4}));
}

// --switch-at at a PD label says why no doubled orbit starts there (no scene run of this model has a PD: the label
// is the onset BP retyped, which reaches the same check).
TEST(BranchPointMode, SwitchAtAPDLabelSaysWhy) {
  SceneBranch run = onset_run();
  const int label = run.branch.special_labels[3];
  run.branch.branch.special_points[3].type = SpecialPointType::PD;
  try {
    switch_at_label(ContinuationRun(run), label);
    FAIL() << "a PD label switched";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.parameter(), "switch_at");
    EXPECT_NE(std::string(e.what()).find("is a PD: the doubled orbit of a scene's PD"), std::string::npos) << e.what();
  }
}

// The mode survives the branch file; a file written before modes were reported (no mode keys) still loads,
// its BPs without a mode.
TEST(BranchPointMode, BranchFilesKeepTheModeAndOldFilesLoad) {
  const ContinuationRun back = round_trip(onset_run());
  const Branch& b = std::get<SceneBranch>(back).branch.branch;
  ASSERT_EQ(b.special_points.size(), 4u);
  EXPECT_EQ(b.special_points[3].mode_l, std::optional<int>(3));
  nlohmann::json old = branch_file_json(ContinuationRun(onset_run()));
  for (auto& sp : old.at("special_points"))
    for (const char* key : {"mode_l", "mode_m", "mode_direction"}) sp.erase(key);
  const ContinuationRun loaded = parse_branch_file(old.dump(), "old.json");
  const Branch& ob = std::get<SceneBranch>(loaded).branch.branch;
  ASSERT_EQ(ob.special_points.size(), 4u);
  EXPECT_FALSE(ob.special_points[3].mode_l.has_value());
  EXPECT_TRUE(to_json(loaded).at("special_points").at(3).at("mode_l").is_null());
}

// TYPE[:l=L][:m=M] picks the one matching labelled point; a number is itself; anything else is refused
// naming the flag and what matched.
TEST(BranchPointMode, LabelsAreSelectedByTypeAndMode) {
  const ContinuationRun run = round_trip(onset_run());
  const MeasuredBranch& m = onset_run().branch;
  EXPECT_EQ(resolve_label(run, "BP:l=3"), m.special_labels[3]);
  EXPECT_EQ(resolve_label(run, "BP:l=6", "switch_at"), m.special_labels[0]);
  EXPECT_EQ(resolve_label(run, "7"), 7);
  std::string msg;
  EXPECT_EQ(test::invalid_parameter([&] { (void)resolve_label(run, "BP"); }, &msg), "label");
  EXPECT_NE(msg.find("matches 4 labelled points"), std::string::npos) << msg;
  EXPECT_NE(msg.find("(BP l = 3)"), std::string::npos) << msg;
  EXPECT_EQ(test::invalid_parameter([&] { (void)resolve_label(run, "BP:l=7", "switch_at"); }, &msg), "switch_at");
  EXPECT_NE(msg.find("matches no labelled point"), std::string::npos) << msg;
  EXPECT_EQ(test::invalid_parameter([&] { (void)resolve_label(run, "BP:l=3:m=0"); }, &msg), "label");
  for (const char* bad : {"", "0", "bp", "BP:k=3", "BP:l=", "BP:l=3:l=4", "BP:l=x", "99999999999"})
    EXPECT_EQ(test::invalid_parameter([&] { (void)resolve_label(run, bad); }), "label") << bad;
}

// The docs' switching example: --switch-at BP:l=3 switches at the onset (C = 0.0362), where sigma equals
// sigma_3^c = -(12 + 4 alpha / 12), alpha = B / C (closed form, 1e-8 as above), not at the l = 6 BP at
// C = 0.0137; the switched branch has sigma pinned at sigma_3^c (1e-10, as BranchSwitch's tests).
TEST(BranchPointMode, DocsSwitchAtTheOnsetIsTheL3BP) {
  const ContinuationRun run = round_trip(onset_run());
  const SceneBranch s = switch_at_label(run, resolve_label(run, "BP:l=3", "switch_at"));
  ASSERT_TRUE(s.switched && s.switched->switched) << (s.switched ? s.switched->message : "");
  const SpecialPoint& bp = s.branch.branch.special_points[static_cast<std::size_t>(s.switched->bp_number - 1)];
  EXPECT_NEAR(bp.p, 0.0361689, 1e-6);
  const double alpha = 1.0 / bp.p;
  EXPECT_NEAR(std::get<double>(s.branch.special_measures[static_cast<std::size_t>(s.switched->bp_number - 1)][2]),
              sigma_crit(3, alpha), 1e-8);
  const MeasuredBranch& sw = s.switched->branch;
  ASSERT_GT(sw.branch.points.size(), 10u);
  for (std::size_t i = 0; i < sw.branch.points.size(); ++i)
    EXPECT_NEAR(sw.number(i, "sigma"), sigma_crit(3, 1.0 / sw.branch.points[i].p), 1e-10) << i;
  // The switched branch's own BPs: sigma_3^c = sigma_l^c, l = 4 at alpha = 60 (C = 1/60), then l = 5 (C = 1/90).
  ASSERT_GE(sw.branch.special_points.size(), 1u);
  EXPECT_NEAR(sw.branch.special_points[0].p, 1.0 / 60, 1e-9);
  EXPECT_EQ(sw.branch.special_points[0].mode_l, std::optional<int>(4));
}

// A restart in a composite parameter (Lambda, moved through Delta) to the value of one of the run's own
// labels: the start is the label's value, bit for bit, and the branch reaches it. Rebuilding Lambda from
// the scene's Delta (what a restart did) lands off it by rounding for some labels, and a bound set to the
// label's value then refused the start: counted here, so this test would fail if that never happened.
TEST(LabelRestart, ReachesALabelsValueInACompositeParameter) {
  Scene scene = modal_fixtures::scene(0.04, 2);
  const SceneBranch r =
      continue_scene(test::spec_of(scene, ProblemKind::equilibrium, P::Lambda, 0.5, 3, Direction::both));
  const ContinuationRun run = round_trip(r);
  int rebuilt_off = 0, restarts = 0;
  for (const LabelledPoint& lp : labelled_points(run)) {
    if (lp.special || !lp.type.empty()) continue;  // the regular labels (the ends are the bounds)
    const double v = r.branch.branch.points[lp.index].p;
    for (const bool up : {true, false}) {
      RestartChanges ch;
      (up ? ch.p_max : ch.p_min) = v;
      BranchSpec spec = restart_spec(run, lp.label, ch);
      ASSERT_TRUE(spec.start_parameter.has_value());
      EXPECT_EQ(*spec.start_parameter, v);
      const SceneBranch again = continue_scene(spec);
      ASSERT_TRUE(again.start.converged) << lp.label;
      EXPECT_EQ(again.start.p, v);
      EXPECT_EQ(up ? again.branch.branch.points.back().p : again.branch.branch.points.front().p, v) << lp.label;
      ++restarts;
      spec.start_parameter.reset();
      try {
        spec.validate();
      } catch (const InvalidArgument&) {
        ++rebuilt_off;
      }
    }
  }
  EXPECT_GE(restarts, 6);
  EXPECT_GE(rebuilt_off, 1);
  std::printf("%d of %d restarts refused with Lambda rebuilt from Delta\n", rebuilt_off, restarts);
}

// A branch continued to a BP's own value (the onset's C, from a regular label of the same run) stops within
// rounding of the crossing: the BP is the end point, at the label's value exactly, not a secant probe up to
// location_tol (1e-11) before it; and it names its mode.
TEST(LabelRestart, ABPAtTheRangeEndIsTheEndPoint) {
  const ContinuationRun run = round_trip(onset_run());
  const Branch& b = onset_run().branch.branch;
  RestartChanges ch;
  ch.p_min = b.special_points[2].p;  // the l = 4 BP
  ch.p_max = b.special_points[3].p;  // the onset
  const SceneBranch again = restart(run, onset_run().branch.point_labels[10], ch);
  ASSERT_TRUE(again.start.converged);
  const auto& sps = again.branch.branch.special_points;
  ASSERT_FALSE(sps.empty());
  const SpecialPoint& last = sps.back();
  EXPECT_EQ(last.type, SpecialPointType::BP);
  EXPECT_EQ(last.p, b.special_points[3].p);
  // Against the closed form: the root of sigma_eq(C) = sigma_3^c(B/C) (bisection to the last bit): the first
  // run located the onset 2e-13 from it; 1e-12 (the secant's probe at the end was 5.8e-12 off).
  const double root = modal_fixtures::threshold_root(modal_fixtures::scene(0.04, 6).parameters, P::C, 3, 0.03, 0.04);
  EXPECT_NEAR(last.p, root, 1e-12);
  std::printf("onset at the range end: %.3e from the closed-form root\n", last.p - root);
  EXPECT_EQ(last.mode_l, std::optional<int>(3));
  EXPECT_EQ(last.status, LocationStatus::located);
}

// The points of a UZ curve's own file start that curve again: a regular point of the curve and its far
// end (outside the one-parameter branch's bounds in Delta), each giving a curve through the same points
// (Delta at the curve's lambda bounds to 1e-9: both converged to 1e-12 on a regular curve).
TEST(LabelRestart, UZCurvePointsRestartTheirCurve) {
  BranchSpec spec =
      test::spec_of(test::fig2_in_plane(0.3), ProblemKind::orbit, P::Delta, 0.3, 0.45, Direction::forward);
  const SceneCurve c = continue_curve(spec, test::curve_of(CurveKind::UZ, P::lambda, 4.8, 5.6));
  ASSERT_TRUE(c.started) << c.message;
  const ContinuationRun run = round_trip(c);
  const MeasuredBranch& m = c.curve;
  ASSERT_GE(m.branch.points.size(), 3u);
  auto Delta_at = [](const MeasuredBranch& k, double lambda) {
    for (const BranchPoint& q : k.branch.points)
      if (q.parameters.at(1) == lambda) return q.parameters.at(0);
    return std::nan("");
  };
  int tried = 0;
  for (const LabelledPoint& lp : labelled_points(run)) {
    if (lp.branch != 2 || lp.special) continue;
    const SceneCurve again = restart_curve(run, lp.label, test::curve_of(CurveKind::UZ, P::lambda, 4.8, 5.6));
    ASSERT_TRUE(again.started) << lp.label << ": " << again.message;
    for (const double lambda : {4.8, 5.6})
      EXPECT_NEAR(Delta_at(again.curve, lambda), Delta_at(m, lambda), 1e-9) << lp.label;
    ++tried;
  }
  EXPECT_GE(tried, 2);
}

}  // namespace
}  // namespace rbcstab
