#pragma once
// A cell and its flow in physical units, and the paper's dimensionless numbers made from them (Sec. II):
//   R = (3V/4 pi)^(1/3), Delta = A/R^2 - 4 pi, Delta0 = A/R0^2 - 4 pi with R0 = (3 V0/4 pi)^(1/3)  (Sec. II, Fig. 1)
//   B = eta_ex gamma R^3/kappa, C = eta_ex gamma R/mu                                          (Eq. dimless_nums)
//   lambda = eta_in/eta_ex (Sec. II), alpha = B/C = mu R^2/kappa (after Eq. inst), time unit 1/gamma.
// Values are SI; parse_quantity reads a number with an optional unit ("2e-19J", "50kBT", "6uN/m", "3.9um").
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "rbcstab/model/parameters.hpp"

namespace rbcstab {

inline constexpr double kNotGiven = std::numeric_limits<double>::quiet_NaN();  // a physical input not given

enum class PhysicalUnit {
  per_second,
  pascal_second,
  metre,
  square_metre,
  cubic_metre,
  joule,
  newton_per_metre,
  kelvin
};

inline constexpr double kBoltzmann = 1.380649e-23;  // J/K, exact in the SI since 2019

// The SI unit's name ("1/s", "Pa s", "J") and the suffixes accepted for it, for messages and --help.
std::string si_unit(PhysicalUnit unit);
std::string accepted_units(PhysicalUnit unit);
// A number with an optional unit suffix (spaces, '*' and '.' between unit symbols ignored: "1.2 mPa s",
// "1.2mPa.s"). Without a suffix the number is SI. "kBT" (joule) needs a finite temperature > 0 [K]. Throws
// InvalidArgument(name, "<name> = '<text>' ...") for a malformed number, an unknown unit, or a value that is
// not finite and > 0.
double parse_quantity(std::string_view text, PhysicalUnit unit, std::string_view name, double temperature = kNotGiven);

// A bare number (no unit) for a physical key is read in SI, so a radius of "2.8" is 2.8 m. It is accepted only
// within the key's plausible SI range (the field table in physical.cpp, the one place these ranges live); a number
// with a unit is taken as given. key: a PhysicalCell field name ("radius").
struct PlausibleRange {
  PhysicalUnit unit;
  double min, max;  // SI
  double typical;   // SI: the red cell's typical value (a fit's default start, a suggested unit's centre)
};
PlausibleRange plausible_range(std::string_view key);  // throws InvalidArgument for an unknown key
bool plausible_bare(std::string_view key, double value);
// Throws InvalidArgument(key, "<key> = <value> (a bare number, read as <value> <SI unit>) is not a plausible
// <key>: ... in [min, max] <SI unit>; did you mean <value> <unit>? ...") outside the range; the suggestion is
// the accepted unit that puts the number in range nearest the key's typical red-cell value (none when no unit
// does).
void require_plausible_bare(std::string_view key, double value);
// Whether a quantity's text ends in a unit ("3um": true, "3e-6": false).
bool has_unit(std::string_view text);
// A value as a writer puts it so it reads back as itself: the bare SI number when plausible, else the text
// "<value> <SI unit>" at full precision.
bool needs_unit_text(std::string_view key, double value);
std::string with_si_unit(std::string_view key, double value);

// The physical inputs; NaN: not given. A scene holding one derives its B, C (and lambda, Delta, Delta0 when
// their inputs are given) from it (physical_parameters).
struct PhysicalCell {
  double temperature = kNotGiven;         // K: only to read energies given in kBT
  double shear_rate = kNotGiven;          // gamma, 1/s
  double viscosity = kNotGiven;           // eta_ex, Pa s
  double inner_viscosity = kNotGiven;     // eta_in, Pa s (else lambda is dimensionless)
  double radius = kNotGiven;              // R, m (or area with volume)
  double area = kNotGiven;                // A, m^2
  double volume = kNotGiven;              // V, m^3
  double stress_free_volume = kNotGiven;  // V0, m^3 (with area: Delta0)
  double bending_modulus = kNotGiven;     // kappa, J
  double shear_modulus = kNotGiven;       // mu, N/m

  // Every given value finite and > 0; radius excludes area and volume; area needs volume and volume area;
  // stress_free_volume needs area, and V0 >= V (Delta0 <= Delta). Throws InvalidArgument naming the key(s).
  void validate() const;
  // validate() and the inputs of B and C: shear_rate, viscosity, radius (or area and volume), bending_modulus,
  // shear_modulus. Throws InvalidArgument("<key>", "... is missing: a physical scene needs ...").
  void validate_complete() const;
};

// The field of `cell` a key names (SI); throws InvalidArgument for an unknown key.
double& physical_value(PhysicalCell& cell, std::string_view key);

// The paper's symbols, each from its physical inputs (Sec. II).
double equivalent_radius(double volume);         // R = (3V/4 pi)^(1/3)
double excess_area(double area, double volume);  // A/R^2 - 4 pi, R from the volume (Delta; Delta0 from V0)
double bending_number(double eta_ex, double shear_rate, double R, double kappa);  // B = eta gamma R^3/kappa
double capillary_number(double eta_ex, double shear_rate, double R, double mu);   // C = eta gamma R/mu
double viscosity_ratio(double eta_in, double eta_ex);                             // lambda = eta_in/eta_ex
double elasticity_ratio(double mu, double R, double kappa);                       // alpha = mu R^2/kappa = B/C

// The dimensionless numbers a PhysicalCell determines; NaN where an input is missing.
struct CellNumbers {
  double R = kNotGiven;  // m
  double B = kNotGiven, C = kNotGiven, lambda = kNotGiven, alpha = kNotGiven, Delta = kNotGiven, Delta0 = kNotGiven;
  double time_unit = kNotGiven;     // s: 1/gamma, the model's unit of time
  double tension_unit = kNotGiven;  // N/m: kappa/R^2, the unit of the tension sigma (sigma_l^c = -(Pi + 4 alpha/Pi))
};
CellNumbers cell_numbers(const PhysicalCell& cell);
// The material Parameters of these numbers, NaN where one is missing (so Lambda and S are NaN where an input of
// theirs is).
Parameters cell_parameters(const CellNumbers& n);
// `p` with every number the cell determines replaced (validate_complete first).
Parameters physical_parameters(const PhysicalCell& cell, Parameters p);
// The shear rate as a path parameter: at a fixed cell and fluid B = b gamma and C = c gamma, so moving from the
// cell's shear rate to `rate` scales B and C together and keeps alpha (a line of slope 1 in the (ln B, ln C) plane).
// `p` holds the cell's numbers at cell.shear_rate; the cell's shear_rate is the caller's to update.
Parameters at_shear_rate(const PhysicalCell& cell, Parameters p, double rate);
// A dimensionless scene's cell in units where gamma = eta_ex = R = 1 (kappa = 1/B, mu = 1/C): its numbers are
// p's B and C, so the scene can move along shear_rate (B and C scaled by the rate) without physical inputs.
PhysicalCell unit_cell(const Parameters& p);
// The parameter keys (Parameters field names) the cell determines, in table order: B, C, then lambda, Delta,
// Delta0 when their inputs are given; each with the physical keys it is made from.
struct DerivedParameter {
  std::string parameter;              // "B"
  std::vector<std::string> physical;  // "shear_rate", "viscosity", "radius", "bending_modulus"
};
std::vector<DerivedParameter> derived_parameters(const PhysicalCell& cell);

// How each number is made, for `rbcstab units` and docs/theory.md: key (the JSON key), formula, paper reference
// and its value. R, then the parameter table's rows with a physical formula (model/parameter_table.hpp), then
// the time unit.
struct NumberFormula {
  const char* key;
  const char* formula;
  const char* reference;
  double (*value)(const CellNumbers& n);  // NaN where an input is missing
};
const std::vector<NumberFormula>& number_formulas();

// Both ways: the physical cell completed from given dimensionless numbers, then every number it determines.
// Each given number fixes one physical unknown (the row's PhysicalFormula::completes): B (or C without B) the
// shear rate, C with B the shear modulus, alpha the shear modulus, lambda the inner viscosity, Delta the area
// (from V or R), Delta0 the stress-free volume (from A). A given number outside its row's domain is refused as a
// scene value is; giving its unknown too is refused: InvalidArgument(number, "<number> and <key> both given
// ...: give one"); a number whose other inputs are missing is refused naming them.
struct UnitsQuery {
  PhysicalCell cell;
  double B = kNotGiven, C = kNotGiven, lambda = kNotGiven, alpha = kNotGiven, Delta = kNotGiven,
         Delta0 = kNotGiven;  // NaN: not given
};
struct UnitsAnswer {
  PhysicalCell cell;  // the inputs, completed
  CellNumbers numbers;
  std::optional<Parameters> parameters;       // when lambda, Delta, Delta0, B, C are all known: Lambda and S follow
  std::vector<std::string> derived_physical;  // the physical keys completed from dimensionless numbers
};
UnitsAnswer convert_units(const UnitsQuery& query);

}  // namespace rbcstab
