#pragma once
// The run table of the label-restart tests (restart_table_test.cpp: each label to the next label's value;
// hard_branches_slow_test.cpp: every label to every label's value): reduced, modal and full equilibria, the
// in-plane orbit, LP, BP, HB and UZ curves, each round-tripped through its branch file by the test.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "continuation/fig2_fixture.hpp"
#include "continuation/full_fixtures.hpp"
#include "continuation/modal_fixtures.hpp"
#include "continuation/scene_spec_fixture.hpp"
#include "rbcstab/continuation/branch_file.hpp"
#include "rbcstab/continuation/branch_labels.hpp"
#include "rbcstab/continuation/scene_curve.hpp"
#include "rbcstab/continuation/scene_restart.hpp"

namespace rbcstab::restart_table {

using P = ContinuationParameter;

inline ContinuationRun round_trip(const ContinuationRun& run) {
  return parse_branch_file(branch_file_json(run).dump(1), "t.json");
}

inline const MeasuredBranch& branch_no(const ContinuationRun& run, int b) {
  if (const SceneCurve* c = std::get_if<SceneCurve>(&run)) return b == 2 ? c->curve : c->one.branch;
  const SceneBranch& s = std::get<SceneBranch>(run);
  return b == 2 ? s.switched->branch : s.branch;
}

// The labelled point's parameter values (a curve point: both), as stored.
inline const std::vector<double>& values_of(const ContinuationRun& run, const LabelledPoint& lp) {
  const Branch& b = branch_no(run, lp.branch).branch;
  return lp.special ? b.special_points[lp.index].parameters : b.points[lp.index].parameters;
}

inline bool holds_value(const Branch& b, std::size_t slot, double v) {
  return std::any_of(b.points.begin(), b.points.end(), [&](const BranchPoint& q) { return q.parameters[slot] == v; });
}

struct Tally {
  int restarts = 0;
  std::vector<std::string> failures;
  void fail(const LabelledPoint& lp, double from, double to, const std::string& why) {
    std::ostringstream os;
    os.precision(17);
    os << "label " << lp.label << " (" << (lp.type.empty() ? "regular" : lp.type) << ", branch " << lp.branch << ") at "
       << from << " to " << to << ": " << why;
    failures.push_back(os.str());
  }
};

// The labels a restart from labels[i] goes to (the run's parameter, or slot 1 of a curve's: parameter2): every
// other label with another value, or (all = false) only the next such label in label order, cyclically, so
// that every label is restarted from and every label's value is reached once.
inline std::vector<LabelledPoint> targets(const ContinuationRun& run, const std::vector<LabelledPoint>& labels,
                                          std::size_t i, std::size_t slot, bool all) {
  std::vector<LabelledPoint> out;
  const double v0 = values_of(run, labels[i])[slot];
  for (std::size_t k = 1; k < labels.size(); ++k) {
    const LabelledPoint& to = labels[(i + k) % labels.size()];
    if (values_of(run, to)[slot] == v0) continue;
    out.push_back(to);
    if (!all) break;
  }
  return out;
}

// Restarts of the one-parameter branch (branch 1) from each label to each other label's value.
inline void restart_branch_labels(const ContinuationRun& run, Tally& t, bool all) {
  std::vector<LabelledPoint> labels = labelled_points(run);
  labels.erase(std::remove_if(labels.begin(), labels.end(), [](const LabelledPoint& q) { return q.branch != 1; }),
               labels.end());
  for (std::size_t i = 0; i < labels.size(); ++i) {
    const LabelledPoint& lp = labels[i];
    const double v0 = values_of(run, lp)[0];
    for (const LabelledPoint& to : targets(run, labels, i, 0, all)) {
      const double v = values_of(run, to)[0];
      RestartChanges ch;
      ch.direction = v > v0 ? Direction::forward : Direction::backward;
      (v > v0 ? ch.p_max : ch.p_min) = v;
      ++t.restarts;
      try {
        const SceneBranch r = restart(run, lp.label, ch);
        const Branch& b = r.branch.branch;
        if (!r.start.converged)
          t.fail(lp, v0, v, "no start: " + r.start.message);
        else if (b.status != ContinuationStatus::completed)
          t.fail(lp, v0, v, "status " + to_string(b.status) + ": " + b.message);
        else if (!holds_value(b, 0, v))
          t.fail(lp, v0, v, "never at the value: " + b.message);
      } catch (const std::exception& e) {
        t.fail(lp, v0, v, std::string("threw: ") + e.what());
      }
    }
  }
}

// Restarts of the curve (branch 2) from each of its labels with a bound in parameter2 at each other label's.
inline void restart_curve_labels(const ContinuationRun& run, Tally& t, bool all) {
  const SceneCurve& c = std::get<SceneCurve>(run);
  std::vector<LabelledPoint> labels = labelled_points(run);
  labels.erase(std::remove_if(labels.begin(), labels.end(), [](const LabelledPoint& q) { return q.branch != 2; }),
               labels.end());
  for (std::size_t i = 0; i < labels.size(); ++i) {
    const LabelledPoint& lp = labels[i];
    const double v0 = values_of(run, lp)[1];
    for (const LabelledPoint& to : targets(run, labels, i, 1, all)) {
      const double v = values_of(run, to)[1];
      ++t.restarts;
      try {
        const SceneCurve r = restart_curve(
            run, lp.label, test::curve_of(c.spec.type, *c.spec.parameter2, std::min(v0, v), std::max(v0, v)));
        if (!r.started)
          t.fail(lp, v0, v, "no start: " + r.message);
        else if (r.curve.branch.status != ContinuationStatus::completed)
          t.fail(lp, v0, v, "status " + to_string(r.curve.branch.status) + ": " + r.curve.branch.message);
        else if (!holds_value(r.curve.branch, 1, v))
          t.fail(lp, v0, v, "never at the value: " + r.curve.branch.message);
      } catch (const std::exception& e) {
        t.fail(lp, v0, v, std::string("threw: ") + e.what());
      }
    }
  }
}

struct Row {
  const char* name;
  std::function<ContinuationRun()> run;
  bool curve = false;
  bool slow = false;   // over 1 s (shooting): in the slow table only
  int min_labels = 3;  // a row whose run lost its labels cannot pass silently
};

// The vesicle limit (S = inf) in lambda: the tank-treading branch folds at Lambda = 1 (LP and BP together).
inline Scene vesicle() {
  Scene s = modal_fixtures::scene(INFINITY, 2);
  s.parameters.lambda = 5;
  s.parameters.Delta = 0.2;
  s.parameters.Delta0 = 0;
  return s;
}

inline BranchSpec full_spec() {
  BranchSpec s = test::spec_of(full_fixtures::forced_scene(0.08, 5, 1e-3), ProblemKind::full, P::C, 0.012, 0.08,
                               Direction::backward);
  s.engine.max_step = 0.05;
  return s;
}

inline std::vector<Row> rows() {
  return {
      {"reduced equilibrium in Lambda",
       [] {
         return continue_scene(test::spec_of(modal_fixtures::scene(0.04, 2), ProblemKind::equilibrium, P::Lambda, 0.5,
                                             3, Direction::both));
       }},
      {"reduced equilibrium through the vesicle fold",
       [] {
         return continue_scene(test::spec_of(vesicle(), ProblemKind::equilibrium, P::lambda, 0, 20, Direction::both));
       }},
      {"modal equilibrium in C",
       [] {
         return continue_scene(
             test::spec_of(modal_fixtures::scene(0.04, 6), ProblemKind::modal, P::C, 0.01, 0.1, Direction::both));
       }},
      {"full equilibrium in C", [] { return continue_scene(full_spec()); }},
      {"in-plane orbit in Delta", [] { return continue_scene(test::orbit_spec()); }, false, true},
      {"LP curve (vesicle fold) in Delta",
       [] {
         return continue_curve(test::spec_of(vesicle(), ProblemKind::equilibrium, P::lambda, 0, 20, Direction::both),
                               test::curve_of(CurveKind::LP, P::Delta, 0.1, 2));
       },
       true},
      {"BP curve (modal onset) in B",
       [] {
         return continue_curve(
             test::spec_of(modal_fixtures::scene(0.04, 6), ProblemKind::modal, P::C, 0.03, 0.04, Direction::both),
             test::curve_of(CurveKind::BP, P::B, 0.5, 2));
       },
       true},
      {"HB curve (full model, l = 4) in B",
       [] { return continue_curve(full_spec(), test::curve_of(CurveKind::HB, P::B, 0.9, 1.1)); }, true},
      {"UZ curve (swinging-tumbling) in lambda",
       [] {
         return continue_curve(
             test::spec_of(test::fig2_in_plane(0.3), ProblemKind::orbit, P::Delta, 0.3, 0.45, Direction::forward),
             test::curve_of(CurveKind::UZ, P::lambda, 4.8, 5.6));
       },
       true, true},
  };
}

}  // namespace rbcstab::restart_table

namespace rbcstab::restart_table {

// The indices of the rows under 1 s.
inline std::vector<std::size_t> fast_rows() {
  std::vector<std::size_t> out;
  const std::vector<Row> all = rows();
  for (std::size_t i = 0; i < all.size(); ++i)
    if (!all[i].slow) out.push_back(i);
  return out;
}

// One row: its run from scratch, round-tripped through its branch file, each label restarted (all: to every
// other label's value; else to the next label's); every restart must succeed.
inline void check_row(std::size_t i, bool all) {
  const Row row = rows()[i];
  const ContinuationRun first = row.run();
  if (const SceneCurve* c = std::get_if<SceneCurve>(&first)) {
    ASSERT_TRUE(c->started) << row.name << ": " << c->message;
  }
  const ContinuationRun run = round_trip(first);
  ASSERT_GE(labelled_points(run).size(), static_cast<std::size_t>(row.min_labels)) << row.name;
  Tally t;
  if (row.curve)
    restart_curve_labels(run, t, all);
  else
    restart_branch_labels(run, t, all);
  EXPECT_GE(t.restarts, 2) << row.name;
  for (const std::string& f : t.failures) ADD_FAILURE() << row.name << ": " << f;
  std::printf("%s: %d restarts, %zu failed\n", row.name, t.restarts, t.failures.size());
}

}  // namespace rbcstab::restart_table
