#include "rbcstab/report/fit_page.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "rbcstab/core/error.hpp"

namespace rbcstab {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

bool page_angle(Observable o) { return o == Observable::inclination_angle || o == Observable::swinging_amplitude; }

nlohmann::json page_number(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(); }

constexpr double kChi2OneDof95 = 3.841458820694124;  // the profile's threshold (inverse/fit.cpp)
constexpr int kParabolaPoints = 101;

// A computed profile as the figure draws it: the grid in SI, and the Fisher parabola over the same span (none where
// the Fisher information gives no standard error).
nlohmann::json profile_panel(const FitEstimate& e) {
  const Profile& p = e.profile;
  const bool log = e.parameter.log_scale;
  auto si = [&](double x) { return log ? std::exp(x) : x; };
  nlohmann::json x = nlohmann::json::array(), d = nlohmann::json::array();
  for (std::size_t k = 0; k < p.coordinate.size(); ++k) {
    x.push_back(si(p.coordinate[k]));
    d.push_back(page_number(p.delta_chi2[k]));
  }
  nlohmann::json fisher;
  const double se = e.standard_error;
  if (!p.coordinate.empty() && std::isfinite(se) && se > 0) {
    const double centre = log ? std::log(e.value) : e.value, a = p.coordinate.front(), b = p.coordinate.back();
    nlohmann::json fx = nlohmann::json::array(), fd = nlohmann::json::array();
    for (int k = 0; k < kParabolaPoints; ++k) {
      const double c = a + (b - a) * k / (kParabolaPoints - 1);
      fx.push_back(si(c));
      fd.push_back((c - centre) * (c - centre) / (se * se));
    }
    fisher = {{"x", fx}, {"delta_chi2", fd}};
  }
  return {{"parameter", e.parameter.name},
          {"symbol", e.parameter.unicode},
          {"unit", e.parameter.unit},
          {"scale", log ? "log" : "linear"},
          {"value", page_number(e.value)},
          {"threshold", kChi2OneDof95},
          {"flat", p.flat},
          {"statement", p.statement},
          {"x", x},
          {"delta_chi2", d},
          {"span", p.coordinate.empty() ? nlohmann::json() : nlohmann::json::array({x.front(), x.back()})},
          {"fisher", fisher}};
}

}  // namespace

namespace detail {
double fit_page_value(Observable o, double v) { return page_angle(o) ? v * 180 / std::numbers::pi : v; }
std::string fit_page_unit(Observable o) { return page_angle(o) ? "deg" : canonical_unit(o); }
}  // namespace detail

void FitPageOptions::validate() const {
  require(curve_points >= 2 && curve_points <= 10000, "curve_points", curve_points, "an integer in [2, 10000]");
  forward.validate();
}

nlohmann::json fit_page_json(const FitResult& fit, const ObservationData& data, const FitPageOptions& options) {
  options.validate();
  if (fit.status == FitStatus::failed)
    throw InvalidArgument("fit", "the fit failed (" + fit.message + "): there is no estimate to draw");
  std::vector<std::pair<Observable, double>> groups;  // (observable, viscosity) in order of appearance
  for (const ObservedRow& r : data.rows) {
    if (!std::isfinite(r.shear_rate) || r.observable == Observable::regime) continue;
    const std::pair<Observable, double> g{r.observable, r.viscosity};
    bool seen = false;
    for (const auto& h : groups) seen = seen || h == g;
    if (!seen) groups.push_back(g);
  }
  if (groups.empty())
    throw InvalidArgument("data", data.path + " holds no row with a shear rate: nothing to draw against shear rate");
  auto residual_of = [&](int line) -> const RowResidual* {
    for (const RowResidual& q : fit.residuals)
      if (q.line == line) return &q;
    return nullptr;
  };

  nlohmann::json panels = nlohmann::json::array();
  nlohmann::json residuals = nlohmann::json::array();
  bool any_fitted = false;
  for (const auto& [observable, viscosity] : groups) {
    nlohmann::json points = nlohmann::json::array();
    double lo = std::numeric_limits<double>::infinity(), hi = 0;
    for (const ObservedRow& r : data.rows) {
      if (r.observable != observable || r.viscosity != viscosity || !std::isfinite(r.shear_rate)) continue;
      lo = std::min(lo, r.shear_rate);
      hi = std::max(hi, r.shear_rate);
      const RowResidual* q = residual_of(r.line);
      any_fitted = any_fitted || q;
      points.push_back({{"line", r.line},
                        {"shear_rate", r.shear_rate},
                        {"value", detail::fit_page_value(observable, r.value)},
                        {"uncertainty", detail::fit_page_value(observable, r.uncertainty)},
                        {"predicted", page_number(q ? detail::fit_page_value(observable, q->predicted) : kNaN)},
                        {"residual", page_number(q ? q->residual : kNaN)}});
      if (q)
        residuals.push_back({{"line", r.line},
                             {"observable", to_string(observable)},
                             {"viscosity", viscosity},
                             {"shear_rate", r.shear_rate},
                             {"residual", page_number(q->residual)}});
    }
    nlohmann::json rates = nlohmann::json::array(), values = nlohmann::json::array(), reasons = nlohmann::json::array();
    double first = kNaN, last = kNaN;
    const int n = hi > lo ? options.curve_points : 1;
    for (int k = 0; k < n; ++k) {
      const double rate = n == 1 ? lo : lo * std::pow(hi / lo, double(k) / (n - 1));
      ObservedRow row;
      row.observable = observable;
      row.shear_rate = rate;
      row.viscosity = viscosity;
      const Prediction p = predict(fit.cell, row, options.forward);
      rates.push_back(rate);
      values.push_back(p.ok() ? page_number(detail::fit_page_value(observable, p.value)) : nlohmann::json());
      if (p.ok() && std::isfinite(p.value)) {
        if (!std::isfinite(first)) first = rate;
        last = rate;
      } else {
        reasons.push_back(p.reason);
      }
    }
    panels.push_back({{"observable", to_string(observable)},
                      {"unit", detail::fit_page_unit(observable)},
                      {"viscosity", viscosity},
                      {"points", points},
                      {"curve",
                       {{"shear_rate", rates},
                        {"value", values},
                        {"span", std::isfinite(first) ? nlohmann::json::array({first, last}) : nlohmann::json()},
                        {"reasons", reasons}}}});
  }
  if (!any_fitted)
    throw InvalidArgument("data", data.path + " holds no row of this fit (no residual matches a row's line)");
  const nlohmann::json r = to_json(fit);
  nlohmann::json profiles = nlohmann::json::array();
  for (const FitEstimate& e : fit.estimates)
    if (e.profile.computed) profiles.push_back(profile_panel(e));
  return {{"kind", "fit"},
          {"status", to_string(fit.status)},
          {"message", fit.message},
          {"chi2", page_number(fit.chi2)},
          {"dof", fit.dof},
          {"rows", fit.rows},
          {"estimates", r.at("estimates")},
          {"unidentifiable", fit.unidentifiable},
          {"correlation", r.at("correlation")},
          {"panels", panels},
          {"residuals", residuals},
          {"profiles", profiles}};
}

}  // namespace rbcstab
