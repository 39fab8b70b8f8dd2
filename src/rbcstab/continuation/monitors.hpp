#pragma once
// Monitors (AUTO's UZR): label a UZ point, or end the run, where a parameter or a measure of the branch
// reaches given values. A monitor is one more user event g = value(point) - target per target, located
// as every special point is (to location_tol); a stop monitor's event ends the direction it is met in at
// the located point (UserEvent::stop; status completed, message "stopped at NAME=VALUE").
#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace rbcstab {

struct Monitor {
  // A parameter the branch reports (its free parameter, or a composite it moves: Lambda, S, ...) or a
  // numeric measure of the kind (measure_names: r, Psi, Delta_2, r_min, ...); the name of the function's
  // UZ points when `function` is given.
  std::string name;
  std::vector<double> values;  // the targets (finite); a UZ point "name=value" where the quantity reaches each
  bool stop = false;           // end the run (each direction) at the first target reached
  // Optional: the quantity from the point's parameters and numeric measures by name (a front end's callable,
  // e.g. Python); then `name` only names it and values default to {0} (its zeros). It must be continuous.
  std::function<double(const std::map<std::string, double>& point)> function;
  // Throws InvalidArgument("monitor", ...): no name, no value or a value not finite.
  void validate() const;
};

// "NAME=V1,V2,..." (the CLI's --monitor and --stop-at, a scene's [continuation] monitor strings): a name
// and one or more numbers. Throws InvalidArgument(what, ...) naming the text for anything else.
Monitor parse_monitor(std::string_view text, bool stop, const std::string& what = "monitor");

// The monitors of the text forms: each of `monitor` parsed as a monitor, each of `stop_at` as a stop, in that
// order (the CLI's flags, a scene's [continuation] keys; monitor_name / stop_name name them in messages). "none"
// gives nothing: on a restart, monitors given replace the run's and `--monitor none` drops them.
std::vector<Monitor> parse_monitors(const std::vector<std::string>& monitor, const std::vector<std::string>& stop_at,
                                    const std::string& monitor_name = "monitor",
                                    const std::string& stop_name = "stop_at");

// m's text form, "NAME=V1,V2,..." (shortest round-trip numbers): parse_monitor reads it back. A function has none
// (InvalidArgument("monitor")).
std::string monitor_text(const Monitor& m);

// The name of the UZ point (and event) of target `value` of monitor m: "Delta_2=0.5"; m.name for a
// function's zeros.
std::string monitor_event_name(const Monitor& m, double value);

}  // namespace rbcstab
