// The inputs of a bifurcation plot: checking a branch JSON (plot_input), reading one from a file
// (read_plot_input), and the quantities its axes can show (plot_measures).
#include <algorithm>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "rbcstab/core/error.hpp"
#include "rbcstab/io/files.hpp"
#include "rbcstab/report/bifurcation_plot.hpp"
#include "rbcstab/report/detail/plot_branch.hpp"

namespace rbcstab {

using nlohmann::json;

PlotInput plot_input(json j, const std::string& source) {
  using namespace detail::plot;  // the branch readers (detail/plot_branch.hpp)
  auto refuse = [&](const std::string& why) {
    return InvalidArgument("file", source +
                                       " is not a branch JSON (the output of `rbcstab continue --json` or a "
                                       "branch file of --save): " +
                                       why);
  };
  if (!j.is_object()) throw refuse("not a JSON object");
  if (j.contains("format") && j["format"] != "rbcstab-branch")
    throw refuse("format = " + j["format"].dump() + " (expected \"rbcstab-branch\")");
  if (!j.contains("branch") || !j["branch"].is_array()) throw refuse("no \"branch\" array of points");
  if (!j.contains("free_parameter") || !j["free_parameter"].is_string()) throw refuse("no \"free_parameter\"");
  if (is_curve(j)) {
    const json& c = j["curve"];
    if (!c.is_object() || !c.contains("parameters") || !c["parameters"].is_array() || c["parameters"].size() != 2 ||
        !c["parameters"][0].is_string() || !c["parameters"][1].is_string())
      throw refuse("\"curve\" needs \"parameters\": [p1, p2]");
  }
  const std::vector<std::string> params = free_parameters(j);
  auto check_part = [&](const json& part, const std::string& where) {
    for (std::size_t k = 0; k < part["branch"].size(); ++k) {
      const json& p = part["branch"][k];
      if (!p.is_object()) throw refuse(where + "point " + std::to_string(k) + " is not an object");
      for (const auto& q : params)
        if (!p.contains(q)) throw refuse(where + "point " + std::to_string(k) + " has no \"" + q + "\"");
    }
    if (part.contains("special_points") && !part["special_points"].is_array())
      throw refuse(where + "\"special_points\" is not an array");
  };
  check_part(j, "");
  if (j.contains("switched_branch")) {
    const json& sw = j["switched_branch"];
    if (!sw.is_object() || (switched(sw) && !(sw.contains("branch") && sw["branch"].is_array())))
      throw refuse("\"switched_branch\" has no \"branch\" array");
    if (switched(sw)) check_part(sw, "switched branch: ");
  }
  return {source, std::move(j)};
}

PlotInput read_plot_input(const std::string& path) {
  const std::string text = read_file(path);
  json j;
  try {
    j = json::parse(text);
  } catch (const json::parse_error& e) {
    throw InvalidArgument("file", path + " is not valid JSON (truncated or not a branch file?): " + e.what());
  }
  return plot_input(std::move(j), path);
}

std::vector<std::string> plot_measures(const PlotInput& in) {
  using namespace detail::plot;  // the branch readers (detail/plot_branch.hpp)
  const json& j = in.branch;
  std::vector<std::string> out = free_parameters(j);
  const json& pts = j["branch"];
  if (pts.empty()) return out;
  const json& p = pts[0];
  for (const auto& [k, v] : p.items())
    if ((v.is_number() || v.is_null()) && k != "label" && std::find(out.begin(), out.end(), k) == out.end())
      out.push_back(k);
  auto add = [&](const std::string& name, bool applies) {
    if (applies && std::find(out.begin(), out.end(), name) == out.end()) out.push_back(name);
  };
  add("period", orbit_problem(problem_of(j)) && !is_curve(j));
  add("max_abs_multiplier", p.contains("multipliers"));
  add("max_Re_eig", p.contains("eigenvalues"));
  bool has_delta = false;
  for (const auto& [k, v] : p.items()) has_delta = has_delta || is_delta_l(k);
  add("norm_Delta", has_delta);
  add("norm_x", p.contains("x") && p["x"].is_array());
  for (const auto& [name, v] : fixed_parameters(j)) add(name, true);
  return out;
}

}  // namespace rbcstab
