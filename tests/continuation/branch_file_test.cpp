// branch_file.hpp and the restarts of scene_continuation.hpp: a run saved and loaded is the same run (its
// file JSON bit for bit); loading refuses what is not a branch file, naming the key; a restart from a label
// continues the same branch (its end point and its special points beyond the label agree with the
// uninterrupted run to 1e-10), in any parameter (the BP it finds in B is, by a fresh branch in C, a BP at
// the label's C); switching at the labelled onset BP gives the post-instability branch with
// sigma = sigma_3^c; the switched modal orbit is the orbit a simulation relaxes to; curve labels restart
// their point's branch and their curve.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>

#include "continuation/scene_spec_fixture.hpp"
#include "rbcstab/continuation/branch_file.hpp"
#include "rbcstab/continuation/branch_io.hpp"
#include "rbcstab/continuation/scene_restart.hpp"
#include "rbcstab/core/error.hpp"

namespace rbcstab {
namespace {

using P = ContinuationParameter;
using nlohmann::json;

ContinuationRun round_trip(const ContinuationRun& run) {
  return parse_branch_file(branch_file_json(run).dump(1), "t.json");
}

// The ellipsoidal branch of modal equilibria from C = 0.08 down to 0.015 and its switched branch.
const SceneBranch& modal_run() {
  static const SceneBranch r = [] {
    BranchSpec s = test::modal_spec();
    s.switch_at_bp = true;
    return continue_scene(s);
  }();
  return r;
}

const SceneBranch& orbit_run() {
  static const SceneBranch r = continue_scene(test::orbit_spec());
  return r;
}

// The l = 3 BP curve of modal equilibria in (C, B), B in [0.8, 1.2].
const SceneCurve& modal_curve() {
  static const SceneCurve c = continue_curve(test::modal_spec(4, 0.02), test::curve_of(CurveKind::BP, P::B, 0.8, 1.2));
  return c;
}

// The first labelled regular point (type "") of branch b of a run with index >= from.
LabelledPoint regular_label(const ContinuationRun& run, int b, std::size_t from = 1) {
  for (const LabelledPoint& p : labelled_points(run))
    if (p.branch == b && !p.special && p.type.empty() && p.index >= from) return p;
  ADD_FAILURE() << "no regular labelled point";
  return {};
}

double max_diff(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  return a.size() == b.size() ? (a - b).lpNorm<Eigen::Infinity>() : std::numeric_limits<double>::infinity();
}

TEST(BranchFile, SavedRunsLoadBackBitForBit) {
  const std::vector<ContinuationRun> runs{modal_run(), orbit_run(), modal_curve()};
  for (const ContinuationRun& run : runs) {
    const json j = branch_file_json(run);
    EXPECT_EQ(j.at("format"), "rbcstab-branch");
    EXPECT_EQ(j.at("version"), 1);
    const ContinuationRun back = round_trip(run);
    EXPECT_EQ(branch_file_json(back), j);  // every state, spectrum, measure, label and the spec
    EXPECT_EQ(to_json(back), to_json(run));
    EXPECT_EQ(to_csv(back), to_csv(run));
    EXPECT_EQ(to_text(back), to_text(run));
  }
  // The states are the engine's, bit for bit.
  const SceneBranch back = std::get<SceneBranch>(round_trip(modal_run()));
  EXPECT_TRUE(back.branch.branch.points[7].x == modal_run().branch.branch.points[7].x);
  EXPECT_TRUE(back.switched->branch.branch.special_points[0].x ==
              modal_run().switched->branch.branch.special_points[0].x);
  EXPECT_EQ(back.problem_scene.parameters.C, modal_run().problem_scene.parameters.C);
  EXPECT_EQ(back.spec.engine.p_min, 0.015);
  EXPECT_EQ(back.spec.engine.direction, Direction::backward);
}

TEST(BranchFile, RefusesWhatIsNotABranchFileNamingTheKey) {
  const std::string good = branch_file_json(modal_run()).dump(1);
  std::string m;
  auto parse = [&](const std::string& text) { return [text] { (void)parse_branch_file(text, "f.json"); }; };
  auto edited = [&](const std::function<void(json&)>& edit) {
    json j = json::parse(good);
    edit(j);
    return j.dump();
  };
  EXPECT_EQ(test::invalid_parameter(parse(good.substr(0, good.size() / 2)), &m), "restart");  // truncated
  EXPECT_NE(m.find("restart = 'f.json' is not a valid branch file: it is not JSON (a truncated or corrupted file?)"),
            std::string::npos)
      << m;
  EXPECT_EQ(test::invalid_parameter(parse("{\"branch\": []}"), &m), "restart");
  EXPECT_NE(m.find("it has no \"format\": \"rbcstab-branch\""), std::string::npos) << m;
  EXPECT_EQ(test::invalid_parameter(parse("[parameters]\nC = 0.04\n"), &m), "restart");  // a scene file
  EXPECT_NE(m.find("not JSON"), std::string::npos) << m;
  EXPECT_EQ(test::invalid_parameter(parse(edited([](json& j) { j["version"] = 2; })), &m), "restart");
  EXPECT_NE(m.find("version 2: this rbcstab reads version 1"), std::string::npos) << m;
  EXPECT_EQ(test::invalid_parameter(parse(edited([](json& j) { j.erase("spec"); })), &m), "restart");
  EXPECT_NE(m.find("key 'spec' is missing"), std::string::npos) << m;
  EXPECT_EQ(test::invalid_parameter(parse(edited([](json& j) { j["spec"]["kind"] = "nope"; })), &m), "restart");
  EXPECT_NE(m.find("spec.kind: kind = 'nope' is not available"), std::string::npos) << m;
  EXPECT_EQ(test::invalid_parameter(parse(edited([](json& j) { j["branch"][3]["x"].erase(0); })), &m), "restart");
  EXPECT_NE(m.find("branch[3].x has 8 entries: must be 9 (the problem's unknowns)"), std::string::npos) << m;
  EXPECT_EQ(test::invalid_parameter(parse(edited([](json& j) { j["branch"][3]["x"][1] = nullptr; })), &m), "restart");
  EXPECT_NE(m.find("branch[3].x[1] must be a finite number, got null"), std::string::npos) << m;
  EXPECT_EQ(test::invalid_parameter(parse(edited([](json& j) { j["switched_branch"]["branch"][0]["C"] = "0.1"; })), &m),
            "restart");
  EXPECT_NE(m.find("switched_branch.branch[0].C must be a finite number"), std::string::npos) << m;
  EXPECT_EQ(test::invalid_parameter(parse(edited([](json& j) { j["branch"][1]["label"] = 1; })), &m), "restart");
  EXPECT_NE(m.find("label 1 appears twice"), std::string::npos) << m;
  EXPECT_EQ(test::invalid_parameter(parse(edited([](json& j) { j["branch"][0]["type"] = ""; })), &m), "restart");
  EXPECT_NE(m.find("branch[0].type = '' must be 'EP'"), std::string::npos) << m;
  EXPECT_EQ(test::invalid_parameter(parse(edited([](json& j) { j["spec"]["scene"] = "[parameters]\nC = -1\n"; })), &m),
            "restart");
  EXPECT_NE(m.find("spec.scene: "), std::string::npos) << m;
  // An integer measure beyond int was truncated (a winding 2^32 + 1 read as 1; found by fuzzing).
  EXPECT_EQ(test::invalid_parameter(parse(edited([](json& j) { j["branch"][0]["sigma"] = 4294967297LL; })), &m),
            "restart");
  EXPECT_NE(m.find("branch[0].sigma = 4294967297 is out of range"), std::string::npos) << m;
  // A special point's normal form (docs/continuation.md "Normal forms"): refused when malformed, naming the key;
  // a file written before it existed (no key) loads without one.
  ASSERT_TRUE(std::get<SceneBranch>(round_trip(modal_run())).branch.branch.special_points[0].normal_form.has_value());
  EXPECT_EQ(test::invalid_parameter(
                parse(edited([](json& j) { j["special_points"][0]["normal_form"]["criticality"] = "soft"; })), &m),
            "restart");
  EXPECT_NE(m.find("normal_form"), std::string::npos) << m;
  EXPECT_NE(m.find("'soft'"), std::string::npos) << m;
  const ContinuationRun old = parse_branch_file(edited([](json& j) {
                                                  for (json& sp : j["special_points"]) sp.erase("normal_form");
                                                }),
                                                "old.json");
  EXPECT_FALSE(std::get<SceneBranch>(old).branch.branch.special_points[0].normal_form.has_value());
  EXPECT_EQ(test::invalid_parameter([] { (void)load_branch("/nonexistent/b.json"); }, &m), "restart");
  EXPECT_NE(m.find("restart = '/nonexistent/b.json'"), std::string::npos) << m;
}

TEST(BranchRestart, ContinuesTheSameBranchFromALabel) {
  // Modal equilibria, backward in C: from the label of point 10 on, the restart ends on C = 0.015 at the
  // same state and locates the same BPs (both located to 1e-11 in (x, p)).
  const ContinuationRun run = round_trip(modal_run());
  const LabelledPoint lp = regular_label(run, 1, 10);
  const Branch& a = modal_run().branch.branch;
  const SceneBranch r = restart(run, lp.label);
  EXPECT_EQ(r.start.method, StartMethod::restart);
  EXPECT_EQ(r.spec.engine.direction, Direction::backward);
  const Branch& b = r.branch.branch;
  ASSERT_FALSE(b.points.empty());
  EXPECT_EQ(b.points.front().p, a.points[lp.index].p);
  EXPECT_LT(max_diff(b.points.front().x, a.points[lp.index].x), 1e-12);
  EXPECT_EQ(b.points.back().p, 0.015);
  EXPECT_LT(max_diff(b.points.back().x, a.points.back().x), 1e-10);
  std::vector<double> expected;
  for (const SpecialPoint& sp : a.special_points)
    if (sp.after_index >= lp.index) expected.push_back(sp.p);
  ASSERT_EQ(b.special_points.size(), expected.size());
  ASSERT_FALSE(expected.empty());
  for (std::size_t k = 0; k < expected.size(); ++k) EXPECT_NEAR(b.special_points[k].p, expected[k], 1e-10) << k;
  EXPECT_EQ(r.branch.point_labels.front(), 1);  // a new run numbers its labels from 1

  // Orbits (Fig. 2, forward in Delta): from the first point, the same swinging -> tumbling UZ and end orbit.
  const Branch& o = orbit_run().branch.branch;
  const SceneBranch ro = restart(round_trip(orbit_run()), 1);
  ASSERT_EQ(ro.branch.branch.special_points.size(), 1u);
  EXPECT_NEAR(ro.branch.branch.special_points[0].p, o.special_points[0].p, 1e-10);
  EXPECT_EQ(ro.branch.branch.points.back().p, 0.45);
  EXPECT_LT(max_diff(ro.branch.branch.points.back().x, o.points.back().x), 1e-10);
}

TEST(BranchRestart, AnyParameterFromALabel) {
  // From C = 0.08 (label 1, stable) in B: the start is the labelled state; the BP found in B is, by a fresh
  // branch in C at that B started from the scene's closed form, a BP at C = 0.08.
  const ContinuationRun run = round_trip(modal_run());
  RestartChanges ch;
  ch.parameter = P::B;
  ch.p_min = 0.5;
  ch.p_max = 5;
  ch.direction = Direction::both;
  const SceneBranch r = restart(run, 1, ch);
  EXPECT_EQ(r.spec.parameter, P::B);
  EXPECT_EQ(r.problem_scene.parameters.C, 0.08);
  const Branch& b = r.branch.branch;
  const auto start =
      std::find_if(b.points.begin(), b.points.end(), [](const BranchPoint& q) { return q.arclength == 0; });
  ASSERT_NE(start, b.points.end());
  EXPECT_LT(max_diff(start->x, modal_run().branch.branch.points.front().x), 1e-12);
  const SpecialPoint* bp = find_special_point(b, SpecialPointType::BP);
  ASSERT_NE(bp, nullptr);
  BranchSpec fresh =
      test::spec_of(modal_fixtures::scene(0.1, 6), ProblemKind::modal, P::C, 0.05, 0.1, Direction::backward);
  fresh.scene.parameters.B = bp->p;
  const SceneBranch f = continue_scene(fresh);
  const SpecialPoint* fbp = find_special_point(f.branch.branch, SpecialPointType::BP);
  ASSERT_NE(fbp, nullptr);
  EXPECT_NEAR(fbp->p, 0.08, 1e-9);
  // A parameter outside the new bounds, and a kind that is not the run's, are refused.
  ch.p_max = 0.9;
  EXPECT_EQ(test::invalid_parameter([&] { (void)restart_spec(run, 1, ch); }), "min");
  RestartChanges kind;
  kind.kind = ProblemKind::full;
  EXPECT_EQ(test::invalid_parameter([&] { (void)restart_spec(run, 1, kind); }), "kind");
}

TEST(BranchSwitch, AtTheLabelledOnsetBPIsThePostInstabilityBranch) {
  // The run: both ways from C = 0.05 over [0.01, 0.1]; the first BP met is the onset C = 0.0361689
  // (the ellipsoid stable above it), not the l = 6 BP at C = 0.0137 that comes first along the branch.
  BranchSpec s = test::spec_of(modal_fixtures::scene(0.05, 6), ProblemKind::modal, P::C, 0.01, 0.1, Direction::both);
  s.switch_at_bp = true;
  const SceneBranch r = continue_scene(s);
  const Branch& b = r.branch.branch;
  ASSERT_EQ(b.special_points.size(), 4u);
  const int k = first_bp_met(b, Direction::both);
  EXPECT_EQ(k, 4);
  const SpecialPoint& onset = *find_special_point(b, SpecialPointType::BP, k);
  EXPECT_NEAR(onset.p, 0.0361689351, 1e-9);
  EXPECT_EQ(onset.unstable_before, 1);  // C increasing: unstable below the onset, stable above
  EXPECT_EQ(onset.unstable_after, 0);
  EXPECT_EQ(first_bp_met(b, Direction::forward), 1);
  ASSERT_TRUE(r.switched && r.switched->switched);
  EXPECT_EQ(r.switched->bp_number, 4);
  EXPECT_EQ(r.switched->bp_label, r.branch.special_labels[3]);
  // sigma pinned at sigma_3^c = -(12 + 4 alpha / 12), alpha = B / C, at every point of the switched branch.
  const MeasuredBranch& sw = r.switched->branch;
  ASSERT_GT(sw.branch.points.size(), 10u);
  for (std::size_t i = 0; i < sw.branch.points.size(); ++i) {
    const double alpha = 1.0 / sw.branch.points[i].p;
    EXPECT_NEAR(sw.number(i, "sigma"), -(12 + 4 * alpha / 12), 1e-10) << i;
  }
  EXPECT_GT(sw.number(sw.branch.points.size() - 1, "Delta_3"), 0.5);

  // From the saved run, --switch-at that label: the same branch, bit for bit, labelled after the run's.
  const ContinuationRun saved = round_trip(r);
  const SceneBranch again = switch_at_label(saved, r.switched->bp_label);
  ASSERT_TRUE(again.switched && again.switched->switched);
  EXPECT_EQ(again.switched->branch.branch.points.size(), sw.branch.points.size());
  for (std::size_t i = 0; i < sw.branch.points.size(); ++i)
    EXPECT_TRUE(again.switched->branch.branch.points[i].x == sw.branch.points[i].x) << i;
  EXPECT_EQ(again.switched->branch.point_labels.front(), std::max(r.branch.last_label(), sw.last_label()) + 1);
  EXPECT_NE(to_text(again).find("switched at BP label " + std::to_string(r.switched->bp_label) + " at C = 0.03616893"),
            std::string::npos)
      << to_text(again);
  // The l = 4 BP of the run: its branch has sigma pinned at sigma_4^c = -(20 + 4 alpha / 20).
  const SceneBranch l4 = switch_at_label(saved, r.branch.special_labels[2]);
  ASSERT_TRUE(l4.switched && l4.switched->switched) << l4.switched->message;
  EXPECT_NEAR(l4.switched->branch.branch.points.front().p, 0.0262932, 1e-6);
  for (std::size_t i = 0; i < l4.switched->branch.branch.points.size(); ++i) {
    const double alpha = 1.0 / l4.switched->branch.branch.points[i].p;
    EXPECT_NEAR(l4.switched->branch.number(i, "sigma"), -(20 + 4 * alpha / 20), 1e-10) << i;
  }

  // Labels that are not BPs, a label the run does not have, a parameter other than the branch's.
  std::string m;
  EXPECT_EQ(test::invalid_parameter([&] { (void)switch_at_label(saved, 1); }, &m), "switch_at");
  EXPECT_NE(m.find("switch_at = 1 is a point of type EP, not a BP (branch point): the BP labels of this run are"),
            std::string::npos)
      << m;
  EXPECT_EQ(test::invalid_parameter([&] { (void)switch_at_label(saved, 999); }, &m), "switch_at");
  EXPECT_NE(m.find("switch_at = 999 is not a label of this run: its labels are 1 to "), std::string::npos) << m;
  EXPECT_EQ(test::invalid_parameter([&] { (void)restart(saved, 999); }, &m), "label");
  RestartChanges lam;
  lam.parameter = P::lambda;
  EXPECT_EQ(test::invalid_parameter([&] { (void)switch_at_label(saved, r.switched->bp_label, lam); }), "parameter");
  EXPECT_EQ(test::invalid_parameter([&] { (void)switch_at_label(round_trip(orbit_run()), 1); }, &m), "switch_at");
  EXPECT_NE(m.find("not orbit: the reduced in-plane orbit has no BP"), std::string::npos) << m;
}

TEST(BranchSwitch, ModalOrbitAtItsBPIsTheOrbitASimulationRelaxesTo) {
  // The in-plane ellipsoidal modal orbit (delta = 0: every a_l exactly 0) continued in C down to 0.05 has a
  // BP at C = 0.0623 (multiplier of a_3 crossing 1); the switched branch ends at C = 0.05 on the
  // post-instability orbit, which a modal run relaxed from a perturbed scene with the same total excess
  // area (Delta = 0.998 + 2 delta, delta = 1e-3) finds by itself.
  Scene sc = modal_fixtures::scene(0.07, 4);
  sc.beta = M_PI / 2;
  sc.parameters.B = 2;
  sc.delta = 0;
  BranchSpec s = test::spec_of(sc, ProblemKind::modal_orbit, P::C, 0.05, 0.08, Direction::backward);
  s.relax_T = 600;
  s.orbit.segments = 2;
  s.switch_at_bp = true;
  const SceneBranch r = continue_scene(s);
  ASSERT_TRUE(r.switched && r.switched->switched) << (r.switched ? r.switched->message : "");
  const MeasuredBranch& sw = r.switched->branch;
  EXPECT_EQ(sw.branch.points.back().p, 0.05);
  Scene relaxed = sc;
  relaxed.parameters.C = 0.05;
  relaxed.parameters.Delta = 0.998;
  relaxed.delta = 1e-3;
  BranchSpec d = test::spec_of(relaxed, ProblemKind::modal_orbit, P::C, 0.05, 0.051, Direction::forward);
  d.relax_T = 600;
  d.orbit.segments = 2;
  d.engine.max_points = 2;
  const SceneBranch direct = continue_scene(d);
  ASSERT_TRUE(direct.start.converged) << direct.start.message;
  const std::size_t last = sw.branch.points.size() - 1;
  for (const char* m : {"r", "Psi", "sigma", "Delta_2", "Delta_3"})
    EXPECT_NEAR(sw.number(last, m), direct.branch.number(0, m), 1e-10) << m;
  EXPECT_GT(sw.number(last, "Delta_3"), 0.5);
  EXPECT_TRUE(sw.branch.points.back().stable);
}

TEST(BranchRestart, CurveLabelsRestartTheirBranchAndTheirCurve) {
  const ContinuationRun run = round_trip(modal_curve());
  const SceneCurve& c = modal_curve();
  // Labels: the one-parameter branch first, then the curve.
  const std::vector<LabelledPoint> all = labelled_points(run);
  ASSERT_FALSE(all.empty());
  EXPECT_EQ(all.front().branch, 1);
  EXPECT_EQ(all.back().branch, 2);
  // A point of the BP curve at B = B_k: the branch in C at that B from it has its BP at the point's C.
  const LabelledPoint lp = regular_label(run, 2, 5);
  const std::vector<double>& pq = c.curve.branch.points[lp.index].parameters;
  RestartChanges ch;
  ch.p_min = pq[0] - 0.005;
  ch.p_max = pq[0] + 0.005;
  ch.direction = Direction::both;
  const SceneBranch one = restart(run, lp.label, ch);
  EXPECT_EQ(one.spec.parameter, P::C);
  EXPECT_EQ(one.problem_scene.parameters.B, pq[1]);
  // The start is that BP: both halves of the branch meet it, and it is reported once, with the unstable
  // counts of either side.
  const Branch& ob = one.branch.branch;
  ASSERT_EQ(ob.special_points.size(), 1u);
  EXPECT_EQ(ob.special_points[0].type, SpecialPointType::BP);
  EXPECT_NEAR(ob.special_points[0].p, pq[0], 1e-9);
  EXPECT_EQ(ob.points[ob.special_points[0].after_index].n_unstable, ob.special_points[0].unstable_before);
  EXPECT_EQ(ob.points[ob.special_points[0].after_index + 1].n_unstable, ob.special_points[0].unstable_after);
  // The curve again from that point: it lands on the same ends (B = 0.8 and 1.2) at the same C.
  const SceneCurve again = restart_curve(run, lp.label, test::curve_of(CurveKind::BP, P::B, 0.8, 1.2));
  ASSERT_TRUE(again.started) << again.message;
  EXPECT_EQ(again.system, CurveSystem::modal_branch_point);
  const Branch &a = c.curve.branch, &b = again.curve.branch;
  EXPECT_EQ(b.points.front().parameters[1], 0.8);
  EXPECT_EQ(b.points.back().parameters[1], 1.2);
  EXPECT_NEAR(b.points.front().parameters[0], a.points.front().parameters[0], 1e-10);
  EXPECT_NEAR(b.points.back().parameters[0], a.points.back().parameters[0], 1e-10);
  // And from the BP label of the one-parameter branch.
  int bp_label = 0;
  for (const LabelledPoint& p : all)
    if (p.branch == 1 && p.type == "BP" && !bp_label) bp_label = p.label;
  const SceneCurve from_bp = restart_curve(run, bp_label, test::curve_of(CurveKind::BP, P::B, 0.8, 1.2));
  ASSERT_TRUE(from_bp.started) << from_bp.message;
  EXPECT_NEAR(from_bp.curve.branch.points.back().parameters[0], a.points.back().parameters[0], 1e-10);
  // A curve of another type, and switching at a point of the curve, are refused naming the flag.
  std::string m;
  EXPECT_EQ(test::invalid_parameter(
                [&] { (void)restart_curve(run, lp.label, test::curve_of(CurveKind::LP, P::B, 0.8, 1.2)); }, &m),
            "label");
  EXPECT_NE(m.find("is a point of a BP curve: --curve LP starts from a point of type LP or a point of a LP curve"),
            std::string::npos)
      << m;
  EXPECT_EQ(test::invalid_parameter([&] { (void)switch_at_label(run, lp.label); }, &m), "switch_at");
  EXPECT_NE(m.find("is a point of the BP curve, not a BP of a one-parameter branch"), std::string::npos) << m;
}

}  // namespace
}  // namespace rbcstab
