// Monitors: their text form, and their events over a scene problem's parameters and measures.
#include "rbcstab/continuation/monitors.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <utility>
#include <variant>

#include "rbcstab/continuation/detail/scene_problem.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/core/text.hpp"

namespace rbcstab {

void Monitor::validate() const {
  if (name.empty()) throw InvalidArgument("monitor", "a monitor needs a name (NAME=VALUE)");
  if (values.empty() && !function)
    throw InvalidArgument("monitor", "monitor '" + name + "' has no value (NAME=V1,V2,...)");
  for (double v : values) require(std::isfinite(v), "monitor", v, "a finite value (monitor '" + name + "')");
}

Monitor parse_monitor(std::string_view text, bool stop, const std::string& what) {
  const std::string t(text);
  const std::size_t eq = t.find('=');
  const std::string form = stop ? "NAME=VALUE" : "NAME=V1,V2,...";
  if (eq == std::string::npos || eq == 0 || eq + 1 == t.size())
    throw InvalidArgument(
        what, "'" + t + "' is not " + form + " (a parameter or measure, '=', its value" + (stop ? ")" : "s)"));
  Monitor m;
  m.name = t.substr(0, eq);
  m.stop = stop;
  std::size_t from = eq + 1;
  while (from <= t.size()) {
    const std::size_t comma = std::min(t.find(',', from), t.size());
    const std::string item = t.substr(from, comma - from);
    const std::optional<double> v = read_number(item);
    if (!v || !std::isfinite(*v))
      throw InvalidArgument(
          what, "'" + t + "': " + (v ? "'" + item + "' is not finite" : number_error(item)) + " (" + form + ")");
    m.values.push_back(*v);
    from = comma + 1;
  }
  if (stop && m.values.size() != 1)
    throw InvalidArgument(what, "'" + t + "': a stop takes one value (NAME=VALUE; give the flag again for more)");
  return m;
}

std::string monitor_event_name(const Monitor& m, double value) {
  return m.function && value == 0 ? m.name : m.name + "=" + format_value(value);
}

namespace detail {

std::vector<UserEvent> monitor_events(const SceneProblem& sp, const std::vector<std::string>& measure_names,
                                      const std::vector<Monitor>& monitors, const Eigen::VectorXd& x0, double p0) {
  const ContinuationProblem& pr = sp.problem();
  const std::vector<std::string> parameters = pr.parameter_names();
  // The point as a function sees it: its parameters and numeric measures by name.
  auto point_of = [&sp, &pr, parameters, measure_names](const Eigen::VectorXd& x, double p) {
    std::map<std::string, double> point;
    const std::vector<double> pv = pr.parameter_values(x, p);
    for (std::size_t i = 0; i < parameters.size(); ++i) point[parameters[i]] = pv[i];
    const Values mv = sp.measures(x, p);
    for (std::size_t i = 0; i < measure_names.size() && i < mv.size(); ++i)
      if (const double* d = std::get_if<double>(&mv[i])) point.emplace(measure_names[i], *d);
    return point;
  };
  const Values start = sp.measures(x0, p0);
  std::vector<UserEvent> events;
  for (const Monitor& m : monitors) {
    m.validate();
    std::function<double(const Eigen::VectorXd&, double)> q;
    if (m.function) {
      q = [f = m.function, point_of](const Eigen::VectorXd& x, double p) { return f(point_of(x, p)); };
    } else if (auto it = std::find(parameters.begin(), parameters.end(), m.name); it != parameters.end()) {
      const auto i = static_cast<std::size_t>(it - parameters.begin());
      q = [&pr, i](const Eigen::VectorXd& x, double p) { return pr.parameter_values(x, p)[i]; };
    } else if (auto jt = std::find(measure_names.begin(), measure_names.end(), m.name); jt != measure_names.end()) {
      const auto i = static_cast<std::size_t>(jt - measure_names.begin());
      // Labels and integers (kind, winding, mode) jump: no value is reached in between.
      if (i >= start.size() || !std::holds_alternative<double>(start[i]))
        throw InvalidArgument("monitor", "'" + m.name + "' is not a continuous measure: it cannot be monitored");
      q = [&sp, i](const Eigen::VectorXd& x, double p) { return std::get<double>(sp.measures(x, p)[i]); };
    } else {
      std::string names;
      for (const auto& n : parameters) names += (names.empty() ? "" : ", ") + n;
      for (std::size_t i = 0; i < measure_names.size(); ++i)
        if (i < start.size() && std::holds_alternative<double>(start[i])) names += ", " + measure_names[i];
      throw InvalidArgument("monitor", "unknown monitor '" + m.name + "' (this branch has: " + names + ")");
    }
    const std::vector<double> targets = m.values.empty() ? std::vector<double>{0.0} : m.values;
    for (double v : targets) {
      UserEvent e;
      e.name = monitor_event_name(m, v);
      e.g = [q, v](const Eigen::VectorXd& x, double p) { return q(x, p) - v; };
      e.stop = m.stop;
      events.push_back(std::move(e));
    }
  }
  return events;
}

}  // namespace detail

}  // namespace rbcstab
