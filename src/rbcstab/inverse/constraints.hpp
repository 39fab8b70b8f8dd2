#pragma once
// Regime observations as inequality constraints of the fit (docs/inverse.md "Regime rows as constraints"). A row
// that saw the cell swing or tank-tread at (gamma, eta) asks for gamma above the model's tumbling-to-swinging
// transition shear rate gamma_c(eta); one that saw it tumble, below. The margin
//   g = s (ln gamma - ln gamma_c(eta)) >= 0,  s = +1 (swinging, tank-treading) or -1 (tumbling),
// is smooth in the parameters (gamma_c is, to transition_rtol) and in units of ln gamma; gamma_c is computed once
// per viscosity.
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <vector>

#include "rbcstab/inverse/forward.hpp"
#include "rbcstab/inverse/observations.hpp"

namespace rbcstab {

struct RegimeConstraint {
  int line = 0;
  Regime observed = Regime::undetermined;
  double shear_rate = 0, viscosity = 0;
  double sign = 1;
};
// The in-plane regime rows of `data` (swinging, tank-treading, tumbling); rolling and oscillating-out-of-plane rows
// are compared only (the transition they would need is out of the plane).
std::vector<RegimeConstraint> regime_constraints(const ObservationData& data);

struct ConstraintValues {
  bool ok = false;
  std::string reason;                  // why a margin has no value (no transition at a row's viscosity)
  std::vector<double> margin;          // per constraint
  std::vector<std::vector<double>> J;  // per constraint x free: d margin / d x (central differences; step > 0)
};
// The margins at `cell` and, when step > 0, their Jacobian in the fitted coordinates of `free` by central
// differences at `step` (the transition has no derivative route).
ConstraintValues constraint_values(std::span<const RegimeConstraint> c, std::span<const FitParameter> free,
                                   const CellModel& cell, const ForwardOptions& options, double step);

// A constraint at the fit's estimate.
struct ConstraintResult {
  RegimeConstraint row;
  double margin = kNotGiven;      // s (ln gamma - ln gamma_c) at the estimate
  double multiplier = kNotGiven;  // >= 0: the best start's d(chi^2/2)/d margin (Ipopt's, negated)
  bool active = false;            // margin < kActiveMargin: the observed regime bounds the estimate
  bool violated = false;          // margin < -kViolatedMargin: the estimate contradicts the observed regime
};
inline constexpr double kActiveMargin = 1e-3;    // ln gamma: the estimate's gamma_c within 0.1 % of the row's gamma
inline constexpr double kViolatedMargin = 1e-4;  // Ipopt's default constr_viol_tol
nlohmann::json to_json(const ConstraintResult& c);
std::string constraint_text(const ConstraintResult& c);

}  // namespace rbcstab
