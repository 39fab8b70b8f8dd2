// The data of a fit's page (report/fit_page.hpp): one panel per observable and viscosity, the model curve on the
// requested grid over the rows' span, the residuals of the fit's rows, and bad requests refused by name.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "png_size.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/io/files.hpp"
#include "rbcstab/report/fit_page.hpp"
#include "rbcstab/report/report.hpp"
#include "test_files.hpp"

namespace rbcstab {
namespace {

// Three angles at two viscosities and a transition row (no shear rate: not drawn against it).
ObservationData page_data() {
  return parse_observation_data(
      "observable,shear_rate,viscosity,value,uncertainty,unit\n"
      "inclination_angle,150,1,20,0.5,deg\n"
      "inclination_angle,600,1,21,0.5,deg\n"
      "inclination_angle,300,2,22,0.5,deg\n"
      "transition_shear_rate,,1,40,4,1/s\n",
      "page.csv");
}

// A fit result as fit() leaves it, at the synthetic cell of the inverse tests (swinging at these conditions).
FitResult page_fit() {
  FitResult r;
  r.status = FitStatus::converged;
  r.cell.lambda = 5;
  r.cell.Delta = 0.1;
  r.cell.Delta0 = 0.05;
  r.chi2 = 1.5;
  r.rows = 3;
  r.dof = 2;
  for (int line : {2, 3, 4}) {
    RowResidual q;
    q.line = line;
    q.predicted = 0.35;
    q.residual = 0.5 * line;
    r.residuals.push_back(q);
  }
  return r;
}

TEST(FitPage, PanelsCurvesAndResiduals) {
  FitPageOptions o;
  o.curve_points = 5;
  const nlohmann::json page = fit_page_json(page_fit(), page_data(), o);
  EXPECT_EQ(page.at("kind"), "fit");
  ASSERT_EQ(page.at("panels").size(), 2u);  // the transition row has no shear rate
  const nlohmann::json& p = page.at("panels")[0];
  EXPECT_EQ(p.at("unit"), "deg");
  EXPECT_EQ(p.at("points").size(), 2u);
  EXPECT_DOUBLE_EQ(p.at("points")[0].at("value").get<double>(), 20.0);
  const nlohmann::json& c = p.at("curve");
  ASSERT_EQ(c.at("shear_rate").size(), 5u);
  EXPECT_DOUBLE_EQ(c.at("shear_rate").front().get<double>(), 150.0);
  EXPECT_NEAR(c.at("shear_rate").back().get<double>(), 600.0, 1e-9);
  // Every grid point predicted: the drawn span is the computed grid's.
  EXPECT_TRUE(c.at("reasons").empty());
  EXPECT_EQ(c.at("span")[0], c.at("shear_rate").front());
  EXPECT_EQ(c.at("span")[1], c.at("shear_rate").back());
  for (const auto& v : c.at("value")) EXPECT_TRUE(v.is_number());
  // A single shear rate: one curve point, the span a point.
  EXPECT_EQ(page.at("panels")[1].at("curve").at("shear_rate").size(), 1u);
  EXPECT_EQ(page.at("residuals").size(), 3u);
}

// The drawing script draws the page's JSON as given: one figure, every panel, each curve over its computed span.
TEST(FitPage, DrawingScriptDrawsWhatTheJsonSays) {
  const std::filesystem::path dir = test::fresh_dir("fit_page", "draw");
  FitPageOptions o;
  o.curve_points = 7;
  const nlohmann::json page = fit_page_json(page_fit(), page_data(), o);
  write_file_atomic((dir / "fit_page.json").string(), page.dump(1), "test");
  const std::string cmd = "/usr/bin/python3 '" + find_script_dir("") + "/fit_draw.py' '" +
                          (dir / "fit_page.json").string() + "' '" + (dir / "fig_fit.png").string() + "' > '" +
                          (dir / "drawn.json").string() + "' 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << test::slurp(dir / "drawn.json");
  const nlohmann::json drawn = nlohmann::json::parse(test::slurp(dir / "drawn.json"));
  EXPECT_EQ(drawn.at("figures"), 1);
  ASSERT_EQ(drawn.at("panels").size(), page.at("panels").size());
  for (std::size_t k = 0; k < page.at("panels").size(); ++k)
    EXPECT_EQ(drawn.at("panels")[k].at("curve_span"), page.at("panels")[k].at("curve").at("span")) << k;
  EXPECT_GT(png_size(dir / "fig_fit.png").first, 0);
  std::filesystem::remove_all(dir);
}

TEST(FitPage, BadRequestsAreRefusedByName) {
  FitPageOptions o;
  o.curve_points = 1;
  try {
    fit_page_json(page_fit(), page_data(), o);
    FAIL() << "curve_points = 1 accepted";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.parameter(), "curve_points");
  }
  FitResult failed = page_fit();
  failed.status = FitStatus::failed;
  try {
    fit_page_json(failed, page_data());
    FAIL() << "a failed fit drawn";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.parameter(), "fit");
  }
  const ObservationData transitions = parse_observation_data(
      "observable,shear_rate,viscosity,value,uncertainty,unit\n"
      "transition_shear_rate,,1,40,4,1/s\n",
      "t.csv");
  try {
    fit_page_json(page_fit(), transitions);
    FAIL() << "nothing to draw accepted";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.parameter(), "data");
    EXPECT_NE(std::string(e.what()).find("t.csv"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace rbcstab
