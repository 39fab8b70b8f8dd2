#pragma once
// Published observations of red blood cells in shear flow (data/experiments.csv), read for overlay on the
// physical phase diagram. Each row keeps its source and the text it rests on.
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace rbcstab {

struct PublishedObservation {
  std::string source, reference, observation;
  std::string kind;  // "stress" (a line eta_ex gamma = stress), "point", "rate_range" (rates at one viscosity)
  static constexpr double none = std::numeric_limits<double>::quiet_NaN();
  double viscosity = none;                            // Pa s
  double shear_rate_lo = none, shear_rate_hi = none;  // 1/s
  double stress = none;                               // Pa
  std::string precision;                              // "order" (order of magnitude) or "range"
  std::string basis;                                  // the statement the row rests on
};

// The rows of an observations CSV ('#' lines are comments; the header names the columns of data/experiments.csv).
// Throws InvalidArgument("experiments", "<path>:<line>: ...") naming the row and column for a missing column,
// a number that does not parse or is not finite and > 0, an unknown kind or precision, or a kind without the
// values it needs (stress: stress_Pa; point and rate_range: viscosity_Pa_s and both rates, lo <= hi).
std::vector<PublishedObservation> parse_observations(const std::string& text, const std::string& path);
std::vector<PublishedObservation> read_observations(const std::string& path);
// The shipped file: $RBCSTAB_DATA_DIR/data, then <exe>/../share/rbcstab/data, then the source tree ("" if none).
std::string shipped_observations(const std::string& executable_path);

nlohmann::json to_json(const std::vector<PublishedObservation>& observations);

// One CSV record: fields split at commas outside double quotes; "" inside quotes is a quote (every CSV data file
// the library reads: this one and the fit's observations, inverse/observations.hpp).
std::vector<std::string> csv_fields(const std::string& line);

}  // namespace rbcstab
