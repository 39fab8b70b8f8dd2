#pragma once
// The numerical options a user may tune (AUTO's DS/DSMIN/DSMAX, EPSL/EPSU, ITNW, NTST), each declared once
// with its domain: the CLI's flags and --help, Python's keywords and the options' validate() all read this
// table. Orbits are solved by multiple shooting, not collocation: AUTO's NTST is the number of shooting
// segments and the resolution inside a segment is the integrator's tolerance (there is no NCOL).
#include <span>
#include <string>
#include <string_view>

#include "rbcstab/continuation/continuation.hpp"
#include "rbcstab/continuation/orbit.hpp"
#include "rbcstab/model/parameter_table.hpp"

namespace rbcstab {

struct TunableOption {
  const char* name;  // the Python keyword and the name a refusal gives: the field's (orbit_ + OrbitOptions' rtol, ...)
  const char* flag;  // the CLI flag
  const char* help;  // one line for --help and the docs (the domain and default are appended)
  Domain domain;     // the values accepted
  bool integer;      // and only integers
  bool orbit;        // an OrbitOptions field (else ContinuationOptions)
  double (*get)(const ContinuationOptions& engine, const OrbitOptions& orbit);
  void (*set)(ContinuationOptions& engine, OrbitOptions& orbit, double value);
  // The keyword of Python and of a scene's [continuation] table: the flag in snake_case (--newton-tol:
  // newton_tol, --step: step).
  std::string keyword() const;
  // The accepted values in words: the domain, "an integer" for integer options.
  std::string range() const;
  // The default (of a default-constructed options struct).
  double default_value() const;
  // Throws InvalidArgument(name, ...) naming the value and range() unless value is accepted.
  void check(double value) const;
};

std::span<const TunableOption> tunable_options();

// The run sizes a front end may ask for, each checked by the validate() of its struct (the CLI's flags and
// Python's keywords state these ranges): beyond them a value is a slip, not a run (1e8 points per direction is
// days of work and gigabytes of states).
inline constexpr long long kMaxPointsLimit = 100000000;   // ContinuationOptions::max_points in [2, this]
inline constexpr long long kLabelEveryLimit = 100000000;  // BranchSpec::label_every in [0, this]
inline constexpr long long kCurvePointLimit = 1000000;    // CurveSpec::point in [1, this]
// "an integer in [lo, hi]": how messages and --help state these ranges.
inline std::string integer_range(long long lo, long long hi) {
  return "an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
}
// The row of `name`; InvalidArgument("option", ...) listing the names for an unknown one.
const TunableOption& tunable_option(std::string_view name);

}  // namespace rbcstab
