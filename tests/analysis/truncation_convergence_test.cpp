// The truncation study (`rbcstab bench truncation`) against runs made here one by one, against what the command
// printed before the study moved into the library, and its refusals and failed reference.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "rbcstab/analysis/analysis_io.hpp"
#include "rbcstab/analysis/truncation_convergence.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/io/json.hpp"
#include "rbcstab/io/scene_file.hpp"

namespace rbcstab {
namespace {

// The CSV without its last column (seconds: wall-clock time).
std::string without_seconds(const std::string& csv) {
  std::istringstream in(csv);
  std::string out, line;
  while (std::getline(in, line)) out += line.substr(0, line.rfind(',')) + "\n";
  return out;
}

SceneFile short_scene() {
  SceneFile sf = parse_scene("");
  sf.scene.T = 5;
  return sf;
}

TEST(TruncationConvergence, ReproducesTheCommandsTable) {
  // `rbcstab bench truncation --Ls 3,4,5 --T 5 --no-plot` before the study moved into the library.
  const SceneFile sf = short_scene();
  TruncationConvergenceOptions o;
  o.Ls = {3, 4, 5};
  const TruncationConvergence t = truncation_convergence(sf.scene, sf.options, o);
  EXPECT_EQ(without_seconds(truncation_convergence_csv(t)),
            "L,status,l_Delta,sigma_final,error_Delta,error_sigma,rhs_evaluations\n"
            "3,success,3,-30.3243241366255,0.24828679954395186,0.002111612658983439,2119\n"
            "4,success,3,-30.2620210342702,0.0005406250951386637,5.271558039968843e-05,2119\n"
            "5,success,3,-30.26042583835899,0,0,2119\n");
}

TEST(TruncationConvergence, ErrorsAreTheDifferencesOfIndependentRuns) {
  const SceneFile sf = short_scene();
  TruncationConvergenceOptions o;
  o.Ls = {3, 6};
  const TruncationConvergence t = truncation_convergence(sf.scene, sf.options, o);
  ASSERT_EQ(t.rows.size(), 2u);
  auto run = [&](int L) {
    Scene s = sf.scene;
    s.L = L;
    s.dt = s.T;
    SimulationOptions so;
    so.integrator.rtol = 1e-10;
    so.integrator.atol = 1e-14;
    so.record_trajectory = false;
    return simulate(s, so);
  };
  const SimulationResult coarse = run(3), fine = run(6);
  // Modes 4..6 of the reference count at their own area: the coarse run does not hold them.
  double e = 0;
  for (std::size_t k = 0; k < fine.Delta_final.size(); ++k)
    e = std::max(e, std::abs((k < coarse.Delta_final.size() ? coarse.Delta_final[k] : 0.0) - fine.Delta_final[k]));
  EXPECT_EQ(t.rows[0].error_Delta, e / sf.scene.parameters.Delta);
  EXPECT_EQ(t.rows[0].error_sigma,
            std::abs(coarse.sigma_final - fine.sigma_final) / std::max(1.0, std::abs(fine.sigma_final)));
  EXPECT_EQ(t.rows[0].sigma_final, coarse.sigma_final);
  EXPECT_EQ(t.rows[0].rhs_evaluations, coarse.counters.rhs_evaluations);
  EXPECT_EQ(t.rows[1].error_Delta, 0);
  EXPECT_EQ(t.rows[1].error_sigma, 0);
  EXPECT_EQ(t.reference().L, 6);
  EXPECT_TRUE(t.reference_ok());
}

TEST(TruncationConvergence, AnUnsortedListComparesWithTheLastL) {
  // The reference may hold fewer modes than a row: the row's extra modes count at their own area.
  const SceneFile sf = short_scene();
  TruncationConvergenceOptions o;
  o.Ls = {5, 3};
  const TruncationConvergence t = truncation_convergence(sf.scene, sf.options, o);
  EXPECT_TRUE(std::isfinite(t.rows[0].error_Delta));
  EXPECT_GT(t.rows[0].error_Delta, 0);
  EXPECT_LT(t.rows[0].error_Delta, 1);
  EXPECT_EQ(t.rows[1].error_Delta, 0);
}

TEST(TruncationConvergence, RefusesAnEmptyOrOutOfRangeList) {
  const SceneFile sf = short_scene();
  for (const std::vector<int>& Ls : {std::vector<int>{}, std::vector<int>{3, 1}, std::vector<int>{101}}) {
    TruncationConvergenceOptions o;
    o.Ls = Ls;
    try {
      (void)truncation_convergence(sf.scene, sf.options, o);
      ADD_FAILURE() << "accepted " << Ls.size() << " values";
    } catch (const InvalidArgument& e) {
      EXPECT_EQ(e.parameter(), "Ls");
    }
  }
}

TEST(TruncationConvergence, AFailedReferenceLeavesEveryErrorExplained) {
  SceneFile sf = short_scene();
  sf.scene.parameters.lambda = 1e308;
  TruncationConvergenceOptions o;
  o.Ls = {3, 4};
  const TruncationConvergence t = truncation_convergence(sf.scene, sf.options, o);
  ASSERT_FALSE(t.reference_ok());
  for (const TruncationConvergenceRow& r : t.rows) {
    EXPECT_TRUE(std::isnan(r.error_Delta));
    EXPECT_TRUE(std::isnan(r.error_sigma));
  }
  const nlohmann::json j = truncation_convergence_json(sf, t);
  EXPECT_TRUE(unexplained_nulls(j).empty());
  EXPECT_EQ(j["reference_L"], 4);
  EXPECT_NE(j["rows"][0]["error_Delta_reason"].get<std::string>().find("the reference (L = 4)"), std::string::npos);
}

}  // namespace
}  // namespace rbcstab
