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

std::vector<Monitor> parse_monitors(const std::vector<std::string>& monitor, const std::vector<std::string>& stop_at,
                                    const std::string& monitor_name, const std::string& stop_name) {
  std::vector<Monitor> out;
  for (const auto& [texts, stop] : {std::pair{&monitor, false}, std::pair{&stop_at, true}})
    for (const std::string& t : *texts)
      if (t != "none") out.push_back(parse_monitor(t, stop, stop ? stop_name : monitor_name));
  return out;
}

std::string monitor_text(const Monitor& m) {
  if (m.function) throw InvalidArgument("monitor", "monitor '" + m.name + "' is a function: it has no text form");
  std::string t = m.name + "=";
  for (std::size_t i = 0; i < m.values.size(); ++i) t += (i ? "," : "") + format_value(m.values[i]);
  return t;
}

std::string monitor_event_name(const Monitor& m, double value) {
  return m.function && value == 0 ? m.name : m.name + "=" + format_value(value);
}

namespace detail {

std::vector<UserEvent> monitor_events(const MonitoredPoint& q, const std::vector<Monitor>& monitors,
                                      const Eigen::VectorXd& x0, double p0) {
  if (monitors.empty()) return {};
  // The point as a function sees it: its parameters and numeric measures by name.
  auto point_of = [q](const Eigen::VectorXd& x, double p) {
    std::map<std::string, double> point;
    const std::vector<double> pv = q.parameter_values(x, p);
    for (std::size_t i = 0; i < q.parameters.size() && i < pv.size(); ++i) point[q.parameters[i]] = pv[i];
    const Values mv = q.measures(x, p);
    for (std::size_t i = 0; i < q.measure_names.size() && i < mv.size(); ++i)
      if (const double* d = std::get_if<double>(&mv[i])) point.emplace(q.measure_names[i], *d);
    return point;
  };
  const Values start = q.measures(x0, p0);
  const auto& parameters = q.parameters;
  const auto& measure_names = q.measure_names;
  std::vector<UserEvent> events;
  for (const Monitor& m : monitors) {
    m.validate();
    std::function<double(const Eigen::VectorXd&, double)> value;
    if (m.function) {
      value = [f = m.function, point_of](const Eigen::VectorXd& x, double p) { return f(point_of(x, p)); };
    } else if (auto it = std::find(parameters.begin(), parameters.end(), m.name); it != parameters.end()) {
      const auto i = static_cast<std::size_t>(it - parameters.begin());
      value = [f = q.parameter_values, i](const Eigen::VectorXd& x, double p) { return f(x, p)[i]; };
    } else if (auto jt = std::find(measure_names.begin(), measure_names.end(), m.name); jt != measure_names.end()) {
      const auto i = static_cast<std::size_t>(jt - measure_names.begin());
      // Labels and integers (kind, winding, mode) jump: no value is reached in between.
      if (i >= start.size() || !std::holds_alternative<double>(start[i]))
        throw InvalidArgument("monitor", "'" + m.name + "' is not a continuous measure: it cannot be monitored");
      value = [f = q.measures, i](const Eigen::VectorXd& x, double p) { return std::get<double>(f(x, p)[i]); };
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
      e.g = [value, v](const Eigen::VectorXd& x, double p) { return value(x, p) - v; };
      e.stop = m.stop;
      events.push_back(std::move(e));
    }
  }
  return events;
}

std::vector<UserEvent> monitor_events(const SceneProblem& sp, const std::vector<std::string>& measure_names,
                                      const std::vector<Monitor>& monitors, const Eigen::VectorXd& x0, double p0) {
  const ContinuationProblem& pr = sp.problem();
  return monitor_events(
      MonitoredPoint{pr.parameter_names(),
                     [&pr](const Eigen::VectorXd& x, double p) { return pr.parameter_values(x, p); }, measure_names,
                     [&sp](const Eigen::VectorXd& x, double p) { return sp.measures(x, p); }},
      monitors, x0, p0);
}

}  // namespace detail

}  // namespace rbcstab
