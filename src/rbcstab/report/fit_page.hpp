#pragma once
// A fit's report page (docs/report.md "A fit's page"): the observations against the fitted model per observable and
// outer viscosity, with the model evaluated on a grid of shear rates at the estimate, the normalised residuals, the
// profiles against their Fisher parabolas, and the parameter table with intervals and the identifiability
// statements. fit_page_json is the data a drawing script (fit_draw.py) draws as given; write_fit_report writes the
// folder (`rbcstab fit --report DIR`, FitResult.report in Python).
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "rbcstab/inverse/fit.hpp"
#include "rbcstab/inverse/observations.hpp"

namespace rbcstab {

struct FitPageOptions {
  int curve_points = 48;  // [2, 10000]: log-spaced shear rates per (observable, viscosity) over the rows' span
  ForwardOptions forward;
  void validate() const;  // throws InvalidArgument naming the field
};

// {"kind": "fit", "status", "chi2", "dof", "rows", "estimates" (as to_json(FitResult)), "unidentifiable",
//  "panels": [{"observable", "unit" (deg for angles, else the canonical unit), "viscosity" [Pa s],
//              "points": [{"line", "shear_rate", "value", "uncertainty", "predicted", "residual"}],
//              "curve": {"shear_rate": [...], "value": [... null where the model gives no prediction],
//                        "span": [first, last shear rate with a value] or null, "reasons": [...]}}],
//  "residuals": [{"line", "observable", "viscosity", "shear_rate", "residual"}],
//  "profiles": [{"parameter", "symbol", "unit", "scale", "value" (SI), "threshold" (3.84), "flat", "statement",
//               "x": [...] (the profile's grid in SI), "delta_chi2": [...], "span": [first, last x],
//               "fisher": {"x", "delta_chi2"} (((coordinate - estimate)/se)^2 over the span) or null}]} (computed
//  profiles only).
// Panels: the rows with a shear rate (angles, amplitudes, frequencies) grouped by observable and viscosity, in
// the order of first appearance; the curve is the forward model (predict) at `fit.cell` on the grid from the
// group's lowest to highest shear rate. Throws InvalidArgument("fit", ...) for a fit without an estimate
// (status failed) and ("data", ...) when `data` holds no row with a shear rate or no row of the fit.
nlohmann::json fit_page_json(const FitResult& fit, const ObservationData& data, const FitPageOptions& options = {});

namespace detail {
// The page's units: angles in degrees (as labs report them), other values in their canonical unit.
double fit_page_value(Observable o, double v);
std::string fit_page_unit(Observable o);
}  // namespace detail

struct FitReportOptions {
  std::string output;                       // folder to create (its parent must exist)
  bool overwrite = false;                   // replace an existing folder; otherwise refuse (as `rbcstab report`)
  std::string python = "/usr/bin/python3";  // with matplotlib
  std::string script_dir;                   // folder of fit_draw.py; empty: find_script_dir("")
  FitPageOptions page;
  void validate() const;  // throws InvalidArgument naming the field
};

// What a front end checks before the fit runs, so that nothing is computed for a folder that cannot be written:
// the options, the drawing script, python with matplotlib (ReportError) and the folder (an existing one without
// overwrite: InvalidArgument("output")). Returns the options with script_dir filled in.
FitReportOptions check_fit_report(const FitReportOptions& options);

struct FitReportResult {
  std::string output;              // the folder
  std::vector<std::string> files;  // relative to it
};
// The folder, whole or not at all: index.html and README.md (status and chi^2/dof at the top, the parameter
// table, correlations, statements, figures), fit.json (to_json(fit) with "data"), fit_page.json, parameters.csv,
// correlation.csv, residuals.csv, the observations file as read (when data.path is a file), fig_fit.png, one
// fig_profile_<name>.png per computed profile, drawn.json (what the script drew) and plot.log. A failed fit
// (no estimate) is refused as by fit_page_json; python, the script or the folder failing: ReportError.
FitReportResult write_fit_report(const FitResult& fit, const ObservationData& data, const FitReportOptions& options);

}  // namespace rbcstab
