// Monitors (monitors.hpp: UZ points and stops where a parameter or a measure reaches a value) and the tunable
// options (tunable_options.hpp: each refused naming the option, its value and its range).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <variant>
#include <vector>

#include "continuation/invalid_argument_fixture.hpp"
#include "continuation/modal_fixtures.hpp"
#include "continuation/scene_spec_fixture.hpp"
#include "rbcstab/continuation/branch_file.hpp"
#include "rbcstab/continuation/branch_spec.hpp"
#include "rbcstab/continuation/monitors.hpp"
#include "rbcstab/continuation/scene_branch.hpp"
#include "rbcstab/continuation/scene_curve.hpp"
#include "rbcstab/continuation/scene_measures.hpp"
#include "rbcstab/continuation/scene_restart.hpp"
#include "rbcstab/continuation/tunable_options.hpp"
#include "rbcstab/core/error.hpp"

namespace rbcstab {
namespace {

using P = ContinuationParameter;
using test::invalid_parameter;

// The reduced out-of-plane equilibrium in lambda over [0.5, 3] (measures r, Psi).
BranchSpec equilibrium_spec(Direction d = Direction::both) {
  return test::spec_of(modal_fixtures::scene(0.08, 2), ProblemKind::equilibrium, P::lambda, 0.5, 3, d);
}

// The UZ points named `name`.
std::vector<std::size_t> uz_named(const MeasuredBranch& m, const std::string& name) {
  std::vector<std::size_t> k;
  for (std::size_t i = 0; i < m.branch.special_points.size(); ++i)
    if (m.branch.special_points[i].type == SpecialPointType::UZ && m.branch.special_points[i].name == name)
      k.push_back(i);
  return k;
}

// Oracle: the measure evaluated afresh at the located point (special_measures: the scene problem's measures of
// its state, not the event's value during location). The point is located until its bracket spans < 1e-11
// (location_tol) in (x, p); Psi's gradient in x is O(1 / r) with r = O(1) here: 1e-9. lambda is the point's
// own coordinate: within the bracket, 1e-10.
TEST(Monitor, LabelsAUZPointWhereAMeasureOrAParameterReachesEachValue) {
  const SceneBranch plain = continue_scene(equilibrium_spec());
  const MeasuredBranch& m0 = plain.branch;
  ASSERT_GT(m0.branch.points.size(), 5u);
  const double a = m0.number(0, "Psi"), b = m0.number(m0.branch.points.size() - 1, "Psi");
  ASSERT_GT(std::abs(b - a), 1e-3);
  const double v1 = a + (b - a) / 3, v2 = a + 2 * (b - a) / 3;
  BranchSpec spec = equilibrium_spec();
  Monitor psi;
  psi.name = "Psi";
  psi.values = {v1, v2};
  spec.monitors = {psi, parse_monitor("lambda=1.7", false)};
  const SceneBranch r = continue_scene(spec);
  const MeasuredBranch& m = r.branch;
  ASSERT_EQ(m.branch.status, ContinuationStatus::completed) << m.branch.message;
  // Monitors only label: the branch's points are those of the run without them.
  ASSERT_EQ(m.branch.points.size(), m0.branch.points.size());
  for (std::size_t k = 0; k < m.branch.points.size(); ++k) EXPECT_EQ(m.branch.points[k].p, m0.branch.points[k].p);
  for (double v : {v1, v2}) {
    const std::vector<std::size_t> found = uz_named(m, monitor_event_name(psi, v));
    ASSERT_EQ(found.size(), 1u) << v;
    const SpecialPoint& sp = m.branch.special_points[found[0]];
    EXPECT_EQ(sp.status, LocationStatus::located);
    const double at = std::get<double>(m.special_measures[found[0]][1]);  // Psi
    std::printf("Psi = %.15f: located Psi %.15f (%.1e), label %d\n", v, at, at - v, m.special_label(found[0]));
    EXPECT_NEAR(at, v, 1e-9);
    EXPECT_GT(m.special_label(found[0]), 0);  // labelled, so a restart can start there
  }
  const std::vector<std::size_t> l = uz_named(m, "lambda=1.7");
  ASSERT_EQ(l.size(), 1u);
  EXPECT_NEAR(m.branch.special_points[l[0]].p, 1.7, 1e-10);
}

// A stop ends the direction it is met in at the located point: status completed, the message says why, the
// last point is the located one (same oracle and tolerance as above). The other direction is not affected.
TEST(Monitor, StopAtEndsTheRunThereWithStatusCompleted) {
  const SceneBranch plain = continue_scene(equilibrium_spec(Direction::forward));
  const MeasuredBranch& m0 = plain.branch;
  const std::size_t n0 = m0.branch.points.size();
  const double v = m0.number(n0 / 2, "Psi") + 0.25 * (m0.number(n0 / 2 + 1, "Psi") - m0.number(n0 / 2, "Psi"));
  BranchSpec spec = equilibrium_spec(Direction::forward);
  Monitor stop;
  stop.name = "Psi";
  stop.values = {v};
  stop.stop = true;
  spec.monitors = {stop};
  const SceneBranch r = continue_scene(spec);
  const MeasuredBranch& m = r.branch;
  EXPECT_EQ(m.branch.status, ContinuationStatus::completed);
  EXPECT_EQ(m.branch.message, "stopped at " + monitor_event_name(stop, v));
  const std::size_t last = m.branch.points.size() - 1;
  EXPECT_EQ(last, n0 / 2 + 1);  // the step that crossed it ends at the crossing
  EXPECT_NEAR(m.number(last, "Psi"), v, 1e-9);
  EXPECT_LT(m.branch.points[last].p, m0.branch.points[n0 / 2 + 1].p);
  const std::vector<std::size_t> found = uz_named(m, monitor_event_name(stop, v));
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(m.branch.special_points[found[0]].p, m.branch.points[last].p);
  EXPECT_EQ(m.point_type(last), "EP");
  EXPECT_NE(m.branch.points[last].stability, Stability::uncertain);
}

TEST(Monitor, RefusesWhatItCannotMonitor) {
  std::string msg;
  EXPECT_EQ(invalid_parameter([] { parse_monitor("Psi", false); }, &msg), "monitor");
  EXPECT_NE(msg.find("'Psi' is not NAME=V1,V2,..."), std::string::npos) << msg;
  EXPECT_EQ(invalid_parameter([] { parse_monitor("Psi=1,x", false); }, &msg), "monitor");
  EXPECT_NE(msg.find("'x'"), std::string::npos) << msg;
  EXPECT_EQ(invalid_parameter([] { parse_monitor("Psi=1,2", true, "stop_at"); }, &msg), "stop_at");
  EXPECT_EQ(invalid_parameter([] { parse_monitor("Psi=inf", false); }), "monitor");
  EXPECT_EQ(parse_monitor("Delta_2=0.5,0.8", false).values, (std::vector<double>{0.5, 0.8}));
  BranchSpec spec = equilibrium_spec();
  spec.monitors = {parse_monitor("Psi=1", false), parse_monitor("Psi=1", true)};
  EXPECT_EQ(invalid_parameter([&] { spec.validate(); }, &msg), "monitor");
  EXPECT_NE(msg.find("Psi=1 is given twice"), std::string::npos) << msg;
  spec.monitors = {parse_monitor("sigma=1", false)};  // not a measure of the reduced equilibrium
  EXPECT_EQ(invalid_parameter([&] { (void)continue_scene(spec); }, &msg), "monitor");
  EXPECT_NE(msg.find("unknown monitor 'sigma' (this branch has: lambda"), std::string::npos) << msg;
  EXPECT_EQ(parse_monitors({"Psi=1,2", "none"}, {"r=0.5"}).size(), 2u);
  EXPECT_TRUE(parse_monitors({"none"}, {}).empty());
  EXPECT_EQ(monitor_text(parse_monitor("Delta_2=0.5,0.8", false)), "Delta_2=0.5,0.8");
  EXPECT_EQ(invalid_parameter([] { parse_monitors({}, {"r=1,2"}, "m", "continuation.stop_at"); }),
            "continuation.stop_at");
}

// The midpoint of a measure between two consecutive points of one direction of m (a value crossed between them:
// the monitor's event changes sign there), the middle such pair; k_out: its first point. NaN if m has none.
double crossed_between(const MeasuredBranch& m, const std::string& name, std::size_t* k_out = nullptr) {
  std::vector<std::size_t> pairs;
  const auto& pts = m.branch.points;
  for (std::size_t i = 0; i + 1 < pts.size(); ++i)
    if (pts[i].arclength * pts[i + 1].arclength > 0 && std::abs(pts[i + 1].arclength) > std::abs(pts[i].arclength))
      pairs.push_back(i);
  if (pairs.empty()) return NAN;
  const std::size_t k = pairs[pairs.size() / 2];
  if (k_out) *k_out = k;
  return 0.5 * (m.number(k, name) + m.number(k + 1, name));
}

// Monitors on a curve (the modal BP curve of l = 4 in (C, B)): a UZ point where the curve's second parameter B,
// its first parameter C or a measure (r) reaches the value; the branch the curve starts from has none. Oracle:
// the located point's parameters and its measures evaluated afresh equal the targets; the point is located
// until its bracket spans < 1e-11 in (X, B) with O(1) gradients: 1e-9. A wrong point fails it: the nearest
// regular curve points are farther than that from the target.
TEST(Monitor, OnACurveLabelsWhereAParameterOrAMeasureReachesItsValue) {
  BranchSpec spec = test::modal_spec(4, 0.02);
  const CurveSpec cs = test::curve_of(CurveKind::BP, P::B, 0.8, 1.2);
  const SceneCurve plain = continue_curve(spec, cs);
  ASSERT_TRUE(plain.started) << plain.message;
  const MeasuredBranch& m0 = plain.curve;
  ASSERT_GT(m0.branch.points.size(), 6u);
  ASSERT_EQ(m0.branch.parameter_names, (std::vector<std::string>{"C", "B"}));
  ASSERT_EQ(m0.measure_names.at(0), "r");
  std::size_t k = 0;
  const double r = crossed_between(m0, "r", &k);
  ASSERT_TRUE(std::isfinite(r));
  const double C = 0.5 * (m0.branch.points[k].parameters[0] + m0.branch.points[k + 1].parameters[0]);
  const double B = 0.5 * (m0.branch.points[k].parameters[1] + m0.branch.points[k + 1].parameters[1]);
  ASSERT_GT(std::abs(m0.number(k, "r") - r), 1e-7);
  ASSERT_GT(std::abs(m0.branch.points[k].parameters[0] - C), 1e-7);
  spec.monitors = {parse_monitor("B=" + format_value(B), false), parse_monitor("C=" + format_value(C), false),
                   parse_monitor("r=" + format_value(r), false)};
  const SceneCurve c = continue_curve(spec, cs);
  ASSERT_TRUE(c.started) << c.message;
  for (std::size_t i = 0; i < c.one.branch.branch.special_points.size(); ++i)
    EXPECT_NE(c.one.branch.branch.special_points[i].type, SpecialPointType::UZ);
  const MeasuredBranch& m = c.curve;
  EXPECT_EQ(m.branch.points.size(), m0.branch.points.size());  // monitors only label
  const double targets[] = {B, C, r};
  for (std::size_t j = 0; j < 3; ++j) {
    const std::vector<std::size_t> found = uz_named(m, monitor_event_name(spec.monitors[j], targets[j]));
    ASSERT_GE(found.size(), 1u) << spec.monitors[j].name;
    for (std::size_t f : found) {
      const SpecialPoint& sp = m.branch.special_points[f];
      EXPECT_EQ(sp.status, LocationStatus::located);
      EXPECT_GT(m.special_label(f), 0);
      const double at = j == 0   ? sp.parameters[1]
                        : j == 1 ? sp.parameters[0]
                                 : std::get<double>(m.special_measures[f][0]);
      std::printf("curve monitor %s = %.15g: located %.15g (%.1e)\n", spec.monitors[j].name.c_str(), targets[j], at,
                  at - targets[j]);
      EXPECT_NEAR(at, targets[j], 1e-9);
    }
  }
  // Stopped where B reaches the value: both directions end there or at their own end.
  spec.monitors = {parse_monitor("B=" + format_value(B), true)};
  const SceneCurve stopped = continue_curve(spec, cs);
  ASSERT_TRUE(stopped.started);
  EXPECT_EQ(stopped.curve.branch.status, ContinuationStatus::completed) << stopped.curve.branch.message;
  EXPECT_LT(stopped.curve.branch.points.size(), m0.branch.points.size());
}

// Each tunable option: the default valid, a value outside its range refused naming the option, the value and
// the range; the CLI's flags and Python's keywords come from the same rows.
TEST(TunableOptions, EachIsRefusedOutsideItsRangeNamingIt) {
  for (const TunableOption& t : tunable_options()) {
    EXPECT_NO_THROW(t.check(t.default_value())) << t.name;
    ContinuationOptions e;
    OrbitOptions o;
    EXPECT_EQ(t.get(e, o), t.default_value());
    const double bad = std::isfinite(t.domain.hi) ? t.domain.hi * 10 + 1 : -1;
    std::string msg;
    EXPECT_EQ(invalid_parameter([&] { t.check(bad); }, &msg), t.name);
    EXPECT_NE(msg.find(format_value(bad)), std::string::npos) << msg;
    EXPECT_NE(msg.find(t.range()), std::string::npos) << msg;
    t.set(e, o, bad);
    EXPECT_EQ(invalid_parameter([&] { t.orbit ? o.validate() : e.validate(); }), t.name);
    if (t.integer) {
      EXPECT_EQ(invalid_parameter([&] { t.check(t.default_value() + 0.5); }), t.name);
    }
  }
  std::string msg;
  EXPECT_EQ(invalid_parameter([] { tunable_option("ntst"); }, &msg), "option");
  EXPECT_EQ(std::string(tunable_option("newton_tol").flag), "--newton-tol");
  ContinuationOptions e;
  e.newton_tol = 0.5;
  EXPECT_EQ(invalid_parameter([&] { e.validate(); }, &msg), "newton_tol");
  EXPECT_NE(msg.find("newton_tol = 0.5 is out of range: must be in (0, 0.01)"), std::string::npos) << msg;
}

// A branch file keeps the run's monitors (not a function's: it cannot be saved); a restart labels the same
// points, replaces them when given others and drops them when given none; it takes any tunable option, checked
// against its range, but no other number of segments. A function monitor (a front end's callable) labels its
// zero: lambda = 1.2 to the location tolerance (1e-11 in (x, p); lambda is the point's own coordinate: 1e-10).
TEST(Monitor, RestartKeepsReplacesOrDropsTheRunsMonitors) {
  BranchSpec spec = equilibrium_spec();
  Monitor f;
  f.name = "f";
  f.function = [](const std::map<std::string, double>& point) { return point.at("lambda") - 1.2; };
  spec.monitors = {parse_monitor("lambda=1.7", false), parse_monitor("lambda=2.9", true), f};
  const SceneBranch run = continue_scene(spec);
  ASSERT_EQ(uz_named(run.branch, "f").size(), 1u);
  EXPECT_NEAR(run.branch.branch.special_points[uz_named(run.branch, "f")[0]].p, 1.2, 1e-10);
  const ContinuationRun saved = parse_branch_file(branch_file_json(run).dump(), "test");
  const std::vector<Monitor>& kept = std::get<SceneBranch>(saved).spec.monitors;
  ASSERT_EQ(kept.size(), 2u);
  EXPECT_EQ(monitor_text(kept[0]), "lambda=1.7");
  EXPECT_TRUE(kept[1].stop && !kept[0].stop);
  const auto top = [](const SceneBranch& b) {
    double p = -INFINITY;
    for (const BranchPoint& q : b.branch.branch.points) p = std::max(p, q.p);
    return p;
  };
  const SceneBranch again = restart(saved, 1);
  EXPECT_EQ(uz_named(again.branch, "lambda=1.7").size(), 1u);
  EXPECT_NEAR(top(again), 2.9, 1e-10);  // the saved stop
  RestartChanges ch;
  ch.monitors = std::vector<Monitor>{parse_monitor("lambda=2.2", false)};
  ch.tuned = {{"newton_tol", 1e-10}, {"max_step", 0.2}, {"segments", 8}};
  const SceneBranch replaced = restart(saved, 1, ch);
  EXPECT_TRUE(uz_named(replaced.branch, "lambda=1.7").empty());
  EXPECT_EQ(uz_named(replaced.branch, "lambda=2.2").size(), 1u);
  EXPECT_EQ(top(replaced), 3);  // no stop: the bound
  EXPECT_EQ(replaced.spec.engine.newton_tol, 1e-10);
  EXPECT_EQ(replaced.spec.engine.max_step, 0.2);
  ch.monitors = std::vector<Monitor>{};
  const SceneBranch dropped = restart(saved, 1, ch);
  for (const SpecialPoint& sp : dropped.branch.branch.special_points) EXPECT_NE(sp.type, SpecialPointType::UZ);
  std::string msg;
  ch.tuned = {{"newton_tol", 0.5}};
  EXPECT_EQ(invalid_parameter([&] { (void)restart_spec(saved, 1, ch); }, &msg), "newton_tol");
  EXPECT_NE(msg.find("newton_tol = 0.5 is out of range: must be in (0, 0.01)"), std::string::npos) << msg;
  ch.tuned = {{"segments", 4}};
  EXPECT_EQ(invalid_parameter([&] { (void)restart_spec(saved, 1, ch); }, &msg), "segments");
  EXPECT_NE(msg.find("segments = 4 cannot change on a restart (the run's: 8)"), std::string::npos) << msg;
  ch.tuned = {{"ntst", 4}};
  EXPECT_EQ(invalid_parameter([&] { (void)restart_spec(saved, 1, ch); }), "option");
}

// The run's monitors label the branch switched to at its BP too. Oracle as above (r afresh at the located
// point, 1e-9).
TEST(Monitor, LabelsTheSwitchedBranch) {
  BranchSpec spec = test::modal_spec(4, 0.02);
  spec.switch_at_bp = true;
  const SceneBranch plain = continue_scene(spec);
  ASSERT_TRUE(plain.switched && plain.switched->switched) << (plain.switched ? plain.switched->message : "");
  const double r = crossed_between(plain.switched->branch, "r");
  ASSERT_TRUE(std::isfinite(r));
  spec.monitors = {parse_monitor("r=" + format_value(r), false)};
  const SceneBranch run = continue_scene(spec);
  ASSERT_TRUE(run.switched && run.switched->switched);
  const MeasuredBranch& m = run.switched->branch;
  const std::vector<std::size_t> found = uz_named(m, monitor_event_name(spec.monitors[0], r));
  ASSERT_GE(found.size(), 1u);
  for (std::size_t f : found) {
    EXPECT_NEAR(std::get<double>(m.special_measures[f][0]), r, 1e-9);
    EXPECT_GT(m.special_label(f), 0);
  }
}

}  // namespace
}  // namespace rbcstab
