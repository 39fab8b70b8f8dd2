#include "rbcstab/model/physical.hpp"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <iomanip>
#include <numbers>
#include <sstream>
#include <utility>

#include "rbcstab/core/constants.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/model/parameter_table.hpp"

namespace rbcstab {

namespace {

// Decimal prefixes a suffix may take ("u" and the micro signs are the same prefix).
struct Prefix {
  const char* text;
  double factor;
};
constexpr Prefix kLengthPrefixes[] = {
    {"", 1}, {"c", 1e-2}, {"m", 1e-3}, {"u", 1e-6}, {"\xC2\xB5", 1e-6}, {"\xCE\xBC", 1e-6}, {"n", 1e-9}};
constexpr Prefix kSmallPrefixes[] = {{"", 1},     {"m", 1e-3},  {"u", 1e-6},  {"\xC2\xB5", 1e-6}, {"\xCE\xBC", 1e-6},
                                     {"n", 1e-9}, {"p", 1e-12}, {"f", 1e-15}, {"a", 1e-18},       {"z", 1e-21}};

// Every accepted suffix of a unit (as written after removing spaces, '*' and '.') with its factor to SI.
std::vector<std::pair<std::string, double>> suffixes(PhysicalUnit unit) {
  std::vector<std::pair<std::string, double>> out;
  auto prefixed = [&](const auto& prefixes, const std::string& symbol) {
    for (const Prefix& p : prefixes) out.emplace_back(p.text + symbol, p.factor);
  };
  auto powers = [&](int n, std::initializer_list<const char*> marks) {
    for (const Prefix& p : kLengthPrefixes)
      for (const char* mark : marks) out.emplace_back(std::string(p.text) + "m" + mark, std::pow(p.factor, n));
  };
  switch (unit) {
    case PhysicalUnit::per_second:
      for (const char* s : {"1/s", "/s", "s^-1", "s-1", "Hz"}) out.emplace_back(s, 1);
      break;
    case PhysicalUnit::pascal_second:
      prefixed(kSmallPrefixes, "Pas");
      out.emplace_back("cP", 1e-3);
      out.emplace_back("P", 0.1);
      break;
    case PhysicalUnit::metre:
      powers(1, {""});
      break;
    case PhysicalUnit::square_metre:
      powers(2, {"^2", "2", "\xC2\xB2"});
      break;
    case PhysicalUnit::cubic_metre:
      powers(3, {"^3", "3", "\xC2\xB3"});
      for (const char* s : {"fL", "fl"}) out.emplace_back(s, 1e-18);  // 1 fL = 1 um^3: a cell volume's unit
      break;
    case PhysicalUnit::joule:
      prefixed(kSmallPrefixes, "J");
      break;
    case PhysicalUnit::newton_per_metre:
      prefixed(kSmallPrefixes, "N/m");
      prefixed(kSmallPrefixes, "Pam");
      out.emplace_back("pN/um", 1e-6);
      break;
    case PhysicalUnit::kelvin:
      out.emplace_back("K", 1);
      break;
  }
  return out;
}

std::string strip_separators(std::string_view s) {
  std::string out;
  for (char c : s)
    if (c != ' ' && c != '\t' && c != '*' && c != '.') out += c;
  return out;
}

bool given(double v) { return !std::isnan(v); }

// The physical keys of the cell, in PhysicalCell order, with their values, units and the range a bare SI number
// must lie in (wide: vesicles and cells from ~10 nm to 1 mm, fluids from gases to glycerol mixtures; outside, a
// unit must be stated), and the red cell's typical value, the centre a suggested unit aims at.
struct Field {
  const char* key;
  double PhysicalCell::*value;
  PhysicalUnit unit;
  double min, max, typical;
};
constexpr Field kFields[] = {
    {"temperature", &PhysicalCell::temperature, PhysicalUnit::kelvin, 200, 400, 310},
    {"shear_rate", &PhysicalCell::shear_rate, PhysicalUnit::per_second, 1e-6, 1e9, 100},
    {"viscosity", &PhysicalCell::viscosity, PhysicalUnit::pascal_second, 1e-5, 0.5, 1.2e-3},
    {"inner_viscosity", &PhysicalCell::inner_viscosity, PhysicalUnit::pascal_second, 1e-5, 0.5, 6e-3},
    {"radius", &PhysicalCell::radius, PhysicalUnit::metre, 1e-8, 1e-3, 2.8e-6},
    {"area", &PhysicalCell::area, PhysicalUnit::square_metre, 1e-15, 1e-5, 134e-12},
    {"volume", &PhysicalCell::volume, PhysicalUnit::cubic_metre, 1e-24, 1e-8, 94e-18},
    {"stress_free_volume", &PhysicalCell::stress_free_volume, PhysicalUnit::cubic_metre, 1e-24, 1e-8, 94e-18},
    {"bending_modulus", &PhysicalCell::bending_modulus, PhysicalUnit::joule, 1e-21, 1e-16, 2e-19},
    {"shear_modulus", &PhysicalCell::shear_modulus, PhysicalUnit::newton_per_metre, 1e-9, 1e-3, 6e-6}};

const Field& field_of(std::string_view key) {
  for (const Field& f : kFields)
    if (key == f.key) return f;
  throw InvalidArgument(std::string(key), std::string(key) + " is not a physical key");
}

// The shortest of 15..17 significant digits that reads back as v ("2.8", not "2.7999999999999998").
std::string full_precision(double v) {
  std::string out;
  for (int digits = 15; digits <= 17; ++digits) {
    std::ostringstream s;
    s << std::setprecision(digits) << v;
    out = s.str();
    if (std::strtod(out.c_str(), nullptr) == v) break;
  }
  return out;
}

// R from the radius, or from the volume when the area and volume give the size.
double radius_of(const PhysicalCell& c) { return given(c.radius) ? c.radius : equivalent_radius(c.volume); }
}  // namespace

std::string si_unit(PhysicalUnit unit) {
  switch (unit) {
    case PhysicalUnit::per_second:
      return "1/s";
    case PhysicalUnit::pascal_second:
      return "Pa s";
    case PhysicalUnit::metre:
      return "m";
    case PhysicalUnit::square_metre:
      return "m^2";
    case PhysicalUnit::cubic_metre:
      return "m^3";
    case PhysicalUnit::joule:
      return "J";
    case PhysicalUnit::newton_per_metre:
      return "N/m";
    case PhysicalUnit::kelvin:
      return "K";
  }
  return "";
}

std::string accepted_units(PhysicalUnit unit) {
  switch (unit) {
    case PhysicalUnit::per_second:
      return "1/s, /s, s^-1, Hz";
    case PhysicalUnit::pascal_second:
      return "Pa s, mPa s, uPa s, cP, P";
    case PhysicalUnit::metre:
      return "m, cm, mm, um, nm";
    case PhysicalUnit::square_metre:
      return "m^2, mm^2, um^2, nm^2 (also um2)";
    case PhysicalUnit::cubic_metre:
      return "m^3, mm^3, um^3, nm^3 (also um3), fL";
    case PhysicalUnit::joule:
      return "J, mJ, ..., aJ, zJ, kBT (at the stated temperature)";
    case PhysicalUnit::newton_per_metre:
      return "N/m, mN/m, uN/m, nN/m, pN/um, uPa m";
    case PhysicalUnit::kelvin:
      return "K";
  }
  return "";
}

double parse_quantity(std::string_view text, PhysicalUnit unit, std::string_view name, double temperature) {
  const std::string s(text), n(name);
  const std::string form = n + " = '" + s + "' must be a number in " + si_unit(unit) +
                           ", optionally followed by a unit (" + accepted_units(unit) + ")";
  const char* begin = s.c_str();
  char* end = nullptr;
  const double number = std::strtod(begin, &end);
  if (end == begin || s.empty() || std::isspace(static_cast<unsigned char>(s[0]))) throw InvalidArgument(n, form);
  const std::string suffix = strip_separators(std::string_view(end));
  double factor = 1;
  if (!suffix.empty()) {
    bool found = false;
    if (unit == PhysicalUnit::joule && (suffix == "kBT" || suffix == "kT")) {
      if (!(std::isfinite(temperature) && temperature > 0))
        throw InvalidArgument(n, n + " = '" + s + "' is in kBT: state the temperature [K] too");
      factor = kBoltzmann * temperature;
      found = true;
    }
    for (const auto& [spelling, f] : suffixes(unit))
      if (!found && suffix == spelling) {
        factor = f;
        found = true;
      }
    if (!found) throw InvalidArgument(n, form);
  }
  const double value = number * factor;
  if (!(std::isfinite(value) && value > 0))
    throw InvalidArgument(n, n + " = '" + s + "' is out of range: must be finite and > 0 (" + si_unit(unit) + ")");
  return value;
}

PlausibleRange plausible_range(std::string_view key) {
  const Field& f = field_of(key);
  return {f.unit, f.min, f.max, f.typical};
}

double& physical_value(PhysicalCell& cell, std::string_view key) { return cell.*field_of(key).value; }

bool plausible_bare(std::string_view key, double value) {
  const Field& f = field_of(key);
  return value >= f.min && value <= f.max;
}

void require_plausible_bare(std::string_view key, double value) {
  const Field& f = field_of(key);
  // Not finite or <= 0: the positivity checks refuse it with their own message.
  if (!(std::isfinite(value) && value > 0) || plausible_bare(key, value)) return;
  const std::string unit = si_unit(f.unit), k(key), v = format_value(value);
  std::string suggestion;
  double best = kNotGiven;
  auto candidates = suffixes(f.unit);
  if (f.unit == PhysicalUnit::joule)  // a modulus given as a multiple of kBT, at the typical temperature
    candidates.emplace_back("kBT (with a temperature)", kBoltzmann * field_of("temperature").typical);
  for (const auto& [spelling, factor] : candidates) {
    const double x = value * factor;
    const bool ascii = std::all_of(spelling.begin(), spelling.end(), [](char c) { return (c & 0x80) == 0; });
    const double distance = std::abs(std::log(x / f.typical));
    if (factor != 1 && ascii && x >= f.min && x <= f.max && !(distance >= best)) {
      best = distance;
      suggestion = spelling.ends_with("Pas") ? spelling.substr(0, spelling.size() - 1) + " s" : spelling;
    }
  }
  throw InvalidArgument(k, k + " = " + v + " (a bare number, read as " + v + " " + unit + ") is not a plausible " + k +
                               ": a bare number must be in [" + format_value(f.min) + ", " + format_value(f.max) +
                               "] " + unit +
                               (suggestion.empty() ? "." : "; did you mean " + v + " " + suggestion + "?") +
                               " Give the unit to state any other value (" + accepted_units(f.unit) + ")");
}

bool has_unit(std::string_view text) {
  const std::string s(text);
  char* end = nullptr;
  std::strtod(s.c_str(), &end);
  return !strip_separators(std::string_view(end)).empty();
}

bool needs_unit_text(std::string_view key, double value) { return !std::isnan(value) && !plausible_bare(key, value); }

std::string with_si_unit(std::string_view key, double value) {
  return full_precision(value) + " " + si_unit(field_of(key).unit);
}

namespace {
void require_positive(const PhysicalCell& c) {
  for (const Field& f : kFields) {
    const double v = c.*f.value;
    if (given(v)) require(std::isfinite(v) && v > 0, f.key, v, "finite and > 0");
  }
}
}  // namespace

void PhysicalCell::validate() const {
  require_positive(*this);
  auto both = [](const char* a, const char* b, const char* why) {
    throw InvalidArgument(a, std::string(a) + " and " + b + " both given: " + why);
  };
  if (given(radius) && given(area)) both("radius", "area", "the size is the radius or the area with the volume");
  if (given(radius) && given(volume)) both("radius", "volume", "R = (3V/4 pi)^(1/3): give the radius or the volume");
  if (given(area) != given(volume))
    throw InvalidArgument(given(area) ? "area" : "volume",
                          std::string(given(area) ? "area" : "volume") + " is given without " +
                              (given(area) ? "volume" : "area") +
                              ": Delta = A/R^2 - 4 pi with R = (3V/4 pi)^(1/3) needs both");
  if (given(stress_free_volume) && !given(area))
    throw InvalidArgument("stress_free_volume",
                          "stress_free_volume is given without area: Delta0 = A/R0^2 - 4 pi needs the area");
  if (given(stress_free_volume))
    require(stress_free_volume >= volume, "stress_free_volume", stress_free_volume,
            ">= volume = " + format_value(volume) + " m^3 (Delta0 <= Delta: the cell loses volume at enucleation)");
}

void PhysicalCell::validate_complete() const {
  validate();
  const std::string needs =
      "a physical scene needs shear_rate, viscosity, radius (or area and volume), bending_modulus and shear_modulus";
  for (const char* key : {"shear_rate", "viscosity", "radius", "bending_modulus", "shear_modulus"}) {
    for (const Field& f : kFields)
      if (std::string_view(f.key) == key && !given(this->*f.value) &&
          !(std::string_view(key) == "radius" && given(area)))
        throw InvalidArgument(key, std::string(key) + " is missing: " + needs);
  }
}

double equivalent_radius(double volume) { return std::cbrt(3 * volume / (4 * kPi)); }
double excess_area(double area, double volume) {
  const double R = equivalent_radius(volume);
  return area / (R * R) - 4 * kPi;
}
double bending_number(double eta_ex, double shear_rate, double R, double kappa) {
  return eta_ex * shear_rate * R * R * R / kappa;
}
double capillary_number(double eta_ex, double shear_rate, double R, double mu) { return eta_ex * shear_rate * R / mu; }
double viscosity_ratio(double eta_in, double eta_ex) { return eta_in / eta_ex; }
double elasticity_ratio(double mu, double R, double kappa) { return mu * R * R / kappa; }

CellNumbers cell_numbers(const PhysicalCell& c) {
  CellNumbers n;
  n.R = radius_of(c);  // NaN propagates through every number that needs a missing input
  n.B = bending_number(c.viscosity, c.shear_rate, n.R, c.bending_modulus);
  n.C = capillary_number(c.viscosity, c.shear_rate, n.R, c.shear_modulus);
  n.lambda = viscosity_ratio(c.inner_viscosity, c.viscosity);
  n.alpha = elasticity_ratio(c.shear_modulus, n.R, c.bending_modulus);
  n.Delta = excess_area(c.area, c.volume);
  n.Delta0 = excess_area(c.area, c.stress_free_volume);
  n.time_unit = 1 / c.shear_rate;
  n.tension_unit = c.bending_modulus / (n.R * n.R);
  return n;
}

Parameters cell_parameters(const CellNumbers& n) {
  Parameters p;
  p.lambda = n.lambda;
  p.Delta = n.Delta;
  p.Delta0 = n.Delta0;
  p.B = n.B;
  p.C = n.C;
  return p;
}

std::vector<DerivedParameter> derived_parameters(const PhysicalCell& c) {
  const std::string size = given(c.radius) ? "radius" : "volume";
  std::vector<DerivedParameter> out = {{"B", {"shear_rate", "viscosity", size, "bending_modulus"}},
                                       {"C", {"shear_rate", "viscosity", size, "shear_modulus"}}};
  if (given(c.inner_viscosity)) out.push_back({"lambda", {"inner_viscosity", "viscosity"}});
  if (given(c.area)) out.push_back({"Delta", {"area", "volume"}});
  if (given(c.stress_free_volume)) out.push_back({"Delta0", {"stress_free_volume", "area"}});
  return out;
}

Parameters physical_parameters(const PhysicalCell& c, Parameters p) {
  const CellNumbers n = cell_numbers(c);
  p.B = n.B;
  p.C = n.C;
  if (given(c.inner_viscosity)) p.lambda = n.lambda;
  if (given(c.area)) p.Delta = n.Delta;
  if (given(c.stress_free_volume)) p.Delta0 = n.Delta0;
  return p;
}

Parameters at_shear_rate(const PhysicalCell& cell, Parameters p, double rate) {
  require(std::isfinite(rate) && rate > 0, "shear_rate", rate, "finite and > 0 (1/s)");
  const double ratio = rate / cell.shear_rate;
  p.B *= ratio;
  p.C *= ratio;
  return p;
}

PhysicalCell unit_cell(const Parameters& p) {
  PhysicalCell c;
  c.shear_rate = c.viscosity = c.radius = 1;
  c.bending_modulus = 1 / p.B;
  c.shear_modulus = 1 / p.C;
  return c;
}

const std::vector<NumberFormula>& number_formulas() {
  static const std::vector<NumberFormula> f = [] {
    std::vector<NumberFormula> out{
        {"R", "(3 V/(4 pi))^(1/3) [m]", "Sec. II, Fig. 1", [](const CellNumbers& n) { return n.R; }}};
    for (const ParameterRow& r : parameter_table())
      if (r.physical.formula) out.push_back({r.name, r.physical.formula, r.physical.reference, r.physical.value});
    out.push_back({"time_unit_s", "1/gamma [s]", "Sec. II (time in units of 1/gamma)",
                   [](const CellNumbers& n) { return n.time_unit; }});
    return out;
  }();
  return f;
}

UnitsAnswer convert_units(const UnitsQuery& q) {
  require_positive(q.cell);  // the pairs (area with volume) are checked once completed
  // Each given number in its row's domain, as a scene value; Delta0's upper end is Delta where one is known.
  Parameters known;
  known.Delta = given(q.Delta) ? q.Delta : excess_area(q.cell.area, q.cell.volume);
  for (const ParameterRow& r : parameter_table())
    if (r.physical.input && given(q.*r.physical.input))
      require_in(r.id, parameter_domain(r.id, known).known(), q.*r.physical.input);
  UnitsAnswer a;
  a.cell = q.cell;
  PhysicalCell& c = a.cell;
  // Fixes `key` from dimensionless `number`, once, when the inputs the formula needs are all given.
  auto fix = [&](const char* number, double value, const char* key, double PhysicalCell::*field,
                 std::initializer_list<std::pair<const char*, double>> needs, auto formula) {
    if (!given(value)) return;
    if (given(c.*field))
      throw InvalidArgument(
          number, std::string(number) + " and " + key + " both given: " + number + " fixes " + key + " here; give one");
    for (const auto& [need, v] : needs)
      if (!given(v))
        throw InvalidArgument(number,
                              std::string(number) + " = " + format_value(value) + " needs " + need + " to give " + key);
    c.*field = formula(value);
    a.derived_physical.emplace_back(key);
  };
  const double R = radius_of(c);
  const bool size = given(R);
  const char* size_name = given(c.area) ? "volume" : "radius (or area and volume)";
  fix("B", q.B, "shear_rate", &PhysicalCell::shear_rate,
      {{"viscosity", c.viscosity}, {size_name, R}, {"bending_modulus", c.bending_modulus}},
      [&](double B) { return B * c.bending_modulus / (c.viscosity * R * R * R); });
  if (given(q.B)) {
    fix("C", q.C, "shear_modulus", &PhysicalCell::shear_modulus,
        {{"viscosity", c.viscosity}, {size_name, R}, {"shear_rate", c.shear_rate}},
        [&](double C) { return c.viscosity * c.shear_rate * R / C; });
  } else {
    fix("C", q.C, "shear_rate", &PhysicalCell::shear_rate,
        {{"viscosity", c.viscosity}, {size_name, R}, {"shear_modulus", c.shear_modulus}},
        [&](double C) { return C * c.shear_modulus / (c.viscosity * R); });
  }
  fix("alpha", q.alpha, "shear_modulus", &PhysicalCell::shear_modulus,
      {{size_name, R}, {"bending_modulus", c.bending_modulus}},
      [&](double alpha) { return alpha * c.bending_modulus / (R * R); });
  if (given(c.viscosity))  // else lambda stays a dimensionless input
    fix("lambda", q.lambda, "inner_viscosity", &PhysicalCell::inner_viscosity, {{"viscosity", c.viscosity}},
        [&](double lambda) { return lambda * c.viscosity; });
  if (given(q.Delta) && !given(c.volume) && size) {
    // A radius alone: the volume it stands for, so that the area is A = (Delta + 4 pi) R^2 with R from V.
    c.volume = 4 * kPi / 3 * R * R * R;
    c.radius = kNotGiven;
  }
  if (size)  // else Delta stays a dimensionless input, and so does Delta0 without an area
    fix("Delta", q.Delta, "area", &PhysicalCell::area, {{"volume", c.volume}},
        [&](double Delta) { return (Delta + 4 * kPi) * std::pow(equivalent_radius(c.volume), 2); });
  if (given(c.area))
    fix("Delta0", q.Delta0, "stress_free_volume", &PhysicalCell::stress_free_volume, {{"area", c.area}},
        [&](double Delta0) { return 4 * kPi / 3 * std::pow(c.area / (Delta0 + 4 * kPi), 1.5); });
  c.validate();
  a.numbers = cell_numbers(c);
  CellNumbers& n = a.numbers;
  for (auto [number, input] : {std::pair{&n.lambda, q.lambda}, {&n.Delta, q.Delta}, {&n.Delta0, q.Delta0}})
    if (!given(*number)) *number = input;
  if (given(n.B) && given(n.C) && given(n.lambda) && given(n.Delta) && given(n.Delta0)) {
    a.parameters = cell_parameters(n);
  }
  return a;
}

}  // namespace rbcstab
