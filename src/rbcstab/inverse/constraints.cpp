#include "rbcstab/inverse/constraints.hpp"

#include <cmath>
#include <map>

#include "rbcstab/core/error.hpp"
#include "rbcstab/core/text.hpp"
#include "rbcstab/inverse/fit.hpp"

namespace rbcstab {

std::vector<RegimeConstraint> regime_constraints(const ObservationData& data) {
  std::vector<RegimeConstraint> out;
  for (const ObservedRow& o : data.rows) {
    if (o.observable != Observable::regime) continue;
    const bool swings = o.regime == Regime::swinging || o.regime == Regime::tank_treading;
    if (!swings && o.regime != Regime::tumbling) continue;
    out.push_back({o.line, o.regime, o.shear_rate, o.viscosity, swings ? 1.0 : -1.0});
  }
  return out;
}

namespace {

// The margins at one cell; ok false with the first row's reason when its viscosity has no transition.
bool margins_at(std::span<const RegimeConstraint> c, const CellModel& cell, const ForwardOptions& options,
                std::vector<double>& margin, std::string& reason) {
  std::map<double, Prediction> rate;  // per viscosity
  margin.clear();
  for (const RegimeConstraint& k : c) {
    auto it = rate.find(k.viscosity);
    if (it == rate.end()) {
      ObservedRow row;
      row.observable = Observable::transition_shear_rate;
      row.viscosity = k.viscosity;
      it = rate.emplace(k.viscosity, predict(cell, row, options)).first;
    }
    if (!it->second.ok()) {
      reason = "line " + std::to_string(k.line) + " (regime " + to_string(k.observed) + "): " + it->second.reason;
      return false;
    }
    margin.push_back(k.sign * (std::log(k.shear_rate) - std::log(it->second.value)));
  }
  return true;
}

}  // namespace

ConstraintValues constraint_values(std::span<const RegimeConstraint> c, std::span<const FitParameter> free,
                                   const CellModel& cell, const ForwardOptions& options, double step) {
  ConstraintValues v;
  if (!margins_at(c, cell, options, v.margin, v.reason)) return v;
  v.J.assign(c.size(), std::vector<double>(free.size(), 0.0));
  if (step > 0)
    for (std::size_t j = 0; j < free.size(); ++j) {
      const bool log_scale = fit_parameter_info(free[j], cell).log_scale;
      const double x = get_value(cell, free[j]), at = log_scale ? std::log(x) : x;
      std::vector<double> plus, minus;
      CellModel cp = cell, cm = cell;
      set_value(cp, free[j], log_scale ? std::exp(at + step) : at + step);
      set_value(cm, free[j], log_scale ? std::exp(at - step) : at - step);
      if (!margins_at(c, cp, options, plus, v.reason) || !margins_at(c, cm, options, minus, v.reason)) return v;
      for (std::size_t i = 0; i < c.size(); ++i) v.J[i][j] = (plus[i] - minus[i]) / (2 * step);
    }
  v.ok = true;
  return v;
}

void apply_constraints(FitResult& res, const std::vector<RegimeConstraint>& constraints,
                       std::span<const FitParameter> free, const ForwardOptions& options,
                       const std::vector<double>& multipliers) {
  const ConstraintValues v = constraint_values(constraints, free, res.cell, options, 0);
  std::string violated, active;
  for (std::size_t k = 0; k < constraints.size(); ++k) {
    ConstraintResult c;
    c.row = constraints[k];
    if (k < multipliers.size()) c.multiplier = -multipliers[k];  // Ipopt's sign: f + lambda g
    if (v.ok) {
      c.margin = v.margin[k];
      c.active = c.margin < kActiveMargin;
      c.violated = c.margin < -kViolatedMargin;
    }
    if (c.violated)
      violated += (violated.empty() ? "" : ", ") + std::string("line ") + std::to_string(c.row.line) + " (" +
                  to_string(c.row.observed) + " at " + format_value(c.row.shear_rate) + " 1/s)";
    if (c.active && !c.violated) active += (active.empty() ? "line " : ", line ") + std::to_string(c.row.line);
    res.constraints.push_back(c);
  }
  auto add = [&](const std::string& m) { res.message += (res.message.empty() ? "" : "; ") + m; };
  if (!v.ok) add("the regime constraints have no value at the estimate: " + v.reason);
  if (!violated.empty()) {
    res.status = FitStatus::infeasible;
    add("the observed regimes cannot all be met: " + violated +
        " disagree with the model's transition shear rate at the best point");
  } else if (res.status == FitStatus::infeasible) {
    add("Ipopt found the regime constraints infeasible");
  }
  // The Fisher intervals assume an unconstrained optimum, as at a bound; the profiles re-fit with the rows.
  if (!active.empty())
    add("the estimate lies on the regime constraint of " + active +
        " (active): the Fisher intervals ignore it, so they may reach into parameters the observed regimes exclude "
        "(the profiles re-fit with it)");
}

nlohmann::json to_json(const ConstraintResult& c) {
  auto num = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); };
  return {{"line", c.row.line},
          {"observed_regime", to_string(c.row.observed)},
          {"shear_rate", c.row.shear_rate},
          {"viscosity", c.row.viscosity},
          {"margin", num(c.margin)},
          {"multiplier", num(c.multiplier)},
          {"active", c.active},
          {"violated", c.violated}};
}

std::string constraint_text(const ConstraintResult& c) {
  return "line " + std::to_string(c.row.line) + " " + to_string(c.row.observed) + " at " +
         format_value(c.row.shear_rate) + " 1/s: margin " +
         (c.row.sign > 0 ? "ln(gamma/gamma_c)" : "ln(gamma_c/gamma)") + " = " +
         (std::isfinite(c.margin) ? format_value(c.margin) : "n/a") +
         (c.violated ? "  (violated)"
          : c.active ? "  (active)"
                     : "");
}

}  // namespace rbcstab
