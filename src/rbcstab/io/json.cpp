#include "rbcstab/io/json.hpp"

#include <cmath>

#include "rbcstab/model/parameter_table.hpp"

namespace rbcstab {

nlohmann::json number_or_null(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

nlohmann::json by_mode(const std::vector<double>& values) {
  nlohmann::json j = nlohmann::json::object();
  for (std::size_t k = 0; k < values.size(); ++k) j[std::to_string(k + 2)] = number_or_null(values[k]);
  return j;
}

nlohmann::json to_json(const Parameters& p) {
  Scene s;
  s.parameters = p;
  nlohmann::json j = nlohmann::json::object();
  for (const ParameterRow& r : parameter_table())
    if (is_material(r.id) && r.scale == AxisScale::linear) j[r.name] = number_or_null(get_parameter(s, r.id));
  if (!std::isfinite(p.C)) j["C_note"] = "infinite: the vesicle limit";
  if (!std::isfinite(p.S())) j["S_note"] = "infinite: the vesicle limit (Delta0 = 0 or C = inf)";
  return j;
}

nlohmann::json to_json(const Scene& s) {
  nlohmann::json dl = nlohmann::json::object(), rl = nlohmann::json::object();
  for (const auto& [l, v] : s.delta_l) dl[std::to_string(l)] = v;
  for (const auto& [l, v] : s.rest_delta_l) rl[std::to_string(l)] = v;
  return {{"name", s.name}, {"parameters", to_json(s.parameters)}, {"beta", s.beta}, {"delta", s.delta},
          {"delta_l", dl}, {"rest_delta_l", rl}, {"L", s.L}, {"T", s.T}, {"dt", s.dt}, {"model", to_string(s.model)}};
}

void put_truncation(nlohmann::json& j, const SceneFile& file) { put_truncation(j, file.scene.L, file.L_reason); }

void put_truncation(nlohmann::json& j, int L, const std::string& L_reason) {
  j["L"] = L;
  j["L_reason"] = L_reason;
}

nlohmann::json to_json(const SimulationResult& r) {
  return {{"scene", r.scene_name},
          {"model", to_string(r.level.level)},
          {"model_exact", r.level.exact},
          {"model_reason", r.level.reason},
          {"status", to_string(r.status)},
          {"reason", r.reason},
          {"L", r.L},
          {"T", r.T},
          {"t_reached", r.t_reached},
          {"excess_area_total", r.Delta_total_initial},
          {"excess_area_initial", by_mode(r.Delta_initial)},
          {"excess_area_final", by_mode(r.Delta_final)},
          {"excess_area_tail_mean", by_mode(r.Delta_tail_mean)},
          {"oscillating", r.oscillating},
          {"l_Delta", r.l_Delta},
          {"l_Delta_final", r.l_Delta_final},
          {"sigma_initial", number_or_null(r.sigma_initial)},
          {"sigma_final", number_or_null(r.sigma_final)},
          {"sigma_tail_mean", number_or_null(r.sigma_tail_mean)},
          {"r_final", number_or_null(r.r_final)},
          {"Psi_final", number_or_null(r.Psi_final)},
          {"excess_area_drift", number_or_null(r.excess_area_drift)},
          {"steps", r.counters.steps},
          {"failed_steps", r.counters.failed_steps},
          {"rhs_evaluations", r.counters.rhs_evaluations},
          {"jacobian_evaluations", r.counters.jacobian_evaluations},
          {"seconds", r.seconds},
          {"warnings", r.warnings}};
}

}  // namespace rbcstab
