// rbcstab summary: the main job, a readable account of one scene.
#include <cmath>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

#include "analysis_json.hpp"
#include "commands.hpp"
#include "exit_codes.hpp"
#include "rbcstab/analysis/post_instability.hpp"
#include "rbcstab/analysis/predictors.hpp"
#include "rbcstab/analysis/thresholds.hpp"
#include "rbcstab/verdict/predict.hpp"
#include "rbcstab/model/coefficients.hpp"
#include "scene_options.hpp"

namespace rbcstab::cli {

namespace {

// The scene's analysis: regime, thresholds, the three predictors and Delta~2 predicted vs simulated.
void print_analysis(std::ostream& out, const Scene& s, const ReducedTransient& transient, const SimulationResult& r,
                    double tail_window) {
  const Parameters& p = s.parameters;
  const double alpha = p.alpha();
  const ScenePrediction pr = predict(s, transient, &r);
  out << "\nAnalysis (docs/theory.md)\n";
  out << "Regime       " << to_string(pr.regime.regime) << " -- " << pr.regime.reason << " (reduced dynamics)\n";
  out << "Thresholds   sigma_* = " << sigma_star(alpha) << ", l_* = " << l_star(alpha)
      << (l_star_criterion(alpha) ? " (>= 2.5: an integer mode l >= 3 can be excited)" : " (< 2.5: no l >= 3 band)")
      << ", alpha_*^init = " << show(alpha_init(p)) << "\n";
  if (s.L >= 3) out << "             surviving integer mode (largest sigma_l^c) l_s = " << surviving_mode(alpha, s.L) << "\n";
  out << "Predictors   (a) asymptotic     <sigma_R> = " << show(pr.sigma_R_asymptotic) << " ("
      << pr.asymptotic_source << "): unstable " << mode_list(pr.asymptotic.unstable) << ", l_Delta = " << pr.asymptotic.l_Delta
      << "\n";
  out << "             (b) finite horizon <sigma_R>_T = " << pr.horizon.mean_sigma_R << " over [0, " << pr.horizon.T
      << "]: unstable " << mode_list(pr.finite_horizon.unstable) << ", l_Delta = " << pr.finite_horizon.l_Delta
      << " (linear growth exp(2 G_l))\n";
  out << "             (c) simulation     unstable " << mode_list(pr.simulation.unstable) << ", l_Delta = " << pr.simulation.l_Delta
      << "\n";
  if (s.L >= 3) {
    const PostInstability post = post_instability(p, s.L, 0.0);
    out << "Delta~2      predicted: continuous l_* " << show(post.continuous.Delta2_tilde) << ", integer l_s = "
        << post.surviving_mode << " " << show(post.integer_mode.Delta2_tilde) << "\n";
    if (r.l_Delta >= 3 && r.status == IntegrationStatus::success)
      out << "             simulated Delta-bar_2 = " << r.Delta_tail_mean[0] << " (tail mean over the last " << tail_window
          << ")\n";
    else
      out << "             simulated: no post-instability state (l_Delta = " << r.l_Delta << ")\n";
  }
}

// The summary as one JSON object: the run (the keys of `simulate --json`), then the analysis.
nlohmann::json summary_json(const Scene& s, const ReducedTransient& transient, const SimulationResult& r,
                            double tail_window) {
  const Parameters& p = s.parameters;
  const double alpha = p.alpha();
  const ScenePrediction pr = predict(s, transient, &r);
  nlohmann::json j = rbcstab::to_json(r);
  j.erase("trajectory");
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
    if (r.l_Delta >= 3 && r.status == IntegrationStatus::success)
      j["Delta2_simulated"] = number_or_null(r.Delta_tail_mean[0]);
    else {
      j["Delta2_simulated"] = nullptr;
      j["Delta2_simulated_reason"] = "no post-instability state (l_Delta = " + std::to_string(r.l_Delta) + ")";
    }
  }
  j["tail_window"] = tail_window;
  return j;
}

struct SummaryOptions {
  SceneOptions scene;
  bool json = false;
};

int run(const SummaryOptions& o) {
  const SceneOptions& so = o.scene;
  ReducedTransient transient;  // integrated once: the truncation rule and the finite-horizon predictor read it
  const SceneFile sf = so.resolve(TruncationUse::simulation, &transient);
  const Scene& s = sf.scene;
  const Parameters& p = s.parameters;
  const SimulationResult r = simulate(s, sf.options);
  if (o.json) {
    nlohmann::json j = summary_json(s, transient, r, sf.options.tail_window);
    put_truncation(j, sf);
    std::cout << j.dump(2) << "\n";
    return r.status == IntegrationStatus::success ? kOk : kRunFailed;
  }
  std::ostream& out = std::cout;
  out << std::setprecision(6);
  out << "rbcstab " << RBCSTAB_VERSION << " -- scene '" << s.name << "'\n\n";
  out << "Parameters   lambda = " << p.lambda << ", Delta = " << p.Delta << ", Delta0 = " << p.Delta0 << ", B = " << p.B
      << ", C = " << p.C << "\n";
  out << "             beta = " << s.beta << ", delta = " << s.delta << ", L = " << s.L << ", T = " << s.T << "\n";
  out << "Derived      Lambda = " << p.Lambda() << ", S = " << p.S() << ", alpha = B/C = " << p.alpha() << "\n";
  out << "Truncation   " << sf.L_reason << "\n";
  out << "Model level  " << to_string(r.level.level) << " -- " << r.level.reason << "\n";
  for (const auto& w : r.warnings) out << "Warning      " << w << "\n";
  out << "\nExcess area by mode (Delta_l):\n";
  out << "    l      Delta_l(0)      Delta_l(T)   tail mean       change   sigma_l^c\n";
  for (int l = 2; l <= r.L; ++l) {
    const std::size_t k = std::size_t(l - 2);
    const double d0 = r.Delta_initial[k], d1 = r.Delta_final[k];
    out << std::setw(5) << l << std::setw(16) << d0 << std::setw(16) << d1 << std::setw(12) << r.Delta_tail_mean[k]
        << std::setw(13) << (d1 - d0);
    if (l >= 3) out << std::setw(12) << sigma_c(l, p.alpha());
    out << "\n";
  }
  out << "\nl_Delta = " << r.l_Delta;
  if (r.l_Delta == 2)
    out << ": the ellipsoid is stable, the higher modes gave their area back to l = 2\n";
  else
    out << ": mode l = " << r.l_Delta << " took the most excess area from the ellipsoid ("
        << (r.oscillating ? "from the tail mean over the last " : "at T; tail window ") << sf.options.tail_window
        << " time units)\n";
  out << "sigma(T) = " << r.sigma_final << " (tail mean " << r.sigma_tail_mean << "), sigma(0) = " << r.sigma_initial
      << "\n";
  out << "r(T) = " << r.r_final << ", Psi(T) = " << r.Psi_final << "\n";
  out << "Excess-area drift max_t |Delta(t) - Delta(0)| = " << r.excess_area_drift << "\n";
  print_analysis(out, s, transient, r, sf.options.tail_window);
  out << "Cost: " << r.counters.steps << " steps (" << r.counters.failed_steps << " rejected), "
      << r.counters.rhs_evaluations << " RHS and " << r.counters.jacobian_evaluations << " Jacobian evaluations, "
      << r.seconds << " s with " << to_string(sf.options.integrator.stepper) << " at rtol " << sf.options.integrator.rtol
      << "\n";
  if (r.status != IntegrationStatus::success) {
    out << "Status: " << to_string(r.status) << " at t = " << r.t_reached << ": " << r.reason << "\n";
    return kRunFailed;
  }
  out << "Status: success\n";
  return kOk;
}
}  // namespace

static Runner add_summary(CLI::App& app) {
  auto o = std::make_shared<SummaryOptions>();
  o->scene.add_to(app);
  app.add_flag("--json", o->json, "print one JSON object on stdout (the keys of simulate --json, then the analysis)");
  return [o] { return run(*o); };
}

namespace {
const RegisterCommand kRegister{"summary", "The main job: a readable summary of a scene (default: the paper's Fig. 3 case)", add_summary, 10};
}  // namespace

}  // namespace rbcstab::cli
