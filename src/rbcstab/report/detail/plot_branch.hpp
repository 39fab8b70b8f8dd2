#pragma once
// Reading a branch JSON for the bifurcation plot (module-private; plot_branch.cpp): its kind and free
// parameters, the quantities of its points (own, derived, or a parameter it holds fixed), their stability,
// labels and types, and whether its switched branch is drawn.
#include <cstddef>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "rbcstab/model/parameter_table.hpp"

namespace rbcstab::detail::plot {

using nlohmann::json;

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
inline constexpr double kInf = std::numeric_limits<double>::infinity();

bool is_curve(const json& j);
std::vector<std::string> free_parameters(const json& j);
// The input's problem kind; a bare branch without "kind" is an orbit when its points carry multipliers.
std::string problem_of(const json& j);
bool orbit_problem(const std::string& problem);
std::string level_of(const json& j, const std::string& problem);
bool is_delta_l(const std::string& key);

// The scene's parameters that stay fixed along an input: held_parameters() except those a free parameter
// moves (moves_stored: itself, Lambda through Delta, S through C, shear_rate B and C; the composites themselves
// are never fixed). Null (C = inf) is infinite.
using Fixed = std::map<std::string, double>;
Fixed fixed_parameters(const json& j);
// The stored parameters a branch can hold fixed: the continuation rows a scene file stores, in table order.
std::vector<SceneParameter> held_parameters();

// The quantity `name` of a point: its own key (null: undefined), else a derived measure, else a
// parameter the input holds fixed.
double value(const json& p, const std::string& name, const Fixed* fixed = nullptr);

std::string stability_of(const json& p, const std::string& source, std::size_t k);
std::string style_of(const std::string& stability);
std::optional<int> label_of(const json& p);
std::string type_of(const json& p);
// A switched branch is drawn when switching succeeded ("switched"; without the key: when it has points).
bool switched(const json& sw);

}  // namespace rbcstab::detail::plot
