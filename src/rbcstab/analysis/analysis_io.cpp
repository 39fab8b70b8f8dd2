#include "rbcstab/analysis/analysis_io.hpp"

#include <iomanip>
#include <sstream>

#include "rbcstab/analysis/truncation.hpp"
#include "rbcstab/core/text.hpp"
#include "rbcstab/io/json.hpp"
#include "rbcstab/io/units_io.hpp"

namespace rbcstab {

void put(nlohmann::json& j, const std::string& key, const Quantity& q) {
  j[key] = q.valid() ? number_or_null(q.value) : nlohmann::json(nullptr);
  if (!q.reason.empty()) j[key + "_reason"] = q.reason;
}

nlohmann::json to_json(const std::complex<double>& z) { return {number_or_null(z.real()), number_or_null(z.imag())}; }

nlohmann::json to_json(const Delta2Prediction& d) {
  nlohmann::json j;
  j["variant"] = d.variant;
  j["l"] = d.l;
  j["sigma_s"] = d.sigma_s;
  j["mu_tilde"] = d.mu_tilde;
  put(j, "Delta2_tilde", d.Delta2_tilde);
  put(j, "r_tilde", d.r_tilde);
  put(j, "Psi_tilde", d.Psi_tilde);
  j["K1"] = d.K1;
  j["K2"] = d.K2;
  j["c"] = d.c;
  j["roots"] = {d.roots[0], d.roots[1]};
  j["selection"] = d.selection;
  return j;
}

std::string to_text(const Quantity& q) {
  TextStream s;
  s << std::setprecision(6);
  if (q.valid())
    s << q.value;
  else
    s << "n/a (" << q.reason << ")";
  return s.str();
}

std::string mode_list(const std::vector<int>& modes) {
  if (modes.empty()) return "none";
  std::string s;
  for (std::size_t i = 0; i < modes.size(); ++i) s += (i ? ", " : "") + std::to_string(modes[i]);
  return s;
}

Quantity simulated_Delta2(const SimulationResult& r) {
  if (r.status != IntegrationStatus::success)
    return Quantity::outside("simulation stopped at t = " + std::to_string(r.t_reached) + ": " + r.reason);
  if (r.l_Delta == 2) return Quantity::outside("the simulation stayed stable (l_Delta = 2): no post-instability state");
  return Quantity::of(r.Delta_tail_mean[0]);
}

nlohmann::json post_json(const SceneFile& file, const PostInstability& post, const SimulationResult& r) {
  const Parameters& p = file.scene.parameters;
  nlohmann::json j;
  j["scene"] = file.scene.name;
  j["parameters"] = to_json(p);
  put_truncation(j, file);
  j["alpha"] = p.alpha();
  j["surviving_mode"] = post.surviving_mode;
  put(j, "Delta2_tilde", post.continuous.Delta2_tilde);
  put(j, "Delta2_tilde_integer_mode", post.integer_mode.Delta2_tilde);
  put(j, "r_tilde", post.continuous.r_tilde);
  put(j, "Psi_tilde", post.continuous.Psi_tilde);
  put(j, "r_tilde_integer_mode", post.integer_mode.r_tilde);
  put(j, "Psi_tilde_integer_mode", post.integer_mode.Psi_tilde);
  put(j, "Delta2_simulated", simulated_Delta2(r));
  j["continuous"] = to_json(post.continuous);
  j["integer_mode"] = to_json(post.integer_mode);
  j["l_Delta_simulated"] = r.l_Delta;
  j["sigma_tail_mean_simulated"] = number_or_null(r.sigma_tail_mean);
  j["T"] = file.scene.T;
  j["tail_window"] = file.options.tail_window;
  explain_nulls(j, nonfinite_reason(p));
  return j;
}

std::string post_text(const SceneFile& file, const PostInstability& post, const SimulationResult& r) {
  const Scene& s = file.scene;
  const Parameters& p = s.parameters;
  const UnitText u(s);  // on a physical scene tensions also in N/m, times in s
  TextStream out;
  out << std::setprecision(6);
  out << "Scene '" << s.name << "': lambda = " << p.lambda << ", Delta = " << p.Delta << ", Delta0 = " << p.Delta0
      << ", B = " << p.B << ", C = " << p.C << ", alpha = " << p.alpha() << "\n";
  out << "Truncation: " << file.L_reason << "\n";
  for (const Delta2Prediction* d : {&post.continuous, &post.integer_mode}) {
    out << (d->variant == "continuous" ? "Continuous l_* = " : "Integer surviving mode l_s = ") << d->l
        << ", sigma = " << u.tension(d->sigma_s) << ": Delta~2 = " << to_text(d->Delta2_tilde)
        << ", r~ = " << to_text(d->r_tilde)
        << ", Psi~ = " << (d->Psi_tilde.valid() ? degrees_text(d->Psi_tilde.value) : to_text(d->Psi_tilde)) << "\n";
  }
  out << "Simulated Delta-bar_2 (tail mean over the last " << u.time(file.options.tail_window)
      << " of T = " << u.time(s.T) << ") = " << to_text(simulated_Delta2(r)) << ", l_Delta = " << r.l_Delta
      << ", sigma tail mean = " << u.tension(r.sigma_tail_mean) << "\n";
  return out.str();
}

std::string truncation_convergence_csv(const TruncationConvergence& t) {
  std::ostringstream csv;
  csv << std::setprecision(10) << "L,status,l_Delta,sigma_final,error_Delta,error_sigma,rhs_evaluations,seconds\n";
  for (const TruncationConvergenceRow& r : t.rows)
    csv << r.L << ',' << to_string(r.status) << ',' << r.l_Delta << ',' << csv_number(r.sigma_final) << ','
        << csv_number(r.error_Delta) << ',' << csv_number(r.error_sigma) << ',' << r.rhs_evaluations << ','
        << csv_number(r.seconds) << '\n';
  return csv.str();
}

nlohmann::json truncation_convergence_json(const SceneFile& file, const TruncationConvergence& t) {
  const Parameters& p = file.scene.parameters;
  const TruncationConvergenceRow& ref = t.reference();
  nlohmann::json rows = nlohmann::json::array();
  for (const TruncationConvergenceRow& r : t.rows) {
    nlohmann::json row{{"L", r.L},
                       {"status", to_string(r.status)},
                       {"reason", r.reason},
                       {"l_Delta", r.l_Delta},
                       {"rhs_evaluations", r.rhs_evaluations},
                       {"seconds", r.seconds}};
    const std::string why = row_reason(r.status, r.reason, p);
    put_number(row, "sigma_final", r.sigma_final, why);
    const std::string error_why =
        t.reference_ok() ? why
                         : "the reference (L = " + std::to_string(ref.L) + ") " + row_reason(ref.status, ref.reason, p);
    put_number(row, "error_Delta", r.error_Delta, error_why);
    put_number(row, "error_sigma", r.error_sigma, error_why);
    rows.push_back(row);
  }
  nlohmann::json j{{"scene", to_json(file.scene)}, {"reference_L", ref.L}, {"rows", rows}};
  put_truncation(j, file);
  return j;
}

}  // namespace rbcstab
