#pragma once
// The data of a fit's report page (docs/report.md "A fit's page"): the observations against the fitted model per
// observable and outer viscosity, with the model evaluated on a grid of shear rates at the estimate, the
// normalised residuals, and the parameter table with intervals and the identifiability statements. One JSON
// document that a drawing script draws as given; the front end (a report panel or `fit --report`) is not built yet.
#include <nlohmann/json.hpp>

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
//  "residuals": [{"line", "observable", "viscosity", "shear_rate", "residual"}]}.
// Panels: the rows with a shear rate (angles, amplitudes, frequencies) grouped by observable and viscosity, in
// the order of first appearance; the curve is the forward model (predict) at `fit.cell` on the grid from the
// group's lowest to highest shear rate. Throws InvalidArgument("fit", ...) for a fit without an estimate
// (status failed) and ("data", ...) when `data` holds no row with a shear rate or no row of the fit.
nlohmann::json fit_page_json(const FitResult& fit, const ObservationData& data, const FitPageOptions& options = {});

}  // namespace rbcstab
