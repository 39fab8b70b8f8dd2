#include "rbcstab/verdict/verdict_io.hpp"

#include <cmath>
#include <complex>
#include <iomanip>
#include <optional>
#include <sstream>

#include "rbcstab/analysis/analysis_io.hpp"
#include "rbcstab/analysis/post_instability.hpp"
#include "rbcstab/analysis/predictors.hpp"
#include "rbcstab/analysis/thresholds.hpp"
#include "rbcstab/analysis/truncation.hpp"
#include "rbcstab/core/constants.hpp"
#include "rbcstab/core/text.hpp"
#include "rbcstab/io/json.hpp"
#include "rbcstab/io/units_io.hpp"
#include "rbcstab/model/coefficients.hpp"
#include "rbcstab/model/parameter_table.hpp"
#include "rbcstab/verdict/certified_run.hpp"

namespace rbcstab {

nlohmann::json to_json(const ModePrediction& m) {
  nlohmann::json j;
  j["unstable_modes"] = m.unstable;
  j["l_Delta"] = m.l_Delta;
  j["rate"] = by_mode(m.rate);
  j["status"] = to_string(m.status);
  if (!m.reason.empty()) j["reason"] = m.reason;
  return j;
}

namespace {

bool has_post_instability_state(const SimulationResult& r) {
  return r.l_Delta >= 3 && r.status == IntegrationStatus::success;
}

// A tension Quantity in kappa/R^2 and N/m, or why it has no value.
std::string tension_text(const UnitText& u, const Quantity& q) { return q.valid() ? u.tension(q.value) : to_text(q); }

// The analysis part of the summary: regime, thresholds, the three predictors and Delta~2 predicted vs simulated.
void analysis_text(std::ostream& out, const SceneFile& file, const SimulationResult& r, const ScenePrediction& pr) {
  const Scene& s = file.scene;
  const Parameters& p = s.parameters;
  const double alpha = p.alpha();
  const UnitText u(s);
  out << "\nAnalysis (docs/theory.md)\n";
  out << "Regime       " << to_string(pr.regime.regime) << " -- " << pr.regime.reason << " (reduced dynamics)\n";
  out << "Thresholds   sigma_* = " << u.tension(sigma_star(alpha)) << ", l_* = " << l_star(alpha)
      << (l_star_criterion(alpha) ? " (>= 2.5: an integer mode l >= 3 can be excited)" : " (< 2.5: no l >= 3 band)")
      << ", alpha_*^init = " << to_text(alpha_init(p)) << "\n";
  if (s.L >= 3)
    out << "             surviving integer mode (largest sigma_l^c) l_s = " << surviving_mode(alpha, s.L) << "\n";
  out << "Predictors   (a) asymptotic     <sigma_R> = " << tension_text(u, pr.sigma_R_asymptotic) << " ("
      << pr.asymptotic_source << "): unstable " << mode_list(pr.asymptotic.unstable)
      << ", l_Delta = " << pr.asymptotic.l_Delta << "\n";
  out << "             (b) finite horizon <sigma_R>_T = " << u.tension(pr.horizon.mean_sigma_R) << " over [0, "
      << u.time(pr.horizon.T) << "]: unstable " << mode_list(pr.finite_horizon.unstable)
      << ", l_Delta = " << pr.finite_horizon.l_Delta << " (linear growth exp(2 G_l))\n";
  out << "             (c) simulation     unstable " << mode_list(pr.simulation.unstable)
      << ", l_Delta = " << pr.simulation.l_Delta << "\n";
  if (s.L >= 3) {
    const PostInstability post = post_instability(p, s.L, 0.0);
    out << "Delta~2      predicted: continuous l_* " << to_text(post.continuous.Delta2_tilde)
        << ", integer l_s = " << post.surviving_mode << " " << to_text(post.integer_mode.Delta2_tilde) << "\n";
    if (has_post_instability_state(r))
      out << "             simulated Delta-bar_2 = " << r.Delta_tail_mean[0] << " (tail mean over the last "
          << u.time(file.options.tail_window) << ")\n";
    else
      out << "             simulated: no post-instability state (l_Delta = " << r.l_Delta << ")\n";
  }
}

}  // namespace

nlohmann::json summary_json(const SceneFile& file, const SimulationResult& r, const ScenePrediction& pr) {
  const Scene& s = file.scene;
  const Parameters& p = s.parameters;
  const double alpha = p.alpha();
  nlohmann::json j = to_json(r);
  j.erase("trajectory");
  j["reason"] = run_reason(r, p);
  j["scene"] = s.name;
  j["regime"] = to_string(pr.regime.regime);
  j["regime_reason"] = pr.regime.reason;
  j["alpha"] = number_or_null(alpha);
  j["sigma_star"] = number_or_null(sigma_star(alpha));
  j["l_star"] = number_or_null(l_star(alpha));
  j["l_star_criterion"] = l_star_criterion(alpha);
  put(j, "alpha_init", alpha_init(p));
  if (s.L >= 3) j["surviving_mode"] = surviving_mode(alpha, s.L);
  put(j, "sigma_R_asymptotic", pr.sigma_R_asymptotic);
  j["sigma_R_asymptotic_source"] = pr.asymptotic_source;
  j["asymptotic"] = to_json(pr.asymptotic);
  j["finite_horizon"] = to_json(pr.finite_horizon);
  j["finite_horizon"]["T"] = pr.horizon.T;
  j["finite_horizon"]["mean_sigma_R"] = number_or_null(pr.horizon.mean_sigma_R);
  j["simulation"] = to_json(pr.simulation);
  if (s.L >= 3) {
    const PostInstability post = post_instability(p, s.L, 0.0);
    put(j, "Delta2_tilde", post.continuous.Delta2_tilde);
    put(j, "Delta2_tilde_integer_mode", post.integer_mode.Delta2_tilde);
    if (has_post_instability_state(r))
      j["Delta2_simulated"] = number_or_null(r.Delta_tail_mean[0]);
    else {
      j["Delta2_simulated"] = nullptr;
      j["Delta2_simulated_reason"] = "no post-instability state (l_Delta = " + std::to_string(r.l_Delta) + ")";
    }
  }
  j["tail_window"] = file.options.tail_window;
  j["Psi_final_deg"] = number_or_null(r.Psi_final * 180 / kPi);
  if (s.physical) {  // sigma in N/m: times the tension unit kappa/R^2
    const double unit = cell_numbers(*s.physical).tension_unit;
    j["sigma_final_N_per_m"] = number_or_null(r.sigma_final * unit);
    j["sigma_tail_mean_N_per_m"] = number_or_null(r.sigma_tail_mean * unit);
    j["sigma_initial_N_per_m"] = number_or_null(r.sigma_initial * unit);
    j["sigma_star_N_per_m"] = number_or_null(sigma_star(alpha) * unit);
  }
  j["glossary"] = kGlossary;
  put_truncation(j, file);
  put_physical(j, s);
  if (s.physical) j["shear_rate_thresholds"] = to_json(pr.shear_rate_thresholds);
  explain_nulls(j, nonfinite_reason(p));
  return j;
}

namespace {
nlohmann::json crossing_json(const RateCrossing& c, const RateBand& band) {
  nlohmann::json o = {{"found", c.found}};
  if (c.found) {
    o["shear_rate"] = c.rate;
    o["bracket"] = {c.lo, c.hi};
  } else {
    o["reason"] = c.reason;
    if (!c.side.empty()) o["side"] = c.side;
  }
  if (c.l >= 3) o["l"] = c.l;
  o["band"] = {{"cells", band.cells}, {"found", band.found}};
  if (band.found > 0) {
    o["band"]["lo"] = band.lo;
    o["band"]["hi"] = band.hi;
    o["band"]["lo_from"] = band.lo_key.empty() ? "nominal" : band.lo_key;
    o["band"]["hi_from"] = band.hi_key.empty() ? "nominal" : band.hi_key;
  }
  return o;
}
}  // namespace

nlohmann::json to_json(const PhysicalMap& map) {
  nlohmann::json cell = nlohmann::json::object();
  for (const char* key : {"viscosity", "inner_viscosity", "radius", "area", "volume", "stress_free_volume",
                          "bending_modulus", "shear_modulus"}) {
    PhysicalCell c = map.cell;
    if (const double v = physical_value(c, key); !std::isnan(v)) cell[key] = v;
  }
  nlohmann::json spreads = nlohmann::json::array();
  for (const PhysicalSpread& s : map.spreads)
    spreads.push_back({{"key", s.key}, {"lo", s.lo}, {"hi", s.hi}, {"source", s.source}});
  nlohmann::json columns = nlohmann::json::array();
  for (const PhysicalMapColumn& c : map.columns)
    columns.push_back({{"viscosity", c.viscosity},
                       {"lambda", c.lambda},
                       {"Lambda", c.Lambda},
                       {"tumbling_to_swinging", crossing_json(c.tumbling_to_swinging, c.tumbling_band)},
                       {"onset_out_of_plane", crossing_json(c.onset[0], c.onset_band[0])},
                       {"onset_in_plane", crossing_json(c.onset[1], c.onset_band[1])}});
  nlohmann::json checks = nlohmann::json::array();
  for (const AssumptionCheck& a : map.assumptions)
    checks.push_back({{"assumption", a.assumption},
                      {"quantity", a.quantity},
                      {"value", a.value},
                      {"bound", a.bound},
                      {"holds", a.holds},
                      {"meaning", a.meaning}});
  return {{"cell", cell},       {"spreads", spreads},    {"shear_rate_range", {map.min_rate, map.max_rate}},
          {"columns", columns}, {"assumptions", checks}, {"evaluations", map.evaluations}};
}

nlohmann::json to_json(const PhysicalMap& map, const std::vector<PublishedObservation>& observed,
                       const std::string& experiments_file) {
  nlohmann::json j = to_json(map);
  j["experiments"] = to_json(observed);
  j["experiments_file"] = experiments_file;
  return j;
}

nlohmann::json to_json(const std::vector<ShearRateThreshold>& thresholds) {
  nlohmann::json a = nlohmann::json::array();
  for (const ShearRateThreshold& t : thresholds) {
    nlohmann::json o = {{"orientation", t.orientation},
                        {"beta", t.beta},
                        {"found", t.found},
                        {"alpha", t.alpha},
                        {"evaluations", t.evaluations}};
    if (t.found) {
      o["shear_rate"] = t.shear_rate;
      o["bracket"] = {t.lo, t.hi};
      o["B"] = t.B;
      o["C"] = t.C;
    } else {
      o["reason"] = t.reason;
      if (!t.side.empty()) o["side"] = t.side;
    }
    if (t.found || t.l >= 3) {  // the window's upper end: found, or why not
      if (t.end_found) {
        o["end_shear_rate"] = t.end_shear_rate;
        o["end_bracket"] = {t.end_bracket[0], t.end_bracket[1]};
      } else {
        o["end_shear_rate"] = nullptr;
        o["end_reason"] = t.end_reason;
      }
    }
    if (t.l >= 3) {
      o["l"] = t.l;
      o["shape"] = t.shape;
    }
    a.push_back(o);
  }
  return a;
}

std::string shear_rate_text(const std::vector<ShearRateThreshold>& thresholds) {
  TextStream out;
  out << std::setprecision(6);
  for (const ShearRateThreshold& t : thresholds) {
    out << "             " << (t.orientation == "out_of_plane" ? "out of plane: " : "in plane:     ");
    // The window's upper end, or why none was found.
    const std::string end = t.end_found ? "; upper end " + format_value(t.end_shear_rate) + " 1/s (stable above)"
                                        : "; upper end: none found, " + t.end_reason;
    if (t.found)
      out << "unstable from " << t.shear_rate << " 1/s (B = " << t.B << ", C = " << t.C << "), mode l = " << t.l
          << " -> " << t.shape << end << "\n";
    else
      out << t.reason << (t.l >= 3 ? " (mode l = " + std::to_string(t.l) + " -> " + t.shape + ")" + end : "") << "\n";
  }
  return out.str();
}

std::string summary_text(const SceneFile& file, const SimulationResult& r, const ScenePrediction& pr) {
  const Scene& s = file.scene;
  const Parameters& p = s.parameters;
  const UnitText u(s);
  TextStream out;
  out << std::setprecision(6);
  out << "rbcstab " << RBCSTAB_VERSION << " -- scene '" << s.name << "'\n";
  out << "Glossary     every term below: " << kGlossary << "\n\n";
  // The rows of the parameter table: a scene file's two tables, then the composites (a short definition shown).
  auto values = [&](const std::vector<SceneParameter>& rows) {
    for (std::size_t k = 0; k < rows.size(); ++k) {
      const ParameterRow& row = parameter_row(rows[k]);
      out << (k ? ", " : "") << row.name << " = ";
      if (row.definition && std::string_view(row.definition).find(' ') == std::string_view::npos)
        out << row.definition << " = ";
      out << get_parameter(s, rows[k]);
    }
  };
  out << "Parameters   ";
  values(stored_parameters("parameters"));
  out << "\n             ";
  values(stored_parameters("initial"));
  out << ", L = " << s.L << ", T = " << u.time(s.T) << "\n";
  out << "Derived      ";
  values(composite_parameters());
  out << "\n";
  if (s.physical) {
    out << "Physical     shear rate " << s.physical->shear_rate
        << " 1/s: time unit 1/gamma = " << 1 / s.physical->shear_rate
        << " s, tension unit kappa/R^2 = " << u.tension_unit() << " N/m\n";
    out << "Threshold    unstable window in shear rate along B/C = alpha fixed (asymptotic verdict):\n"
        << shear_rate_text(pr.shear_rate_thresholds);
  }
  out << "Truncation   " << file.L_reason << "\n";
  out << "Model level  " << to_string(r.level.level) << " -- " << r.level.reason << "\n";
  for (const auto& w : r.warnings) out << "Warning      " << w << "\n";
  out << "\nExcess area by mode (Delta_l):\n";
  out << "    l      Delta_l(0)      Delta_l(T)   tail mean       change   sigma_l^c"
      << (u.physical() ? "  sigma_l^c [N/m]" : "") << "\n";
  for (int l = 2; l <= r.L; ++l) {
    const std::size_t k = std::size_t(l - 2);
    const double d0 = r.Delta_initial[k], d1 = r.Delta_final[k];
    out << std::setw(5) << l << std::setw(16) << d0 << std::setw(16) << d1 << std::setw(12) << r.Delta_tail_mean[k]
        << std::setw(13) << (d1 - d0);
    if (l >= 3) out << std::setw(12) << sigma_c(l, p.alpha());
    if (l >= 3 && u.physical()) out << std::setw(17) << sigma_c(l, p.alpha()) * u.tension_unit();
    out << "\n";
  }
  out << "\nl_Delta = " << r.l_Delta;
  if (r.l_Delta == 2)
    out << ": the ellipsoid is stable, the higher modes gave their area back to l = 2\n";
  else
    out << ": mode l = " << r.l_Delta << " took the most excess area from the ellipsoid ("
        << (r.oscillating ? "from the tail mean over the last " : "at T; tail window ") << file.options.tail_window
        << " time units" << u.seconds(file.options.tail_window) << ")\n";
  out << "sigma(T) = " << u.tension(r.sigma_final) << ", tail mean " << u.tension(r.sigma_tail_mean)
      << ", sigma(0) = " << u.tension(r.sigma_initial) << "\n";
  out << "r(T) = " << r.r_final << ", Psi(T) = " << degrees_text(r.Psi_final) << "\n";
  out << "Excess-area drift max_t |Delta(t) - Delta(0)| = " << r.excess_area_drift << "\n";
  analysis_text(out, file, r, pr);
  out << "Cost: " << r.counters.steps << " steps (" << r.counters.failed_steps << " rejected), "
      << r.counters.rhs_evaluations << " RHS and " << r.counters.jacobian_evaluations << " Jacobian evaluations, "
      << r.seconds << " s with " << to_string(file.options.integrator.stepper) << " at rtol "
      << file.options.integrator.rtol << "\n";
  if (r.early.terminated)
    out << "Early stop: at t = " << u.time(r.early.terminated_at) << " the state was certified on an attracting "
        << r.early.kind << " (margin 1 - max |mu| = " << r.early.margin << " +- " << r.early.margin_error
        << ", distance " << r.early.distance << "); the run resumed on it at t = " << u.time(r.early.resumed_at)
        << "\n";
  else if (!r.early.note.empty())
    out << "Full horizon: " << r.early.note << "\n";
  if (r.status != IntegrationStatus::success)
    out << "Status: " << to_string(r.status) << " at t = " << u.time(r.t_reached) << ": " << r.reason << "\n";
  else
    out << "Status: success\n";
  return out.str();
}

ThresholdReport threshold_report(const Scene& scene, bool exact_C_star_roots) {
  return threshold_report(validated(scene), exact_C_star_roots);
}

ThresholdReport threshold_report(const ValidScene& valid, bool exact_C_star_roots) {
  const Scene& scene = *valid;
  const Parameters& p = scene.parameters;
  const double alpha = p.alpha();
  ThresholdReport t;
  t.r0 = stress_free_r0(valid);
  t.criterion = out_of_plane_criterion(p, scene.L);
  t.prediction = predict(valid, nullptr);
  t.lambda_star_minus = std::isfinite(p.C) && alpha > 0 ? lambda_star_minus(alpha, p.C, p.Delta)
                                                        : Quantity::outside("needs finite C (alpha > 0)");
  t.has_exact_C_star = exact_C_star_roots;
  if (exact_C_star_roots) t.exact_C_star = exact_C_star(p, std::exp(-5.5), std::exp(2.0));
  return t;
}

nlohmann::json thresholds_json(const SceneFile& file, const ThresholdReport& t) {
  const Scene& s = file.scene;
  const Parameters& p = s.parameters;
  const double alpha = p.alpha();
  const ScenePrediction& pr = t.prediction;
  nlohmann::json j;
  j["scene"] = s.name;
  j["parameters"] = to_json(p);
  put_truncation(j, file);
  j["Lambda"] = p.Lambda();
  put_number(j, "S", p.S(), S_reason(p));
  j["alpha"] = alpha;
  j["r0"] = t.r0;
  j["l_star"] = l_star(alpha);
  j["sigma_star"] = sigma_star(alpha);
  j["l_star_criterion"] = l_star_criterion(alpha);
  j["alpha_l_star_2_5"] = alpha_for_l_star(2.5);
  j["surviving_mode"] = s.L >= 3 ? surviving_mode(alpha, s.L) : 2;
  nlohmann::json change = nlohmann::json::object();
  for (int l = 2; l < s.L; ++l) change[std::to_string(l) + "->" + std::to_string(l + 1)] = alpha_mode_change(l);
  j["alpha_mode_change"] = change;
  std::vector<double> sc;
  for (int l = 2; l <= s.L; ++l) sc.push_back(sigma_c(l, alpha));
  j["sigma_critical"] = by_mode(sc);
  j["sigma_R_initial"] = sigma_R_initial(p);
  put(j, "alpha_init", alpha_init(p));
  put(j, "mean_sigma_R_minus", mean_sigma_R_minus(p));
  put(j, "mean_sigma_R_plus", mean_sigma_R_plus(p, t.r0));
  put(j, "C_star_minus", C_star_minus(p));
  put(j, "C_star_plus", C_star_plus(p, t.r0));
  put(j, "C_star_plus_printed", C_star_plus_printed(p, t.r0));
  if (s.physical) {
    // C = c gamma at this cell: the shear rate [1/s] at which C reaches each C threshold (the reduced system's
    // thresholds depend on C through S alone, not on B).
    put_physical(j, s);
    const double per_C = s.physical->shear_rate / p.C;
    for (const auto& [key, q] : {std::pair{"C_star_minus", C_star_minus(p)}, {"C_star_plus", C_star_plus(p, t.r0)}})
      if (q.valid()) j[std::string(key) + "_shear_rate"] = q.value * per_C;
    if (t.has_exact_C_star) {
      std::vector<double> rates;
      for (double c : t.exact_C_star) rates.push_back(c * per_C);
      j["C_star_exact_out_of_plane_shear_rate"] = rates;
    }
  }
  put(j, "lambda_star_minus", t.lambda_star_minus);
  const OutOfPlaneEquilibrium& eq = t.criterion.equilibrium;
  j["sigma_R_equilibrium"] = eq.sigma_R;
  j["equilibrium"] = {{"r", eq.r},
                      {"Psi", eq.Psi},
                      {"mu", eq.mu},
                      {"stable", eq.stability_known() ? nlohmann::json(eq.stable) : nlohmann::json(nullptr)},
                      {"eigenvalues", {to_json(eq.eigenvalues[0]), to_json(eq.eigenvalues[1])}},
                      {"residual", eq.residual},
                      {"r_large_S", eq.r_large_S},
                      {"Psi_large_S", eq.Psi_large_S}};
  put(j["equilibrium"], "sigma_R_large_S", eq.sigma_R_large_S);
  j["unstable_modes_exact_equilibrium"] = t.criterion.unstable_exact;
  j["unstable_modes_large_S"] = t.criterion.unstable_large_S;
  put(j, "sigma_R_asymptotic", pr.sigma_R_asymptotic);
  j["sigma_R_asymptotic_source"] = pr.asymptotic_source;
  j["unstable_modes_asymptotic"] = pr.asymptotic.unstable;
  j["unstable_modes_finite_horizon"] = pr.finite_horizon.unstable;
  j["asymptotic"] = to_json(pr.asymptotic);
  j["finite_horizon"] = to_json(pr.finite_horizon);
  j["finite_horizon"]["T"] = pr.horizon.T;
  j["finite_horizon"]["mean_sigma_R"] = pr.horizon.mean_sigma_R;
  j["regime"] = to_string(pr.regime.regime);
  j["regime_reason"] = pr.regime.reason;
  if (t.has_exact_C_star) j["C_star_exact_out_of_plane"] = t.exact_C_star;
  explain_nulls(j, nonfinite_reason(p));
  return j;
}

std::string thresholds_text(const SceneFile& file, const ThresholdReport& t) {
  const Scene& s = file.scene;
  const Parameters& p = s.parameters;
  const double alpha = p.alpha();
  const ScenePrediction& pr = t.prediction;
  const OutOfPlaneCriterion& crit = t.criterion;
  const UnitText u(s);  // on a physical scene every tension also in N/m, time in s, rate in 1/s
  TextStream out;
  out << std::setprecision(6);
  out << "Scene '" << s.name << "': lambda = " << p.lambda << ", Delta = " << p.Delta << ", Delta0 = " << p.Delta0
      << ", B = " << p.B << ", C = " << p.C << ", beta = " << degrees_text(s.beta) << "\n";
  out << "Lambda = " << p.Lambda() << ", S = " << p.S() << ", alpha = " << alpha << ", r0 = " << t.r0 << "\n";
  if (s.physical)
    out << "Physical: shear rate " << s.physical->shear_rate
        << " 1/s; tensions in units of kappa/R^2 = " << u.tension_unit()
        << " N/m, times in units of 1/gamma = " << 1 / s.physical->shear_rate << " s\n";
  out << "Truncation: " << file.L_reason << "\n\n";
  out << "Continuous band (Eq. inst): l_* = " << l_star(alpha) << ", sigma_* = " << u.tension(sigma_star(alpha))
      << "; l_* >= 2.5 <=> alpha >= (35/8)^2 = " << alpha_for_l_star(2.5) << ": "
      << (l_star_criterion(alpha) ? "met" : "not met") << "\n";
  if (s.L >= 3) out << "Surviving integer mode (largest sigma_l^c): l = " << surviving_mode(alpha, s.L) << "\n";
  out << "alpha_*^init = " << to_text(alpha_init(p)) << " (sigma_R(0) = " << u.tension(sigma_R_initial(p)) << ")\n";
  out << "<sigma_R^-> = " << tension_text(u, mean_sigma_R_minus(p))
      << ", <sigma_R^+> = " << tension_text(u, mean_sigma_R_plus(p, t.r0)) << "  (Eq. ss_st_red, S >> 1)\n";
  out << "C_*^- = " << to_text(C_star_minus(p)) << ", C_*^+ = " << to_text(C_star_plus(p, t.r0))
      << " (printed A^+: " << to_text(C_star_plus_printed(p, t.r0)) << ")\n";
  // C = c gamma at this cell: each C threshold as the shear rate at which C reaches it (as the JSON's *_shear_rate).
  const double per_C = s.physical ? s.physical->shear_rate / p.C : kNotGiven;
  auto as_rate = [&](const Quantity& q) { return q.valid() ? format_value(q.value * per_C) + " 1/s" : to_text(q); };
  if (s.physical)
    out << "  as shear rates of this cell: C_*^- at " << as_rate(C_star_minus(p)) << ", C_*^+ at "
        << as_rate(C_star_plus(p, t.r0)) << "\n";
  out << "lambda_*^- = " << to_text(t.lambda_star_minus) << "\n";
  if (t.has_exact_C_star) {
    out << "Exact out-of-plane C_* (sigma_R^eq = sigma_*, C in [e^-5.5, e^2]):";
    for (double c : t.exact_C_star) out << " " << c << (s.physical ? " (" + format_value(c * per_C) + " 1/s)" : "");
    out << (t.exact_C_star.empty() ? " none\n" : "\n");
  }
  const OutOfPlaneEquilibrium& eq = crit.equilibrium;
  out << "\nExact out-of-plane equilibrium (every S): r = " << eq.r << ", Psi = " << degrees_text(eq.Psi)
      << ", sigma_R = " << u.tension(eq.sigma_R) << ", ";
  auto eigenvalue = [&](const std::complex<double>& e) {
    TextStream o;
    o << std::setprecision(6) << e;
    if (s.physical) o << " (" << e * s.physical->shear_rate << " 1/s)";
    return o.str();
  };
  if (eq.stability_known())
    out << (eq.stable ? "stable" : "unstable") << " (eigenvalues " << eigenvalue(eq.eigenvalues[0]) << ", "
        << eigenvalue(eq.eigenvalues[1]) << ")\n";
  else
    out << "stability n/a (eigenvalues " << nonfinite_reason(p) << ")\n";
  out << "  S >> 1 (Eq. ss_red): r = " << eq.r_large_S << ", Psi = " << degrees_text(eq.Psi_large_S)
      << ", <sigma_R> = " << tension_text(u, eq.sigma_R_large_S) << "\n";
  out << "  unstable modes: exact " << mode_list(crit.unstable_exact) << "; S >> 1 " << mode_list(crit.unstable_large_S)
      << "\n";
  out << "\nReduced regime: " << to_string(pr.regime.regime) << " (" << pr.regime.reason << ")\n";
  out << "Asymptotic predictor: <sigma_R> = " << tension_text(u, pr.sigma_R_asymptotic) << " from "
      << pr.asymptotic_source << "\n  unstable modes " << mode_list(pr.asymptotic.unstable)
      << ", l_Delta = " << pr.asymptotic.l_Delta << "\n";
  out << "Finite-horizon predictor (T = " << u.time(pr.horizon.T)
      << ", <sigma_R>_T = " << u.tension(pr.horizon.mean_sigma_R) << "): unstable modes "
      << mode_list(pr.finite_horizon.unstable) << ", l_Delta = " << pr.finite_horizon.l_Delta << "\n";
  return out.str();
}

SummaryRun run_summary(SceneFile file, const ShearRateSearchOptions& search) {
  SummaryRun out{std::move(file), {}, {}};
  // The one check of the scene (naming flags and files in its messages); the run may lower L to a checked one.
  const ValidScene valid = validated(out.file);
  // Certified: the automatic L and the finite-horizon predictor read its integral to T (exact to first order in
  // the certified distance, as a run's skip), so a long T costs no more than the transient to the attractor.
  const ReducedTransient transient = scene_transient(valid, out.file.options.full_horizon);
  SimulationOptions options = out.file.options;
  options.record_trajectory = false;  // the summary reports the run at T and its tail, not its samples
  out.run = simulate_scene(out.file, valid, options, &transient);
  out.prediction = predict(valid, transient, &out.run);
  if (out.file.scene.physical) out.prediction.shear_rate_thresholds = shear_rate_thresholds(out.file.scene, search);
  return out;
}

PostRun run_post(SceneFile file) {
  PostRun out{std::move(file), {}, {}};
  SimulationOptions options = out.file.options;
  options.record_trajectory = false;
  out.run = simulate_scene(out.file, options);
  out.post = post_instability(out.file.scene.parameters, out.file.scene.L, 0.0);
  return out;
}

}  // namespace rbcstab
