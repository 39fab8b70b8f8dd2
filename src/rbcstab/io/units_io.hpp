#pragma once
// JSON and text views of a units conversion (rbcstab units): the physical inputs, each dimensionless number with its
// formula and the paper's equation, and the time unit in seconds.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "rbcstab/model/physical.hpp"
#include "rbcstab/model/scene.hpp"

namespace rbcstab {

// Keys: B, C, lambda, alpha, Lambda, S, Delta, Delta0 (null with <key>_reason when an input is missing), R_m,
// time_unit_s; "physical" (the completed inputs, SI, by their scene keys), "derived_physical" (the inputs completed
// from dimensionless numbers), "formulas" ({key: {formula, reference}}).
nlohmann::json units_json(const UnitsAnswer& a);
std::string units_text(const UnitsAnswer& a);

// A model quantity as the text outputs write it: the model's number, then on a physical scene the same in SI
// ("0.5 (0.0005 s)"); only the number otherwise. Every physical output (summary, thresholds, post) writes its times,
// rates and tensions through this, so none goes out without its unit.
class UnitText {
 public:
  explicit UnitText(const Scene& scene);
  bool physical() const { return cell_.has_value(); }
  std::string time(double t) const;         // units of 1/gamma, and s
  std::string seconds(double t) const;      // " (<t> s)", or "" when not physical
  std::string rate(double r) const;         // units of gamma, and 1/s
  std::string tension(double sigma) const;  // units of kappa/R^2, and N/m
  double tension_unit() const;              // N/m; NaN when not physical

 private:
  std::optional<CellNumbers> cell_;
};
// An angle in radians and degrees: "0.785398 rad (45 deg)".
std::string degrees_text(double radians);

}  // namespace rbcstab
