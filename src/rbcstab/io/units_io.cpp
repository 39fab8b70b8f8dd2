#include "rbcstab/io/units_io.hpp"

#include <cmath>
#include <iomanip>
#include <sstream>

#include "rbcstab/core/text.hpp"
#include "rbcstab/io/json.hpp"
#include "rbcstab/io/scene_file.hpp"

namespace rbcstab {

namespace {
// The JSON key of a number: R and the time unit carry their unit.
std::string json_key(const std::string& key) { return key == "R" ? "R_m" : key; }

}  // namespace

nlohmann::json units_json(const UnitsAnswer& a) {
  nlohmann::json j = nlohmann::json::object(), formulas = nlohmann::json::object();
  for (const NumberFormula& f : number_formulas()) {
    const std::string key = json_key(f.key);
    put_number(j, key, f.value(a.numbers), "not determined: an input of " + std::string(f.formula) + " is missing");
    formulas[key] = {{"formula", f.formula}, {"reference", f.reference}};
  }
  j["physical"] = to_json(a.cell);
  j["derived_physical"] = a.derived_physical;
  j["formulas"] = formulas;
  return j;
}

std::string units_text(const UnitsAnswer& a) {
  TextStream out;
  out << std::setprecision(6);
  out << "Physical inputs (SI):\n";
  const nlohmann::json given = to_json(a.cell);  // a named object: iterating a temporary's items() dangles
  for (const auto& [key, v] : given.items()) {
    bool derived = false;
    for (const std::string& d : a.derived_physical) derived = derived || d == key;
    out << "  " << std::left << std::setw(20) << key << v.get<double>()
        << (derived ? "  (from the dimensionless input)" : "") << "\n";
  }
  out << "Dimensionless numbers (paper Sec. II):\n";
  for (const NumberFormula& f : number_formulas()) {
    const double v = f.value(a.numbers);
    TextStream value;
    value << std::setprecision(6);
    if (std::isnan(v))
      value << "-";
    else
      value << v;
    out << "  " << std::left << std::setw(12) << json_key(f.key) << std::setw(14) << value.str() << std::setw(48)
        << f.formula << f.reference << "\n";
  }
  return out.str();
}

}  // namespace rbcstab
