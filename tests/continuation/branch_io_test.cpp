// branch_io.hpp: the Branch JSON, CSV and text of continuation results, read back against the result
// they render (keys of the shared schema, every value, the columns and rows of the CSV).
#include <gtest/gtest.h>

#include <algorithm>
#include <iomanip>
#include <sstream>

#include "continuation/scene_spec_fixture.hpp"
#include "rbcstab/continuation/branch_io.hpp"
#include "rbcstab/continuation/continuation_parameter.hpp"
#include "rbcstab/continuation/scene_run.hpp"

namespace rbcstab {
namespace {

using P = ContinuationParameter;

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream ss(text);
  for (std::string line; std::getline(ss, line);) out.push_back(line);
  return out;
}

const SceneBranch& modal_switched() {
  static const SceneBranch r = [] {
    BranchSpec s = test::modal_spec(4, 0.02);
    s.switch_at_bp = true;
    return continue_scene(s);
  }();
  return r;
}

const SceneBranch& orbit_branch() {
  static const SceneBranch r = continue_scene(test::orbit_spec());
  return r;
}

// Every point and special point of a branch JSON holds the result's values under the shared keys.
void expect_branch_json(const nlohmann::json& j, const MeasuredBranch& m, const char* spectrum_key) {
  const Branch& b = m.branch;
  ASSERT_EQ(j.at("branch").size(), b.points.size());
  for (std::size_t k = 0; k < b.points.size(); ++k) {
    const nlohmann::json& pt = j.at("branch")[k];
    EXPECT_EQ(pt.at(b.parameter_names[0]).get<double>(), b.points[k].p);
    EXPECT_EQ(pt.at("stable").get<bool>(), b.points[k].stable);
    EXPECT_EQ(pt.at("n_unstable").get<int>(), b.points[k].n_unstable);
    ASSERT_EQ(pt.at(spectrum_key).size(), static_cast<std::size_t>(b.points[k].spectrum.size()));
    EXPECT_EQ(pt.at(spectrum_key)[0][0].get<double>(), b.points[k].spectrum[0].real());
    for (std::size_t i = 0; i < m.measure_names.size(); ++i) {
      const MeasureValue& v = m.point_measures[k][i];
      const nlohmann::json& got = pt.at(m.measure_names[i]);
      if (const double* d = std::get_if<double>(&v))
        EXPECT_EQ(got.get<double>(), *d) << m.measure_names[i];
      else if (const int* n = std::get_if<int>(&v))
        EXPECT_EQ(got.get<int>(), *n) << m.measure_names[i];
      else
        EXPECT_EQ(got.get<std::string>(), std::get<std::string>(v)) << m.measure_names[i];
    }
  }
  ASSERT_EQ(j.at("special_points").size(), b.special_points.size());
  for (std::size_t k = 0; k < b.special_points.size(); ++k) {
    const nlohmann::json& sp = j.at("special_points")[k];
    EXPECT_EQ(sp.at("type"), to_string(b.special_points[k].type));
    EXPECT_EQ(sp.at(b.parameter_names[0]).get<double>(), b.special_points[k].p);
    EXPECT_EQ(sp.at("precision").get<double>(), b.special_points[k].precision);
    for (const char* key : {"name", "bracket", "status", "unstable_before", "unstable_after", "r", "Psi"})
      EXPECT_TRUE(sp.contains(key)) << key;
  }
  EXPECT_EQ(j.at("status"), to_string(b.status));
  EXPECT_EQ(j.at("counters").at("steps").get<std::size_t>(), b.counters.steps);
}

TEST(BranchJson, ModalBranchAndItsSwitchedBranch) {
  const SceneBranch& r = modal_switched();
  ASSERT_TRUE(r.switched && r.switched->switched);
  const nlohmann::json j = to_json(r);
  expect_branch_json(j, r.branch, "eigenvalues");
  EXPECT_EQ(j.at("kind"), "modal");
  EXPECT_EQ(j.at("level"), "modal");
  EXPECT_EQ(j.at("free_parameter"), "C");
  EXPECT_EQ(j.at("beta").get<double>(), 0.0);
  EXPECT_EQ(j.at("parameters").at("B").get<double>(), 1.0);
  EXPECT_FALSE(j.contains("segments"));
  const nlohmann::json& sw = j.at("switched_branch");
  EXPECT_TRUE(sw.at("switched").get<bool>());
  expect_branch_json(sw, r.switched->branch, "eigenvalues");
  // A BP carries no critical eigenvalue (only HB, PD, NS do).
  EXPECT_FALSE(j.at("special_points")[0].contains("critical"));
}

TEST(BranchJson, OrbitCarriesItsOrbitMeasuresAndSegments) {
  const SceneBranch& r = orbit_branch();
  const nlohmann::json j = to_json(r);
  expect_branch_json(j, r.branch, "multipliers");
  EXPECT_EQ(j.at("kind"), "orbit");
  EXPECT_EQ(j.at("level"), "reduced");
  EXPECT_EQ(j.at("segments").get<int>(), 4);
  EXPECT_FALSE(j.contains("switched_branch"));
  EXPECT_EQ(j.at("special_points")[0].at("name"), "swing_tumble");
  EXPECT_TRUE(j.at("branch")[0].contains("trivial_multiplier"));
}

std::vector<std::string> cells_of(const std::string& line) {
  std::vector<std::string> cells;
  std::istringstream ss(line);
  for (std::string c; std::getline(ss, c, ',');) cells.push_back(c);
  if (!line.empty() && line.back() == ',') cells.emplace_back();  // an empty last cell
  return cells;
}

TEST(BranchCsv, ColumnsFollowTheMeasuresAndRowsThePointsAndSpecialPoints) {
  const SceneBranch& m = modal_switched();
  const std::vector<std::string> lines = lines_of(to_csv(m));
  EXPECT_EQ(lines.at(0), "C,branch,r,Psi,sigma,Delta_2,Delta_3,Delta_4,stable,n_unstable,max_Re_eig,label,type");
  // One row per point and per special point, in order along each branch.
  const Branch &b = m.branch.branch, &s = m.switched->branch.branch;
  ASSERT_EQ(lines.size(), 1 + b.points.size() + b.special_points.size() + s.points.size() + s.special_points.size());
  std::vector<std::string> cells = cells_of(lines.at(1));
  ASSERT_EQ(cells.size(), 13u);
  EXPECT_EQ(std::stod(cells[0]), b.points[0].p);  // 17 digits: exact round trip
  EXPECT_EQ(cells[1], "primary");
  EXPECT_EQ(std::stod(cells[4]), m.branch.number(0, "sigma"));
  EXPECT_EQ(cells[11], "1");
  EXPECT_EQ(cells[12], "EP");
  EXPECT_NE(lines.back().find(",switched,"), std::string::npos);
  // The first BP's row follows point after_index; its stability cells are empty.
  const SpecialPoint& bp = b.special_points.at(0);
  cells = cells_of(lines.at(1 + bp.after_index + 1));
  ASSERT_EQ(cells.size(), 13u);
  EXPECT_EQ(std::stod(cells[0]), bp.p);
  EXPECT_EQ(cells[8] + cells[9] + cells[10], "");
  EXPECT_EQ(cells[11], std::to_string(m.branch.special_labels[0]));
  EXPECT_EQ(cells[12], "BP");
  // A regular unlabelled point: empty label and type.
  cells = cells_of(lines.at(3));
  EXPECT_EQ(cells[11] + cells[12], "");

  // Orbits: no branch column, no trivial_multiplier (a JSON-only check of the shooting).
  EXPECT_EQ(lines_of(to_csv(orbit_branch())).at(0),
            "Delta,r,Psi,r_min,r_max,Psi_min,Psi_max,winding,kind,stable,n_unstable,max_abs_multiplier,label,type");
}

// Labels (AUTO's LAB): every special point, the two ends (EP) and every label_every-th point, numbered
// 1, 2, ... along the primary branch and on along the switched one; the JSON carries them.
TEST(BranchLabels, SpecialPointsEndsAndEveryNthPointNumberedAlongTheRun) {
  const SceneBranch& r = modal_switched();
  std::vector<int> seen;
  for (const MeasuredBranch* m : {&r.branch, &r.switched->branch}) {
    const Branch& b = m->branch;
    ASSERT_EQ(m->point_labels.size(), b.points.size());
    ASSERT_EQ(m->special_labels.size(), b.special_points.size());
    std::size_t j = 0;
    for (std::size_t k = 0; k < b.points.size(); ++k) {
      const bool end = k == 0 || k + 1 == b.points.size();
      EXPECT_EQ(m->point_type(k), end ? "EP" : "");
      EXPECT_EQ(m->point_labels[k] > 0, end || k % 10 == 0) << k;
      if (m->point_labels[k] > 0) seen.push_back(m->point_labels[k]);
      for (; j < b.special_points.size() && b.special_points[j].after_index <= k; ++j) {
        EXPECT_GT(m->special_labels[j], 0);
        seen.push_back(m->special_labels[j]);
      }
    }
    EXPECT_EQ(j, b.special_points.size());
  }
  // Unique, and increasing along the run: 1 .. n in walking order.
  for (std::size_t i = 0; i < seen.size(); ++i) EXPECT_EQ(seen[i], static_cast<int>(i) + 1);
  EXPECT_EQ(r.switched->bp_label, r.branch.special_labels[0]);  // backward from 0.08: the first BP met is the first

  const nlohmann::json j = to_json(r);
  EXPECT_EQ(j.at("branch")[0].at("label").get<int>(), 1);
  EXPECT_EQ(j.at("branch")[0].at("type"), "EP");
  EXPECT_TRUE(j.at("branch")[1].at("label").is_null());
  EXPECT_EQ(j.at("branch")[1].at("type"), "");
  EXPECT_EQ(j.at("special_points")[0].at("label").get<int>(), r.branch.special_labels[0]);
  EXPECT_EQ(j.at("switched_branch").at("bp_label").get<int>(), r.switched->bp_label);
  EXPECT_EQ(j.at("switched_branch").at("branch")[0].at("label").get<int>(), r.switched->branch.point_labels[0]);

  // label_every: 0 labels only the ends and the special points; 3 every third point.
  for (int every : {0, 3}) {
    BranchSpec s = test::modal_spec(4, 0.02);
    s.label_every = every;
    const SceneBranch q = continue_scene(s);
    int labelled = 0;
    for (std::size_t k = 0; k < q.branch.branch.points.size(); ++k) labelled += q.branch.point_labels[k] > 0;
    const std::size_t n = q.branch.branch.points.size();
    EXPECT_EQ(labelled, every == 0 ? 2 : static_cast<int>((n - 1) / 3 + 1 + ((n - 1) % 3 != 0)));
  }
  BranchSpec bad = test::modal_spec(4, 0.02);
  bad.label_every = -1;
  EXPECT_EQ(test::invalid_parameter([&] { bad.validate(); }), "label_every");
}

TEST(BranchText, SummarisesTheBranchItsSpecialPointsAndTheSwitch) {
  const SceneBranch& m = modal_switched();
  const std::string t = to_text(m);
  EXPECT_EQ(
      t.rfind(std::to_string(m.branch.branch.points.size()) + " points in C from 0.08 to 0.02, status completed", 0),
      0u)
      << t;
  EXPECT_NE(t.find("\nBP C = 0.03616893"), std::string::npos) << t;
  EXPECT_NE(t.find("switched at the first BP: "), std::string::npos) << t;
  EXPECT_NE(to_text(orbit_branch()).find("swing_tumble Delta = 0.38478"), std::string::npos);
}

// AUTO's b-file table: a header, then one row per labelled point (BR, PT, TY, LAB, the parameter, the
// measures, stability), primary then switched branch; the measures can be chosen.
TEST(BranchText, TableHasOneRowPerLabelledPoint) {
  const SceneBranch& m = modal_switched();
  const std::vector<std::string> lines = lines_of(to_text(m));
  std::size_t head = 0;
  while (head < lines.size() && lines[head].rfind(" BR", 0) != 0) ++head;
  ASSERT_LT(head, lines.size());
  EXPECT_NE(lines[head].find(
                "LAB                C                r              Psi            sigma          Delta_2  stability"),
            std::string::npos)
      << lines[head];
  const int n = std::max(m.branch.last_label(), m.switched->branch.last_label());
  ASSERT_EQ(lines.size(), head + 1 + static_cast<std::size_t>(n));
  // Row of the first BP: branch 1, PT k+ (between points k and k + 1), type, label, C to 10 digits.
  const SpecialPoint& bp = m.branch.branch.special_points[0];
  std::ostringstream row;
  row << "  1" << std::setw(7) << (std::to_string(bp.after_index) + "+") << "  BP" << std::setw(6)
      << m.branch.special_labels[0] << std::setw(17) << std::setprecision(10) << bp.p;
  bool found = false;
  for (std::size_t i = head + 1; i < lines.size(); ++i) found = found || lines[i].rfind(row.str(), 0) == 0;
  EXPECT_TRUE(found) << row.str();
  EXPECT_NE(lines.back().find("  2 "), std::string::npos);
  EXPECT_NE(lines.back().find("EP"), std::string::npos);
  // Chosen measures; an unknown one names the flag and the choices.
  TableOptions table;
  table.measures = {"Delta_3"};
  const std::string t = to_text(m, table);
  EXPECT_NE(t.find("LAB                C          Delta_3  stability"), std::string::npos) << t;
  table.measures = {"nope"};
  std::string message;
  EXPECT_EQ(test::invalid_parameter([&] { (void)to_text(m, table); }, &message), "measures");
  EXPECT_NE(message.find("measures = 'nope' is not a measure of this branch: must be one of r, Psi"), std::string::npos)
      << message;
}

// An empty name in the list was dropped, so "r,,Psi" read as "r,Psi" (found by fuzzing); the empty text is the
// default table.
TEST(BranchText, MeasureListRefusesEmptyNames) {
  EXPECT_EQ(TableOptions::from_list("r,Psi").measures, (std::vector<std::string>{"r", "Psi"}));
  EXPECT_TRUE(TableOptions::from_list("").measures.empty());
  for (const std::string list : {"r,,Psi", "r,", ",r", ","}) {
    std::string message;
    EXPECT_EQ(test::invalid_parameter([&] { (void)TableOptions::from_list(list); }, &message), "measures") << list;
    EXPECT_NE(message.find("measures = '" + list + "' has an empty name"), std::string::npos) << message;
  }
}

TEST(CurveOutput, JsonCsvAndTextOfAModalBPCurve) {
  const SceneCurve c = continue_curve(test::modal_spec(4, 0.02), test::curve_of(CurveKind::BP, P::B, 0.8, 1.2));
  ASSERT_TRUE(c.started) << c.message;
  const nlohmann::json j = to_json(c);
  EXPECT_EQ(j.at("free_parameter"), "B");
  EXPECT_EQ(j.at("level"), "modal");
  const nlohmann::json& curve = j.at("curve");
  EXPECT_EQ(curve.at("type"), "BP");
  EXPECT_EQ(curve.at("system"), "modal_branch_point");
  EXPECT_EQ(curve.at("parameters"), (std::vector<std::string>{"C", "B"}));
  EXPECT_EQ(curve.at("start").at("C").get<double>(), c.start.p);
  EXPECT_EQ(curve.at("start").at("B").get<double>(), 1.0);
  EXPECT_EQ(curve.at("one_parameter_points").get<std::size_t>(), c.one.branch.branch.points.size());
  ASSERT_EQ(j.at("branch").size(), c.curve.branch.points.size());
  EXPECT_EQ(j.at("branch")[0].at("C").get<double>(), c.curve.branch.points[0].parameters[0]);
  EXPECT_EQ(j.at("branch")[0].at("B").get<double>(), 0.8);
  EXPECT_EQ(j.at("branch")[0].at("Delta_3").get<double>(), 0.0);
  const std::vector<std::string> lines = lines_of(to_csv(c));
  EXPECT_EQ(lines.at(0), "C,B,r,Psi,sigma,Delta_2,Delta_3,Delta_4,stable,n_unstable,label,type");
  EXPECT_EQ(lines.size(), 1 + c.curve.branch.points.size() + c.curve.branch.special_points.size());
  // The branch the curve started from is in the JSON, labelled first; the curve's labels follow.
  EXPECT_EQ(j.at("one_parameter_branch").at("branch").size(), c.one.branch.branch.points.size());
  EXPECT_EQ(j.at("branch")[0].at("label").get<int>(), c.one.branch.last_label() + 1);
  EXPECT_EQ(to_text(c).rfind("BP curve from BP (C = 0.03616893", 0), 0u) << to_text(c);
}

}  // namespace
}  // namespace rbcstab

namespace rbcstab {
namespace {
// The largest change of the state along a branch, relative to the start's size.
double state_spread(const Branch& b) {
  double spread = 0;
  for (const BranchPoint& pt : b.points) spread = std::max(spread, (pt.x - b.points.front().x).norm());
  return spread / b.points.front().x.norm();
}

// The largest change along the branch of the sum of its growth rates (the Jacobian's trace: independent of the
// eigenvalues' order).
double rate_sum_spread(const Branch& b) {
  const auto trace = [](const BranchPoint& pt) { return pt.spectrum.real().sum(); };
  double spread = 0;
  for (const BranchPoint& pt : b.points) spread = std::max(spread, std::abs(trace(pt) - trace(b.points.front())));
  return spread;
}

// A parameter the run's model does not contain (the table's levels: B at the reduced level) gives a branch of one
// state and one spectrum repeated, and the outcome says so. Where it enters (modal) there is no note and the
// spectrum moves: below the l >= 3 onset the equilibrium's shape is the l = 2 one whatever B (the tension absorbs
// it), but the l >= 3 relaxation rates Υ_l depend on B. The oracle is the branch itself, not the table.
TEST(LevelNote, BranchInAParameterTheLevelLeavesAloneSaysSo) {
  const Scene scene = modal_fixtures::scene(0.08, 4);
  const SceneBranch reduced = continue_scene(
      test::spec_of(scene, ProblemKind::equilibrium, ContinuationParameter::B, 0.5, 3, Direction::forward));
  ASSERT_GE(reduced.branch.branch.points.size(), 3u);
  EXPECT_LT(state_spread(reduced.branch.branch), 1e-12);
  EXPECT_LT(rate_sum_spread(reduced.branch.branch), 1e-12);
  EXPECT_NE(outcome(reduced).note.find("B does not enter the reduced model"), std::string::npos)
      << outcome(reduced).note;
  EXPECT_NE(outcome(reduced).note.find("moves the modal and full models"), std::string::npos);

  const SceneBranch modal =
      continue_scene(test::spec_of(scene, ProblemKind::modal, ContinuationParameter::B, 0.5, 3, Direction::forward));
  ASSERT_GE(modal.branch.branch.points.size(), 3u);
  EXPECT_GT(rate_sum_spread(modal.branch.branch), 1e-3);
  EXPECT_EQ(outcome(modal).note.find("does not enter"), std::string::npos) << outcome(modal).note;
  // Every continuation parameter moves the levels its row says; lambda moves every level.
  EXPECT_EQ(unmoved_level_note(ContinuationParameter::lambda, ModelLevel::reduced), "");
  EXPECT_EQ(unmoved_level_note(ContinuationParameter::C, ModelLevel::reduced), "");
}
}  // namespace
}  // namespace rbcstab
