// Monitors (monitors.hpp: UZ points and stops where a parameter or a measure reaches a value) and the tunable
// options (tunable_options.hpp: each refused naming the option, its value and its range).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "continuation/invalid_argument_fixture.hpp"
#include "continuation/modal_fixtures.hpp"
#include "continuation/scene_spec_fixture.hpp"
#include "rbcstab/continuation/branch_spec.hpp"
#include "rbcstab/continuation/monitors.hpp"
#include "rbcstab/continuation/scene_branch.hpp"
#include "rbcstab/continuation/scene_curve.hpp"
#include "rbcstab/continuation/scene_measures.hpp"
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
  CurveSpec c = test::curve_of(CurveKind::LP, P::Delta, 0.1, 2);
  spec.monitors = {parse_monitor("Psi=1", false)};
  EXPECT_EQ(invalid_parameter([&] { c.validate(spec); }), "monitor");
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

}  // namespace
}  // namespace rbcstab
