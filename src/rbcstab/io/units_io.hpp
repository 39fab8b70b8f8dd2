#pragma once
// JSON and text views of a units conversion (rbcstab units): the physical inputs, each dimensionless number with its
// formula and the paper's equation, and the time unit in seconds.
#include <nlohmann/json.hpp>
#include <string>

#include "rbcstab/model/physical.hpp"

namespace rbcstab {

// Keys: B, C, lambda, alpha, Lambda, S, Delta, Delta0 (null with <key>_reason when an input is missing), R_m,
// time_unit_s; "physical" (the completed inputs, SI, by their scene keys), "derived_physical" (the inputs completed
// from dimensionless numbers), "formulas" ({key: {formula, reference}}).
nlohmann::json units_json(const UnitsAnswer& a);
std::string units_text(const UnitsAnswer& a);

}  // namespace rbcstab
