// A fit's report folder (report/fit_page.hpp write_fit_report): the page's tables made from the FitResult, the
// figures drawn by fit_draw.py from fit_page_json, and the data behind both, staged and published whole as
// `rbcstab report` does (detail/staging.hpp).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "rbcstab/core/error.hpp"
#include "rbcstab/io/files.hpp"
#include "rbcstab/io/json.hpp"
#include "rbcstab/report/detail/html_text.hpp"
#include "rbcstab/report/detail/provenance.hpp"
#include "rbcstab/report/detail/report_pages.hpp"
#include "rbcstab/report/detail/staging.hpp"
#include "rbcstab/report/fit_page.hpp"

namespace rbcstab {

namespace {

namespace fs = std::filesystem;

constexpr const char* kFitScript = "fit_draw.py";

// A number for a page cell (6 significant digits; the page writes its exponent as a power of ten).
std::string fit_cell(double v, int digits = 6) {
  if (!std::isfinite(v)) return "n/a";
  std::ostringstream s;
  s.precision(digits);
  s << v;
  return s.str();
}
std::string fit_with_unit(double v, const std::string& unit) { return fit_cell(v) + (unit.empty() ? "" : " " + unit); }
std::string fit_yes_no(bool b) { return b ? "yes" : "no"; }
std::string fit_csv_bool(bool b) { return b ? "true" : "false"; }

using detail::fit_page_unit;
using detail::fit_page_value;
using detail::html_text;
using detail::plain_text;

const ObservedRow* fit_row_at(const ObservationData& data, int line) {
  for (const ObservedRow& r : data.rows)
    if (r.line == line) return &r;
  return nullptr;
}

struct FitPageText {
  std::string title, summary;
  std::vector<std::string> warnings;
  std::vector<ReportTable> tables;
};

FitPageText fit_page_text(const FitResult& fit, const ObservationData& data, const std::string& data_name) {
  FitPageText p;
  p.title = "rbcstab fit: " + data_name;
  std::ostringstream s;
  s << "Status: " << to_string(fit.status) << ". χ² = " << fit_cell(fit.chi2) << " over " << fit.rows << " rows and "
    << fit.estimates.size() << " free parameter" << (fit.estimates.size() == 1 ? "" : "s") << " (" << fit.dof
    << " degrees of freedom)";
  if (fit.dof > 0 && std::isfinite(fit.chi2)) s << ": χ²/dof = " << fit_cell(fit.chi2 / fit.dof, 4);
  s << ". The 95 % intervals take the uncertainties as given (not rescaled by χ²/dof); " << fit.evaluations
    << " evaluations of the model over all rows.";
  p.summary = s.str();
  if (fit.status != FitStatus::converged)
    p.warnings.push_back("the fit did not converge (status " + to_string(fit.status) + "): " + fit.message);
  else if (std::any_of(fit.estimates.begin(), fit.estimates.end(),
                       [](const FitEstimate& e) { return e.identifiable && !std::isfinite(e.standard_error); }))
    p.warnings.push_back("no Fisher intervals at the estimate: " + fit.message);
  for (const ConstraintResult& c : fit.constraints)
    if (c.active && !c.violated)
      p.warnings.push_back("the estimate lies on a regime constraint (" + constraint_text(c) +
                           "): the Fisher intervals ignore it (the profiles re-fit with it)");

  ReportTable params{
      "Parameters (95 % intervals: Fisher, from the Fisher information at the estimate; profile, "
      "where Δχ² of the profile crosses 3.84)",
      {"parameter", "estimate", "95 % Fisher interval", "95 % profile interval", "identifiable", "at a bound",
       "profile"},
      {}};
  for (const FitEstimate& e : fit.estimates) {
    const std::string& u = e.parameter.unit;
    const Profile& pr = e.profile;
    const bool assessed = !e.identifiable || std::isfinite(e.standard_error);  // the Fisher test ran
    // A Greek name ("lambda") is written as its letter on the page: no symbol beside it then.
    const bool greek = plain_text("$" + e.parameter.name + "$") == e.parameter.unicode;
    params.rows.push_back({greek ? e.parameter.name : e.parameter.name + " (" + e.parameter.unicode + ")",
                           fit_with_unit(e.value, u),
                           !e.identifiable                   ? "none: not identifiable"
                           : std::isfinite(e.standard_error) ? "[" + fit_cell(e.lo95) + ", " + fit_cell(e.hi95) + "]"
                                                             : "none: no Fisher information (see the warning)",
                           !pr.computed ? "not computed"
                           : pr.flat    ? "none: flat"
                                        : "[" + (std::isfinite(pr.lo95) ? fit_cell(pr.lo95) : "open") + ", " +
                                           (std::isfinite(pr.hi95) ? fit_cell(pr.hi95) : "open") + "]",
                           assessed ? fit_yes_no(e.identifiable) : "not assessed", fit_yes_no(e.at_bound),
                           pr.computed ? pr.statement : "not computed (profiles not asked for)"});
  }
  p.tables.push_back(std::move(params));

  if (!fit.correlation.empty()) {
    ReportTable corr{"Correlations of the fitted coordinates (ln for the moduli, viscosities and lambda)", {""}, {}};
    for (const FitEstimate& e : fit.estimates) corr.header.push_back(e.parameter.name);
    for (std::size_t j = 0; j < fit.correlation.size(); ++j) {
      std::vector<std::string> row{fit.estimates[j].parameter.name};
      for (double v : fit.correlation[j]) row.push_back(std::isfinite(v) ? fit_cell(v, 3) : "n/a");
      corr.rows.push_back(std::move(row));
    }
    p.tables.push_back(std::move(corr));
  }

  ReportTable flat{"What these data cannot pin down, and what would", {"statement"}, {}};
  for (const std::string& u : fit.unidentifiable) flat.rows.push_back({u});
  if (flat.rows.empty()) flat.rows.push_back({"every direction of the free parameters is constrained (Fisher test)"});
  p.tables.push_back(std::move(flat));

  ReportTable res{"Residuals (angles in degrees)",
                  {"line", "observable", "shear rate [1/s]", "viscosity [mPa s]", "observed", "predicted",
                   "uncertainty", "(predicted - observed)/uncertainty", "regime seen / predicted"},
                  {}};
  for (const RowResidual& r : fit.residuals) {
    const ObservedRow* o = fit_row_at(data, r.line);
    const bool numeric = r.observable != Observable::regime;
    const std::string unit = numeric ? " " + fit_page_unit(r.observable) : "";
    res.rows.push_back({std::to_string(r.line), to_string(r.observable), o ? fit_cell(o->shear_rate) : "n/a",
                        o ? fit_cell(o->viscosity * 1e3) : "n/a",
                        numeric ? fit_cell(fit_page_value(r.observable, r.observed)) + unit : "",
                        numeric
                            ? (std::isfinite(r.predicted) ? fit_cell(fit_page_value(r.observable, r.predicted)) + unit
                                                          : "none: " + r.reason)
                            : "",
                        numeric ? fit_cell(fit_page_value(r.observable, r.uncertainty)) + unit : "",
                        numeric ? fit_cell(r.residual, 4) : "",
                        r.observed_regime == Regime::undetermined
                            ? to_string(r.predicted_regime)
                            : to_string(r.observed_regime) + " / " + to_string(r.predicted_regime) +
                                  (r.regime_agrees ? "" : " (DISAGREES)")});
  }
  p.tables.push_back(std::move(res));

  ReportTable starts{
      "Starts (Ipopt, in the fitted coordinates)", {"start", "status", "Ipopt", "chi^2", "iterations"}, {}};
  for (std::size_t k = 0; k < fit.starts.size(); ++k)
    starts.rows.push_back({std::to_string(k + 1), to_string(fit.starts[k].status), fit.starts[k].ipopt_status,
                           fit_cell(fit.starts[k].chi2), std::to_string(fit.starts[k].iterations)});
  p.tables.push_back(std::move(starts));
  return p;
}

std::string parameters_csv(const FitResult& fit) {
  std::ostringstream s;
  s << "name,unit,scale,value,standard_error,lo95,hi95,profile_lo95,profile_hi95,identifiable,at_bound,"
       "profile_computed,profile_flat,profile_nonlinear\n";
  for (const FitEstimate& e : fit.estimates)
    s << e.parameter.name << ',' << e.parameter.unit << ',' << (e.parameter.log_scale ? "log" : "linear") << ','
      << csv_number(e.value) << ',' << csv_number(e.standard_error) << ',' << csv_number(e.lo95) << ','
      << csv_number(e.hi95) << ',' << csv_number(e.profile.lo95) << ',' << csv_number(e.profile.hi95) << ','
      << fit_csv_bool(e.identifiable) << ',' << fit_csv_bool(e.at_bound) << ',' << fit_csv_bool(e.profile.computed)
      << ',' << fit_csv_bool(e.profile.flat) << ',' << fit_csv_bool(e.profile.nonlinear) << '\n';
  return s.str();
}

std::string correlation_csv(const FitResult& fit) {
  std::ostringstream s;
  s << "name";
  for (const FitEstimate& e : fit.estimates) s << ',' << e.parameter.name;
  s << '\n';
  for (std::size_t j = 0; j < fit.correlation.size(); ++j) {
    s << fit.estimates[j].parameter.name;
    for (double v : fit.correlation[j]) s << ',' << csv_number(v);
    s << '\n';
  }
  return s.str();
}

// Canonical units (rad, Hz, 1/s) and SI conditions, as the fit computes them.
std::string residuals_csv(const FitResult& fit, const ObservationData& data) {
  std::ostringstream s;
  s << "line,observable,shear_rate,viscosity,observed,predicted,uncertainty,unit,residual,observed_regime,"
       "predicted_regime,regime_agrees\n";
  for (const RowResidual& r : fit.residuals) {
    const ObservedRow* o = fit_row_at(data, r.line);
    const bool numeric = r.observable != Observable::regime;
    s << r.line << ',' << to_string(r.observable) << ',' << csv_number(o ? o->shear_rate : kNotGiven) << ','
      << csv_number(o ? o->viscosity : kNotGiven) << ',' << csv_number(r.observed) << ',' << csv_number(r.predicted)
      << ',' << csv_number(r.uncertainty) << ',' << (numeric ? canonical_unit(r.observable) : "") << ','
      << csv_number(r.residual) << ','
      << (r.observed_regime == Regime::undetermined ? "" : to_string(r.observed_regime)) << ','
      << to_string(r.predicted_regime) << ',' << fit_csv_bool(r.regime_agrees) << '\n';
  }
  return s.str();
}

struct FitFigure {
  std::string file, caption;
};

std::vector<FitFigure> fit_figures(const FitResult& fit, const nlohmann::json& drawn) {
  std::vector<FitFigure> out{
      {"fig_fit.png",
       "The observations (points, error bars one uncertainty) against shear rate, one colour per outer viscosity, "
       "and the model at the estimate (lines, drawn only over the shear rates where it was computed); below, "
       "(predicted - observed)/uncertainty with the +-2 band. Data: fit_page.json, residuals.csv"}};
  for (const auto& d : drawn.at("profiles")) {
    std::string statement;
    for (const FitEstimate& e : fit.estimates)
      if (e.parameter.name == d.at("parameter").get<std::string>()) statement = e.profile.statement;
    out.push_back(
        {d.at("file").get<std::string>(), "Profile of " + d.at("parameter").get<std::string>() +
                                              ": Δχ² of the profile (points), the 3.84 line and the Fisher parabola, "
                                              "over the computed grid only; " +
                                              statement + ". Data: fit_page.json"});
  }
  return out;
}

std::string fit_markdown(const FitPageText& p, const std::vector<FitFigure>& figures, const detail::Provenance& stamp) {
  std::ostringstream md;
  md << "# " << p.title << "\n\n" << plain_text(p.summary) << "\n\n";
  for (const auto& w : p.warnings) md << "> warning: " << plain_text(w) << "\n\n";
  for (const ReportTable& t : p.tables) md << detail::table_markdown(t.title, t.header, t.rows);
  md << "## Figures\n\n";
  for (const FitFigure& f : figures)
    md << "![" << f.file << "](" << f.file << ")\n\n" << plain_text(f.caption) << "\n\n";
  md << "## Numbers\n\nfit.json (the whole result), parameters.csv, correlation.csv, residuals.csv.\n\n"
     << detail::provenance_markdown(stamp);
  return md.str();
}

std::string fit_html(const FitPageText& p, const std::vector<FitFigure>& figures, const detail::Provenance& stamp) {
  using detail::html_escape;
  std::ostringstream h;
  h << detail::page_head_html(p.title) << "<h1>" << html_escape(p.title) << "</h1>\n";
  for (const auto& w : p.warnings) h << "<p class=\"warn\">warning: " << html_text(w) << "</p>\n";
  h << "<p>" << html_text(p.summary) << "</p>\n";
  for (const ReportTable& t : p.tables) h << detail::table_html(t.title, t.header, t.rows);
  h << "<h2>Figures</h2>\n";
  for (const FitFigure& f : figures)
    h << "<figure><a href=\"" << html_escape(f.file) << "\" title=\"open the figure whole\"><img src=\""
      << html_escape(f.file) << "\" alt=\"" << html_escape(f.file) << "\"></a><figcaption>" << html_text(f.caption)
      << "</figcaption></figure>\n";
  h << "<h2>Numbers</h2>\n<p><a href=\"fit.json\">fit.json</a> (the whole result), <a "
       "href=\"parameters.csv\">parameters.csv</a>, <a href=\"correlation.csv\">correlation.csv</a>, <a "
       "href=\"residuals.csv\">residuals.csv</a>.</p>\n"
    << detail::provenance_html(stamp) << "</body></html>\n";
  return h.str();
}

}  // namespace

void FitReportOptions::validate() const {
  if (output.empty()) throw InvalidArgument("output", "output: a folder path is required");
  if (python.empty()) throw InvalidArgument("python", "python: an interpreter path is required");
  page.validate();
}

FitReportOptions check_fit_report(const FitReportOptions& options) {
  options.validate();
  FitReportOptions o = options;
  if (o.script_dir.empty()) o.script_dir = find_script_dir("");
  std::error_code ec;
  if (!fs::is_regular_file(fs::path(o.script_dir) / kFitScript, ec))
    throw ReportError("script_dir: " + std::string(kFitScript) + " not found (looked in '" + o.script_dir +
                      "', $RBCSTAB_DATA_DIR, <prefix>/share/rbcstab/python); set RBCSTAB_DATA_DIR");
  detail::output_target(o.output, o.overwrite);  // first: a refusal needs no python
  check_python(o.python);
  return o;
}

FitReportResult write_fit_report(const FitResult& fit, const ObservationData& data, const FitReportOptions& options) {
  const FitReportOptions o = check_fit_report(options);
  const nlohmann::json page = fit_page_json(fit, data, o.page);  // refuses a fit without an estimate
  const fs::path target = detail::output_target(o.output, o.overwrite);
  std::error_code ec;
  const bool has_file = !data.path.empty() && fs::is_regular_file(data.path, ec);
  const std::string data_text = has_file ? read_file(data.path, "data") : "";
  const std::string data_name = has_file ? fs::path(data.path).filename().string() : data.path;
  const detail::Provenance stamp = detail::make_provenance(
      {data_text}, has_file ? "the observations file " + data_name : "no observations file: rows given in memory");
  FitReportResult res;
  res.output = target.string();
  detail::in_staging_folder(target, [&](const fs::path& tmp) {
    nlohmann::json result = to_json(fit);
    result["data"] = data.path;
    result["provenance"] = detail::provenance_json(stamp);
    std::vector<std::pair<std::string, std::string>> files = {{"fit.json", result.dump(1) + "\n"},
                                                              {"fit_page.json", page.dump(1) + "\n"},
                                                              {"parameters.csv", parameters_csv(fit)},
                                                              {"correlation.csv", correlation_csv(fit)},
                                                              {"residuals.csv", residuals_csv(fit, data)}};
    if (has_file) files.emplace_back("observations.csv", data_text);
    for (const auto& [name, text] : files) {
      write_file_atomic((tmp / name).string(), text);
      res.files.push_back(name);
    }
    const std::string log = (tmp / "plot.log").string();
    const int rc =
        run_process({o.python, (fs::path(o.script_dir) / kFitScript).string(), (tmp / "fit_page.json").string(),
                     (tmp / "fig_fit.png").string(), (tmp / "drawn.json").string()},
                    log);
    if (rc != 0)
      throw ReportError("the drawing script failed (exit " + std::to_string(rc) + "): " + detail::log_tail(log, 1500));
    const nlohmann::json drawn = nlohmann::json::parse(read_file((tmp / "drawn.json").string()));
    const std::vector<FitFigure> figures = fit_figures(fit, drawn);
    for (const FitFigure& f : figures) res.files.push_back(f.file);
    res.files.insert(res.files.end(), {"drawn.json", "plot.log"});
    const FitPageText text = fit_page_text(fit, data, data_name);
    write_file_atomic((tmp / "README.md").string(), fit_markdown(text, figures, stamp));
    write_file_atomic((tmp / "index.html").string(), fit_html(text, figures, stamp));
    res.files.insert(res.files.end(), {"README.md", "index.html"});
    detail::publish_folder(tmp, target);
  });
  return res;
}

}  // namespace rbcstab
