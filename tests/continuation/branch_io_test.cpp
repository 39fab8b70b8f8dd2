// branch_io.hpp: the Branch JSON, CSV and text of continuation results, read back against the result
// they render (keys of the shared schema, every value, the columns and rows of the CSV).
#include <gtest/gtest.h>

#include <sstream>

#include "continuation/scene_spec_fixture.hpp"
#include "rbcstab/continuation/branch_io.hpp"

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
      if (const double* d = std::get_if<double>(&v)) EXPECT_EQ(got.get<double>(), *d) << m.measure_names[i];
      else if (const int* n = std::get_if<int>(&v)) EXPECT_EQ(got.get<int>(), *n) << m.measure_names[i];
      else EXPECT_EQ(got.get<std::string>(), std::get<std::string>(v)) << m.measure_names[i];
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

TEST(BranchCsv, ColumnsFollowTheMeasuresAndRowsThePoints) {
  const SceneBranch& m = modal_switched();
  const std::vector<std::string> lines = lines_of(to_csv(m));
  EXPECT_EQ(lines.at(0), "C,branch,r,Psi,sigma,Delta_2,Delta_3,Delta_4,stable,n_unstable,max_Re_eig");
  ASSERT_EQ(lines.size(), 1 + m.branch.branch.points.size() + m.switched->branch.branch.points.size());
  std::istringstream first(lines.at(1));
  std::vector<std::string> cells;
  for (std::string c; std::getline(first, c, ',');) cells.push_back(c);
  ASSERT_EQ(cells.size(), 11u);
  EXPECT_EQ(std::stod(cells[0]), m.branch.branch.points[0].p);  // 17 digits: exact round trip
  EXPECT_EQ(cells[1], "primary");
  EXPECT_EQ(std::stod(cells[4]), m.branch.number(0, "sigma"));
  EXPECT_NE(lines.back().find(",switched,"), std::string::npos);

  // Orbits: no branch column, no trivial_multiplier (a JSON-only check of the shooting).
  EXPECT_EQ(lines_of(to_csv(orbit_branch())).at(0),
            "Delta,r,Psi,r_min,r_max,Psi_min,Psi_max,winding,kind,stable,n_unstable,max_abs_multiplier");
}

TEST(BranchText, SummarisesTheBranchItsSpecialPointsAndTheSwitch) {
  const SceneBranch& m = modal_switched();
  const std::string t = to_text(m);
  EXPECT_EQ(t.rfind(std::to_string(m.branch.branch.points.size()) + " points in C from 0.08 to 0.02, status completed", 0),
            0u) << t;
  EXPECT_NE(t.find("\nBP C = 0.03616893"), std::string::npos) << t;
  EXPECT_NE(t.find("switched at the first BP: "), std::string::npos) << t;
  EXPECT_NE(to_text(orbit_branch()).find("swing_tumble Delta = 0.38478"), std::string::npos);
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
  EXPECT_EQ(lines.at(0), "C,B,r,Psi,sigma,Delta_2,Delta_3,Delta_4,stable,n_unstable");
  EXPECT_EQ(lines.size(), 1 + c.curve.branch.points.size());
  EXPECT_EQ(to_text(c).rfind("BP curve from BP (C = 0.03616893", 0), 0u) << to_text(c);
}

}  // namespace
}  // namespace rbcstab
