#include "rbcstab/io/json.hpp"

#include <charconv>
#include <cmath>

#include "rbcstab/core/error.hpp"

#include "rbcstab/model/parameter_table.hpp"

namespace rbcstab {

nlohmann::json number_or_null(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

nlohmann::json complex_json(std::complex<double> z) { return {number_or_null(z.real()), number_or_null(z.imag())}; }

std::string csv_number(double v) {
  if (!std::isfinite(v)) return "";
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

void put_number(nlohmann::json& j, const std::string& key, double v, const std::string& reason) {
  j[key] = number_or_null(v);
  if (!std::isfinite(v)) j[key + "_reason"] = reason;
}

std::string row_reason(IntegrationStatus status, const std::string& reason, const Parameters& p) {
  if (status == IntegrationStatus::success) return nonfinite_reason(p);
  return "the run ended with " + to_string(status) + ": " + run_reason(status, reason, p);
}

namespace {

bool holds_null(const nlohmann::json& v) {
  if (v.is_null()) return true;
  if (v.is_number_float()) return !std::isfinite(v.get<double>());
  if (v.is_array())
    for (const auto& e : v)
      if (holds_null(e)) return true;
  return false;
}

// Non-finite numbers become null; objects (also inside arrays) are explained in turn.
void nullify(nlohmann::json& v, const std::string& reason) {
  if (v.is_number_float() && !std::isfinite(v.get<double>())) v = nullptr;
  if (v.is_object()) explain_nulls(v, reason);
  if (v.is_array())
    for (auto& e : v) nullify(e, reason);
}

void collect_unexplained(const nlohmann::json& j, const std::string& path, std::vector<std::string>& out) {
  if (j.is_array()) {
    for (std::size_t k = 0; k < j.size(); ++k) collect_unexplained(j[k], path + "/" + std::to_string(k), out);
    return;
  }
  if (!j.is_object()) return;
  for (const auto& [key, v] : j.items()) {
    if (holds_null(v) && !j.contains(key + "_reason")) out.push_back(path + "/" + key);
    collect_unexplained(v, path + "/" + key, out);
  }
}

}  // namespace

void explain_nulls(nlohmann::json& j, const std::string& reason) {
  if (!j.is_object()) return nullify(j, reason);
  std::vector<std::string> unexplained;
  for (auto& [key, v] : j.items()) {
    if (holds_null(v) && !j.contains(key + "_reason")) unexplained.push_back(key);
    nullify(v, reason);
  }
  for (const std::string& key : unexplained) j[key + "_reason"] = reason;
}

std::vector<std::string> unexplained_nulls(const nlohmann::json& j) {
  std::vector<std::string> out;
  collect_unexplained(j, "", out);
  return out;
}

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
  if (!std::isfinite(p.C)) j["C_reason"] = "infinite: the vesicle limit";
  if (!std::isfinite(p.S())) j["S_reason"] = S_reason(p);
  explain_nulls(j, nonfinite_reason(p));
  return j;
}

nlohmann::json to_json(const Scene& s) {
  nlohmann::json dl = nlohmann::json::object(), rl = nlohmann::json::object();
  for (const auto& [l, v] : s.delta_l) dl[std::to_string(l)] = v;
  for (const auto& [l, v] : s.rest_delta_l) rl[std::to_string(l)] = v;
  return {{"name", s.name}, {"parameters", to_json(s.parameters)},
          {"beta", s.beta}, {"delta", s.delta},
          {"delta_l", dl},  {"rest_delta_l", rl},
          {"L", s.L},       {"T", s.T},
          {"dt", s.dt},     {"model", to_string(s.model)}};
}

nlohmann::json parse_json_text(const std::string& text, const std::string& source, const std::string& parameter) {
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    throw InvalidArgument(parameter, "'" + source + "' is not JSON: " + e.what());
  }
}

nlohmann::json to_json(const PhysicalCell& c) {
  SceneFile f;
  f.scene.physical = c;
  nlohmann::json o = nlohmann::json::object();
  for (const SceneKey& k : scene_keys())
    if (k.kind == ValueKind::quantity && !std::isnan(std::get<double>(k.get(f)))) o[k.key] = std::get<double>(k.get(f));
  return o;
}

void put_physical(nlohmann::json& j, const Scene& s) {
  if (!s.physical) return;
  nlohmann::json o = to_json(*s.physical);
  const CellNumbers n = cell_numbers(*s.physical);
  o["R_m"] = n.R;
  o["time_unit_s"] = n.time_unit;
  o["tension_unit_N_per_m"] = n.tension_unit;
  o["T_s"] = s.T * n.time_unit;
  o["dt_s"] = s.dt * n.time_unit;
  j["physical"] = o;
}

void put_truncation(nlohmann::json& j, const SceneFile& file) {
  put_truncation(j, file.scene.L, file.L_reason);
  if (file.truncation_check) j["truncation_check"] = to_json(*file.truncation_check);
}

nlohmann::json to_json(const TruncationCheck& c) {
  const std::string overflow = "the linear growth along the run's sigma(t) overflows a double";
  nlohmann::json dropped = nlohmann::json::array();
  for (const auto& d : c.dropped) {
    nlohmann::json m = {{"l", d.l}, {"delta", d.delta}, {"bound", d.delta + c.threshold}, {"t_max", d.t_max}};
    put_number(m, "Delta_max", d.Delta_max, overflow);
    dropped.push_back(m);
  }
  nlohmann::json j = {{"L_scene", c.L_scene},
                      {"L_candidate", c.L_candidate},
                      {"L_run", c.L_run},
                      {"dropped", dropped},
                      {"threshold", c.threshold},
                      {"t_sigma_shift", c.t_sigma_shift},
                      {"sigma_tolerance", c.sigma_tolerance},
                      {"samples", c.samples},
                      {"passed", c.passed},
                      {"verdict", c.verdict}};
  put_number(j, "sigma_shift", c.sigma_shift, "no bound: the dropped modes' area is not small against the kept modes'");
  return j;
}

void put_truncation(nlohmann::json& j, int L, const std::string& L_reason) {
  j["L"] = L;
  j["L_reason"] = L_reason;
}

nlohmann::json to_json(const EarlyTermination& e) {
  nlohmann::json j{{"attempts", e.attempts}, {"rhs_evaluations", e.work.rhs_evaluations}};
  if (!e.terminated) {
    j["note"] = e.note;
    return j;
  }
  j["terminated_at"] = e.terminated_at;
  j["resumed_at"] = e.resumed_at;
  j["kind"] = e.kind;
  j["period"] = e.period;
  j["margin"] = e.margin;
  j["margin_error"] = e.margin_error;
  j["rate"] = e.rate;
  j["residual"] = e.residual;
  j["distance"] = e.distance;
  j["decay_bound"] = e.decay_bound;
  j["sigma_integral"] = e.sigma_integral;
  return j;
}

nlohmann::json to_json(const SimulationResult& r) {
  nlohmann::json j = {{"scene", r.scene_name},
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
                      {"warnings", r.warnings},
                      {"samples", r.trajectory.rows()},
                      {"samples_integrated", r.trajectory.integrated_count()}};
  j["terminated_at"] = number_or_null(r.early.terminated_at);
  if (!r.early.terminated)
    j["terminated_at_reason"] =
        r.early.note.empty() ? "integrated to T (no early termination asked for)" : r.early.note;
  j["early_termination"] = to_json(r.early);
  return j;
}

nlohmann::json to_json(const SimulationResult& r, const Parameters& p) {
  nlohmann::json j = to_json(r);
  explain_nulls(j, r.status == IntegrationStatus::success ? nonfinite_reason(p) : run_reason(r, p));
  return j;
}

}  // namespace rbcstab
