#pragma once
// Observations of red blood cells in shear flow, in physical units with their uncertainties: the data a fit of the
// membrane's properties reads (docs/inverse.md "Data format"). One CSV file: '#' lines are comments, then a header
// row, then one observation per row.
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "rbcstab/analysis/predictors.hpp"
#include "rbcstab/core/enum_table.hpp"

namespace rbcstab {

// What a row observed. Angles are of the cell's long axis to the flow direction (psi = Psi/2 of Eq. subs);
// frequencies are cycles per time.
enum class Observable {
  inclination_angle,        // time-mean <psi> (tank-treading or swinging)
  swinging_amplitude,       // half the peak-to-peak range of psi on the attractor
  swinging_frequency,       // frequency of the psi oscillation
  tank_treading_frequency,  // rotation frequency of the membrane
  transition_shear_rate,    // the shear rate where tumbling gives way to swinging at the row's viscosity
  regime,                   // the regime seen at the row's shear rate and viscosity (the regime column)
};
template <>
struct EnumTable<Observable> {
  static constexpr EnumName<Observable> entries[] = {{Observable::inclination_angle, "inclination_angle"},
                                                     {Observable::swinging_amplitude, "swinging_amplitude"},
                                                     {Observable::swinging_frequency, "swinging_frequency"},
                                                     {Observable::tank_treading_frequency, "tank_treading_frequency"},
                                                     {Observable::transition_shear_rate, "transition_shear_rate"},
                                                     {Observable::regime, "regime"}};
};

// The SI unit a row's value is held in: rad for angles, Hz (cycles per second) for frequencies, 1/s for rates;
// "" for a regime row.
std::string canonical_unit(Observable o);
// The units a row of this observable may give ("deg|rad").
std::string accepted_observation_units(Observable o);
// The factor taking a value in `unit` to canonical_unit(o) (deg: pi/180; rad/s: 1/(2 pi) cycles per second);
// NaN when `unit` does not fit `o`.
double observation_unit_factor(Observable o, const std::string& unit);

struct ObservedRow {
  static constexpr double none = std::numeric_limits<double>::quiet_NaN();
  int line = 0;  // the row's line in the file (1-based), for messages
  Observable observable = Observable::inclination_angle;
  double shear_rate = none;   // gamma, 1/s (none for transition_shear_rate)
  double viscosity = none;    // outer viscosity eta_ex, Pa s
  double value = none;        // in canonical_unit(observable); none for a regime row
  double uncertainty = none;  // one standard deviation, same unit, > 0; none for a regime row
  std::string unit;           // as the row gave it
  bool has_regime = false;    // the regime column named one
  Regime regime = Regime::undetermined;
  std::string note;
};

struct ObservationData {
  std::string path;
  std::vector<std::string> comments;  // the '#' lines without the '#' (citation, figure, how values were read)
  std::vector<ObservedRow> rows;
};

// Reads the CSV text. Throws InvalidArgument("data", "<path>:<line>: column '<column>': ...") naming the row's file
// line and the column for: a missing required column (the header's line), an unknown condition unit in a header
// bracket, a row with another number of fields than the header, a number that does not parse or is not finite
// (> 0 for the conditions and uncertainty), a unit that does not parse or does not fit the observable, a regime
// label that is not a Regime name, a transition row with a shear rate, a regime row with a value; and an empty file
// (no header or no rows).
ObservationData parse_observation_data(const std::string& text, const std::string& path);
ObservationData read_observation_data(const std::string& path);

nlohmann::json to_json(const ObservedRow& o);

}  // namespace rbcstab
