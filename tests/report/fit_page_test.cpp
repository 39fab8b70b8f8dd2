// The data of a fit's page (report/fit_page.hpp): one panel per observable and viscosity, the model curve on the
// requested grid over the rows' span, the residuals of the fit's rows, and bad requests refused by name; the page's
// folder (write_fit_report) from a real fit: its parameter table read back, the profile figure's drawn span.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "inverse/synthetic_cell.hpp"
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

// A flat profile as fit() leaves one for kappa (Fit.ProfileOfKappaAloneIsFlat): Delta chi^2 = 0 from bound to bound,
// no Fisher standard error.
FitEstimate flat_kappa() {
  FitEstimate e;
  e.parameter = fit_parameter_info(FitParameter::bending_modulus, CellModel{});
  e.value = 2e-19;
  e.identifiable = false;
  e.profile.computed = true;
  e.profile.flat = true;
  e.profile.coordinate = {std::log(e.parameter.lo), std::log(e.value), std::log(e.parameter.hi)};
  e.profile.delta_chi2 = {0, 0, 0};
  e.profile.statement = "profile of bending_modulus: flat";
  return e;
}

// The drawing script draws the page's JSON as given: the fit's figure with every panel, each curve over its computed
// span, and the flat profile's figure over its grid (log axis: it spans decades), without a Fisher parabola, titled
// flat.
TEST(FitPage, DrawingScriptDrawsWhatTheJsonSays) {
  const std::filesystem::path dir = test::fresh_dir("fit_page", "draw");
  FitPageOptions o;
  o.curve_points = 7;
  FitResult fit = page_fit();
  fit.estimates.push_back(flat_kappa());
  const nlohmann::json page = fit_page_json(fit, page_data(), o);
  write_file_atomic((dir / "fit_page.json").string(), page.dump(1), "test");
  const std::string cmd = "/usr/bin/python3 '" + find_script_dir("") + "/fit_draw.py' '" +
                          (dir / "fit_page.json").string() + "' '" + (dir / "fig_fit.png").string() + "' > '" +
                          (dir / "drawn.json").string() + "' 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << test::slurp(dir / "drawn.json");
  const nlohmann::json drawn = nlohmann::json::parse(test::slurp(dir / "drawn.json"));
  EXPECT_EQ(drawn.at("figures"), 2);
  ASSERT_EQ(drawn.at("panels").size(), page.at("panels").size());
  for (std::size_t k = 0; k < page.at("panels").size(); ++k)
    EXPECT_EQ(drawn.at("panels")[k].at("curve_span"), page.at("panels")[k].at("curve").at("span")) << k;
  EXPECT_GT(png_size(dir / "fig_fit.png").first, 0);
  ASSERT_EQ(drawn.at("profiles").size(), 1u);
  const nlohmann::json& d = drawn.at("profiles")[0];
  const std::vector<double>& c = fit.estimates[0].profile.coordinate;
  EXPECT_EQ(d.at("span"), nlohmann::json::array({std::exp(c.front()), std::exp(c.back())}));
  EXPECT_TRUE(d.at("fisher_span").is_null());
  EXPECT_EQ(d.at("xscale"), "log");
  EXPECT_NE(d.at("title").get<std::string>().find("flat"), std::string::npos) << d.dump();
  EXPECT_GT(png_size(dir / "fig_profile_bending_modulus.png").first, 0);
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
  // The page's folder: a path is required; python without matplotlib (here: none at all) is an output error, found
  // before anything is computed or written.
  FitReportOptions ro;
  try {
    check_fit_report(ro);
    FAIL() << "no output folder accepted";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.parameter(), "output");
  }
  const std::filesystem::path dir = test::fresh_dir("fit_page", "refused");
  ro.output = (dir / "page").string();
  ro.python = (dir / "no-python3").string();
  EXPECT_THROW(check_fit_report(ro), ReportError);
  EXPECT_FALSE(std::filesystem::exists(dir / "page"));
  std::filesystem::remove_all(dir);
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

// parameters.csv as rows of name -> field.
std::vector<std::map<std::string, std::string>> read_csv(const std::string& text) {
  std::istringstream in(text);
  std::string line;
  std::vector<std::string> header;
  std::vector<std::map<std::string, std::string>> rows;
  while (std::getline(in, line)) {
    std::vector<std::string> fields;
    std::stringstream ls(line);
    std::string f;
    while (std::getline(ls, f, ',')) fields.push_back(f);
    if (!line.empty() && line.back() == ',') fields.emplace_back();
    if (header.empty()) {
      header = fields;
      continue;
    }
    std::map<std::string, std::string> row;
    for (std::size_t k = 0; k < header.size(); ++k) row[header[k]] = k < fields.size() ? fields[k] : "";
    rows.push_back(row);
  }
  return rows;
}

// "" when the table holds exactly the numbers of the fit's JSON (to_json(FitResult)), else the first difference.
std::string table_mismatch(const std::vector<std::map<std::string, std::string>>& table, const nlohmann::json& fit) {
  const nlohmann::json& est = fit.at("estimates");
  if (table.size() != est.size()) return "rows: " + std::to_string(table.size());
  auto same = [](const std::string& field, const nlohmann::json& v) {
    return v.is_null() ? field.empty() : !field.empty() && std::stod(field) == v.get<double>();
  };
  for (std::size_t j = 0; j < est.size(); ++j) {
    const auto& row = table[j];
    const nlohmann::json& e = est[j];
    const nlohmann::json& p = e.at("profile");
    if (row.at("name") != e.at("name")) return "name " + row.at("name");
    for (const char* k : {"value", "standard_error", "lo95", "hi95"})
      if (!same(row.at(k), e.at(k))) return std::string(k) + " of " + row.at("name");
    if (!same(row.at("profile_lo95"), p.is_null() ? p : p.at("lo95")) ||
        !same(row.at("profile_hi95"), p.is_null() ? p : p.at("hi95")))
      return "profile interval of " + row.at("name");
    if ((row.at("identifiable") == "true") != e.at("identifiable").get<bool>() ||
        (row.at("at_bound") == "true") != e.at("at_bound").get<bool>() ||
        (row.at("profile_flat") == "true") != (!p.is_null() && p.at("flat").get<bool>()))
      return "flags of " + row.at("name");
  }
  return "";
}

// A real fit of lambda alone to the noisy synthetic rows at 1 mPa s, with its profile, written as a page: the table
// holds the fit's numbers, the profile figure spans exactly the computed grid (and so does the Fisher parabola), an
// existing folder is refused, and a fit that did not converge says so at the top.
TEST(FitPage, ReportFolderHoldsTheFitsNumbers) {
  const CellModel truth = synthetic_cell();
  const ObservationData data = one_viscosity(synthetic_data(truth, 1.0, 7));
  FitOptions fo;
  fo.starts = 1;
  fo.profiles.enabled = true;
  fo.profiles.points = 2;
  FitResult r = fit(data, {"lambda"}, truth, fo);
  ASSERT_EQ(r.status, FitStatus::converged) << r.message;
  const std::filesystem::path dir = test::fresh_dir("fit_page", "report");
  FitReportOptions o;
  o.output = (dir / "page").string();
  o.page.curve_points = 3;
  const FitReportResult w = write_fit_report(r, data, o);
  const std::filesystem::path page = w.output;
  for (const char* f : {"index.html", "README.md", "fit.json", "fit_page.json", "parameters.csv", "correlation.csv",
                        "residuals.csv", "fig_fit.png", "fig_profile_lambda.png", "drawn.json"})
    EXPECT_TRUE(std::filesystem::exists(page / f)) << f;

  const nlohmann::json fj = to_json(r);
  const auto table = read_csv(test::slurp(page / "parameters.csv"));
  EXPECT_EQ(table_mismatch(table, fj), "");
  EXPECT_EQ(nlohmann::json::parse(test::slurp(page / "fit.json")).at("estimates"), fj.at("estimates"));
  nlohmann::json off = fj;  // the comparison sees a change in the last digits
  off["estimates"][0]["hi95"] = std::nextafter(off["estimates"][0]["hi95"].get<double>(), 1e9);
  EXPECT_NE(table_mismatch(table, off), "");

  const Profile& pr = r.estimates[0].profile;
  ASSERT_GE(pr.coordinate.size(), 3u);
  const nlohmann::json drawn = nlohmann::json::parse(test::slurp(page / "drawn.json"));
  ASSERT_EQ(drawn.at("profiles").size(), 1u);
  const nlohmann::json& d = drawn.at("profiles")[0];
  const std::vector<double> grid{std::exp(pr.coordinate.front()), std::exp(pr.coordinate.back())};
  auto spans = [](const nlohmann::json& a, const std::vector<double>& b) {
    return a.at(0).get<double>() == b[0] && a.at(1).get<double>() == b[1];
  };
  EXPECT_TRUE(spans(d.at("span"), grid)) << d.dump();
  EXPECT_TRUE(spans(d.at("fisher_span"), grid)) << d.dump();
  EXPECT_TRUE(spans(d.at("threshold_span"), grid)) << d.dump();
  EXPECT_FALSE(spans(d.at("span"), {grid[0], std::exp(pr.coordinate[pr.coordinate.size() - 2])}));
  EXPECT_EQ(d.at("points"), pr.coordinate.size());
  EXPECT_EQ(d.at("flat"), false);

  const std::string readme = test::slurp(page / "README.md");
  EXPECT_NE(readme.find("Status: converged"), std::string::npos);
  EXPECT_EQ(readme.find("warning"), std::string::npos);
  EXPECT_NE(readme.find(pr.statement), std::string::npos);

  try {
    write_fit_report(r, data, o);
    FAIL() << "an existing folder overwritten";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.parameter(), "output");
  }
  EXPECT_EQ(test::slurp(page / "README.md"), readme);

  r.status = FitStatus::maximum_iterations;
  r.message = "the best start did not converge";
  r.estimates[0].profile = {};  // one figure: a quicker drawing
  o.overwrite = true;
  write_fit_report(r, data, o);
  const std::string html = test::slurp(page / "index.html");
  const std::size_t warn = html.find("warning: the fit did not converge (status maximum_iterations)");
  ASSERT_NE(warn, std::string::npos);
  EXPECT_LT(warn, html.find("<h2>"));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace rbcstab
