#include "rbcstab/io/units_io.hpp"

#include <cmath>
#include <iomanip>
#include <sstream>

#include "rbcstab/core/constants.hpp"
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

namespace {
std::string with_unit(double x, double unit, const char* name) {
  TextStream o;
  o << std::setprecision(6) << x;
  if (!std::isnan(unit)) o << " (" << x * unit << name << ")";
  return o.str();
}
}  // namespace

UnitText::UnitText(const Scene& scene) {
  if (scene.physical) cell_ = cell_numbers(*scene.physical);
}
std::string UnitText::time(double t) const { return with_unit(t, cell_ ? cell_->time_unit : kNotGiven, " s"); }
std::string UnitText::seconds(double t) const {
  TextStream o;
  if (cell_) o << std::setprecision(6) << " (" << t * cell_->time_unit << " s)";
  return o.str();
}
std::string UnitText::rate(double r) const { return with_unit(r, cell_ ? 1 / cell_->time_unit : kNotGiven, " 1/s"); }
std::string UnitText::tension(double sigma) const { return with_unit(sigma, tension_unit(), " N/m"); }
double UnitText::tension_unit() const { return cell_ ? cell_->tension_unit : kNotGiven; }

std::string degrees_text(double radians) {
  TextStream o;
  o << std::setprecision(6) << radians << " rad (" << radians * 180 / kPi << " deg)";
  return o.str();
}

}  // namespace rbcstab
