#include "rbcstab/inverse/observations.hpp"

#include <cmath>
#include <map>
#include <sstream>

#include "rbcstab/core/constants.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/core/text.hpp"
#include "rbcstab/io/experiments.hpp"
#include "rbcstab/io/files.hpp"

namespace rbcstab {

namespace {

enum class Dimension { angle, frequency, rate, none };

Dimension dimension_of(Observable o) {
  switch (o) {
    case Observable::inclination_angle:
    case Observable::swinging_amplitude:
      return Dimension::angle;
    case Observable::swinging_frequency:
    case Observable::tank_treading_frequency:
      return Dimension::frequency;
    case Observable::transition_shear_rate:
      return Dimension::rate;
    case Observable::regime:
      return Dimension::none;
  }
  return Dimension::none;
}

struct UnitFactor {
  const char* name;
  double factor;
};
// Frequencies are cycles per time: "Hz" and "1/s" are the same unit, "rad/s" an angular frequency.
const std::map<Dimension, std::vector<UnitFactor>> kUnits = {
    {Dimension::angle, {{"deg", kPi / 180}, {"rad", 1.0}}},
    {Dimension::frequency, {{"Hz", 1.0}, {"1/s", 1.0}, {"rad/s", 1.0 / kTwoPi}}},
    {Dimension::rate, {{"1/s", 1.0}}},
    {Dimension::none, {}}};

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t");
  return s.substr(b, e - b + 1);
}

// A condition column's header: its name and the factor to SI from the bracket ("viscosity[mPa s]").
struct ConditionColumn {
  const char* name;
  double default_factor;                  // without a bracket
  std::vector<UnitFactor> bracket_units;  // accepted in the bracket
};
const ConditionColumn kConditions[] = {
    {"shear_rate", 1.0, {{"1/s", 1.0}}},
    {"viscosity", 1e-3, {{"mPa s", 1e-3}, {"Pa s", 1.0}}},
};

const char* const kRequired[] = {"observable", "shear_rate", "viscosity", "value", "uncertainty", "unit"};

}  // namespace

std::string canonical_unit(Observable o) {
  switch (dimension_of(o)) {
    case Dimension::angle:
      return "rad";
    case Dimension::frequency:
      return "Hz";
    case Dimension::rate:
      return "1/s";
    case Dimension::none:
      return "";
  }
  return "";
}

std::string accepted_observation_units(Observable o) {
  std::string out;
  for (const UnitFactor& u : kUnits.at(dimension_of(o))) out += (out.empty() ? "" : "|") + std::string(u.name);
  return out.empty() ? "(empty)" : out;
}

double observation_unit_factor(Observable o, const std::string& unit) {
  for (const UnitFactor& u : kUnits.at(dimension_of(o)))
    if (unit == u.name) return u.factor;
  return ObservedRow::none;
}

ObservationData parse_observation_data(const std::string& text, const std::string& path) {
  ObservationData data;
  data.path = path;
  std::istringstream in(text);
  std::string line;
  int number = 0;
  std::map<std::string, std::size_t> column;  // canonical name -> field index
  std::map<std::string, double> factor;       // condition column -> SI factor from its header
  std::size_t header_fields = 0;
  auto fail = [&](const std::string& col, const std::string& what) {
    throw InvalidArgument("data", path + ":" + std::to_string(number) + ": column '" + col + "': " + what);
  };
  while (std::getline(in, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (!line.empty() && line[0] == '#') {
      data.comments.push_back(trim(line.substr(1)));
      continue;
    }
    if (trim(line).empty()) continue;
    const std::vector<std::string> f = csv_fields(line);
    if (column.empty()) {
      header_fields = f.size();
      for (std::size_t k = 0; k < f.size(); ++k) {
        std::string name = trim(f[k]);
        const auto open = name.find('[');
        if (open != std::string::npos) {
          const auto close = name.find(']', open);
          const std::string base = trim(name.substr(0, open));
          const std::string unit = close == std::string::npos ? "" : trim(name.substr(open + 1, close - open - 1));
          const ConditionColumn* cond = nullptr;
          for (const ConditionColumn& c : kConditions)
            if (base == c.name) cond = &c;
          if (!cond) fail(name, "only shear_rate and viscosity carry a unit in the header");
          std::string allowed;
          for (const UnitFactor& u : cond->bracket_units) {
            allowed += (allowed.empty() ? "" : ", ") + std::string(u.name);
            if (unit == u.name) factor[base] = u.factor;
          }
          if (close == std::string::npos || close + 1 != name.size() || !factor.count(base))
            fail(name, "unit '" + unit + "' is not one of: " + allowed);
          name = base;
        }
        if (column.count(name)) fail(name, "appears twice in the header");
        column[name] = k;
      }
      for (const char* c : kRequired)
        if (!column.count(c))
          fail(c,
               "missing from the header (required: observable, shear_rate, viscosity, value, "
               "uncertainty, unit; optional: regime, note)");
      for (const ConditionColumn& c : kConditions)
        if (!factor.count(c.name)) factor[c.name] = c.default_factor;
      continue;
    }
    if (f.size() != header_fields)
      fail("*", std::to_string(f.size()) + " fields, the header has " + std::to_string(header_fields));
    auto text_of = [&](const std::string& c) { return column.count(c) ? trim(f[column.at(c)]) : std::string(); };
    // A finite number (> 0 when positive); NaN for an empty field.
    auto number_of = [&](const std::string& c, bool positive) {
      const std::string v = text_of(c);
      if (v.empty()) return ObservedRow::none;
      const std::optional<double> x = read_number(v);
      if (!x) fail(c, number_error(v));
      if (!std::isfinite(*x)) fail(c, "'" + v + "' is not finite");
      if (positive && *x <= 0) fail(c, "'" + v + "' must be > 0");
      return *x;
    };
    ObservedRow o;
    o.line = number;
    const std::string name = text_of("observable");
    bool known = false;
    for (const auto& e : EnumTable<Observable>::entries)
      if (name == e.name) {
        o.observable = e.value;
        known = true;
      }
    if (!known) {
      std::string names;
      for (const auto& e : EnumTable<Observable>::entries) names += (names.empty() ? "" : ", ") + std::string(e.name);
      fail("observable", "'" + name + "' is not an observable: must be one of " + names);
    }
    o.note = text_of("note");
    const std::string regime = text_of("regime");
    if (!regime.empty()) {
      bool found = false;
      std::string names;
      for (const auto& e : EnumTable<Regime>::entries) {
        if (e.value == Regime::undetermined) continue;
        names += (names.empty() ? "" : ", ") + std::string(e.name);
        if (regime == e.name) {
          o.regime = e.value;
          found = true;
        }
      }
      if (!found) fail("regime", "'" + regime + "' is not a regime: must be one of " + names);
      o.has_regime = true;
    }
    o.viscosity = number_of("viscosity", true) * factor.at("viscosity");
    if (std::isnan(o.viscosity)) fail("viscosity", "empty: every row needs the outer viscosity");
    o.shear_rate = number_of("shear_rate", true) * factor.at("shear_rate");
    const bool transition = o.observable == Observable::transition_shear_rate;
    if (transition && !std::isnan(o.shear_rate))
      fail("shear_rate", "must be empty on a transition_shear_rate row (its value is the shear rate)");
    if (!transition && std::isnan(o.shear_rate)) fail("shear_rate", "empty: this observable needs a shear rate");
    o.unit = text_of("unit");
    const double value = number_of("value", false), uncertainty = number_of("uncertainty", false);
    if (o.observable == Observable::regime) {
      if (!o.has_regime) fail("regime", "empty: a regime row names the regime seen");
      if (!std::isnan(value)) fail("value", "must be empty on a regime row");
      if (!std::isnan(uncertainty)) fail("uncertainty", "must be empty on a regime row");
      if (!o.unit.empty()) fail("unit", "must be empty on a regime row");
    } else {
      if (std::isnan(value)) fail("value", "empty: a " + name + " row needs a value");
      if (std::isnan(uncertainty)) fail("uncertainty", "empty: a " + name + " row needs an uncertainty");
      if (uncertainty <= 0) fail("uncertainty", "'" + text_of("uncertainty") + "' must be > 0");
      const double k = observation_unit_factor(o.observable, o.unit);
      if (std::isnan(k))
        fail("unit", "'" + o.unit + "' is not a unit of " + name + ": must be one of " +
                         accepted_observation_units(o.observable));
      if (transition && value <= 0) fail("value", "'" + text_of("value") + "' must be > 0 (a shear rate)");
      o.value = value * k;
      o.uncertainty = uncertainty * k;
    }
    data.rows.push_back(o);
  }
  if (column.empty()) {
    number = std::max(number, 1);
    fail("*",
         "the file is empty: no header row (required columns: observable, shear_rate, viscosity, value, "
         "uncertainty, unit)");
  }
  if (data.rows.empty()) fail("*", "no data rows after the header");
  return data;
}

ObservationData read_observation_data(const std::string& path) {
  return parse_observation_data(read_file(path, "data"), path);
}

nlohmann::json to_json(const ObservedRow& o) {
  auto num = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); };
  nlohmann::json j = {{"line", o.line},
                      {"observable", to_string(o.observable)},
                      {"shear_rate", num(o.shear_rate)},
                      {"viscosity", num(o.viscosity)},
                      {"value", num(o.value)},
                      {"uncertainty", num(o.uncertainty)},
                      {"unit", canonical_unit(o.observable)}};
  j["regime"] = o.has_regime ? nlohmann::json(to_string(o.regime)) : nlohmann::json(nullptr);
  if (!o.note.empty()) j["note"] = o.note;
  return j;
}

}  // namespace rbcstab
