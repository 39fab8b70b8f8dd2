// Reading a branch JSON's kind, parameters and points for the bifurcation plot (declared in plot_branch.hpp).
#include "rbcstab/report/detail/plot_branch.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numbers>
#include <set>
#include <string_view>

#include "rbcstab/core/constants.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/model/parameter_table.hpp"

namespace rbcstab::detail::plot {

namespace {

double num(const json& v) { return v.is_number() ? v.get<double>() : kNaN; }

// The measures computed here from what a point carries (see bifurcation_plot.hpp).
double derived(const json& p, const std::string& name) {
  auto max_over = [&](const char* key, auto&& f) {
    const auto it = p.find(key);
    if (it == p.end() || !it->is_array() || it->empty()) return kNaN;
    double m = -kInf;
    for (const json& z : *it) {
      if (!z.is_array() || z.size() != 2) return kNaN;
      const double v = f(num(z[0]), num(z[1]));
      if (!std::isfinite(v)) return kNaN;
      m = std::max(m, v);
    }
    return m;
  };
  if (name == "period") return 2 * kPi;
  if (name == "max_abs_multiplier")
    return max_over("multipliers", [](double re, double im) { return std::hypot(re, im); });
  if (name == "max_Re_eig") return max_over("eigenvalues", [](double re, double) { return re; });
  if (name == "norm_Delta" || name == "norm_x") {
    double s = 0;
    bool any = false;
    if (name == "norm_Delta") {
      for (const auto& [k, v] : p.items())
        if (is_delta_l(k)) s += num(v) * num(v), any = true;
    } else if (p.contains("x") && p["x"].is_array()) {
      for (const json& v : p["x"]) s += num(v) * num(v), any = true;
    }
    return any ? std::sqrt(s) : kNaN;
  }
  return kNaN;
}

}  // namespace

bool is_curve(const json& j) { return j.contains("curve"); }

std::vector<std::string> free_parameters(const json& j) {
  if (is_curve(j)) {
    const json& p = j["curve"]["parameters"];
    return {p[0].get<std::string>(), p[1].get<std::string>()};
  }
  return {j["free_parameter"].get<std::string>()};
}

std::string problem_of(const json& j) {
  if (j.contains("kind") && j["kind"].is_string()) return j["kind"].get<std::string>();
  const json& pts = j["branch"];
  return !pts.empty() && pts[0].contains("multipliers") ? "orbit" : "equilibrium";
}

bool orbit_problem(const std::string& problem) { return problem == "orbit" || problem == "modal-orbit"; }

std::string level_of(const json& j, const std::string& problem) {
  if (j.contains("level") && j["level"].is_string()) return j["level"].get<std::string>();
  return problem == "modal" || problem == "modal-orbit" ? "modal" : problem == "full" ? "full" : "reduced";
}

bool is_delta_l(const std::string& key) {
  return key.size() > 6 && key.rfind("Delta_", 0) == 0 &&
         std::all_of(key.begin() + 6, key.end(), [](unsigned char c) { return std::isdigit(c); });
}

Fixed fixed_parameters(const json& j) {
  // The free parameters as table rows; a name no row has (a hand-edited file) moves nothing.
  std::vector<SceneParameter> free;
  for (const std::string& q : free_parameters(j))
    for (const ParameterRow& r : parameter_table())
      if (q == r.name) free.push_back(r.id);
  Fixed f;
  const json* ps = j.contains("parameters") && j["parameters"].is_object() ? &j["parameters"] : nullptr;
  for (const SceneParameter q : held_parameters()) {
    if (moves_stored(free, q)) continue;
    const ParameterRow& r = parameter_row(q);
    // A branch file keeps the [parameters] under "parameters" and the [initial] ones (beta) at the top.
    const json* holder = std::string_view(r.table) == "parameters" ? ps : &j;
    const json* v = holder && holder->contains(r.name) ? &(*holder)[r.name] : nullptr;
    if (v && (v->is_number() || v->is_null())) f[r.name] = v->is_null() ? kInf : v->get<double>();
  }
  return f;
}

std::vector<SceneParameter> held_parameters() {
  std::vector<SceneParameter> out;
  for (const ParameterRow& r : parameter_table())
    if (r.table && r.continuation) out.push_back(r.id);
  return out;
}

double value(const json& p, const std::string& name, const Fixed* fixed) {
  const auto it = p.find(name);
  if (it != p.end()) return num(*it);
  if (fixed)
    if (const auto f = fixed->find(name); f != fixed->end()) return f->second;
  return derived(p, name);
}

std::string stability_of(const json& p, const std::string& source, std::size_t k) {
  if (const auto it = p.find("stability"); it != p.end() && !it->is_null()) {
    const std::string s = it->is_string() ? it->get<std::string>() : it->dump();
    if (s != "stable" && s != "unstable" && s != "uncertain")
      throw InvalidArgument("file", source + ": point " + std::to_string(k) + " has stability = '" + s +
                                        "' (must be stable, unstable or uncertain)");
    return s;
  }
  if (const auto it = p.find("stable"); it != p.end() && it->is_boolean())
    return it->get<bool>() ? "stable" : "unstable";
  return "uncertain";
}

std::string style_of(const std::string& stability) {
  return stability == "unstable" ? "dashed" : stability == "uncertain" ? "dotted" : "solid";
}

std::optional<int> label_of(const json& p) {
  const auto it = p.find("label");
  if (it == p.end() || !it->is_number_integer()) return std::nullopt;
  return it->get<int>();
}

std::string type_of(const json& p) {
  const auto it = p.find("type");
  return it != p.end() && it->is_string() ? it->get<std::string>() : "";
}

bool switched(const json& sw) {
  const bool has_points = sw.contains("branch") && sw["branch"].is_array() && !sw["branch"].empty();
  return sw.value("switched", has_points);
}

}  // namespace rbcstab::detail::plot
