// rbcstab thresholds: the paper's instability thresholds for a scene, each with its domain, beside the exact
// finite-S out-of-plane criterion and the asymptotic and finite-horizon predictions (no modal simulation).
#include <cmath>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

#include "analysis_json.hpp"
#include "commands.hpp"
#include "exit_codes.hpp"
#include "rbcstab/analysis/steady_states.hpp"
#include "rbcstab/analysis/thresholds.hpp"
#include "rbcstab/io/json.hpp"
#include "rbcstab/model/coefficients.hpp"
#include "scene_options.hpp"

namespace rbcstab::cli {

namespace {
struct ThresholdsOptions {
  SceneOptions scene;
  bool json = false;
  bool exact_C_star = false;
};

int run(const ThresholdsOptions& o) {
  const SceneFile sf = o.scene.resolve(TruncationUse::analysis);
  const Scene& s = sf.scene;
  const Parameters& p = s.parameters;
  const double alpha = p.alpha();
  const double r0 = stress_free_r0(s);
  const OutOfPlaneCriterion crit = out_of_plane_criterion(p, s.L);
  const ScenePrediction pr = predict(s, nullptr);
  const Quantity lstar_m = std::isfinite(p.C) && alpha > 0 ? lambda_star_minus(alpha, p.C, p.Delta)
                                                           : Quantity::outside("needs finite C (alpha > 0)");
  std::vector<double> exact_roots;
  if (o.exact_C_star) exact_roots = exact_C_star(p, std::exp(-5.5), std::exp(2.0));

  if (o.json) {
    nlohmann::json j;
    j["parameters"] = rbcstab::to_json(p);
    put_truncation(j, sf);
    j["Lambda"] = p.Lambda();
    j["S"] = number_or_null(p.S());
    j["alpha"] = alpha;
    j["r0"] = r0;
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
    put(j, "mean_sigma_R_plus", mean_sigma_R_plus(p, r0));
    put(j, "C_star_minus", C_star_minus(p));
    put(j, "C_star_plus", C_star_plus(p, r0));
    put(j, "C_star_plus_printed", C_star_plus_printed(p, r0));
    put(j, "lambda_star_minus", lstar_m);
    const OutOfPlaneEquilibrium& eq = crit.equilibrium;
    j["sigma_R_equilibrium"] = eq.sigma_R;
    j["equilibrium"] = {{"r", eq.r},
                        {"Psi", eq.Psi},
                        {"mu", eq.mu},
                        {"stable", eq.stable},
                        {"eigenvalues", {to_json(eq.eigenvalues[0]), to_json(eq.eigenvalues[1])}},
                        {"residual", eq.residual},
                        {"r_large_S", eq.r_large_S},
                        {"Psi_large_S", eq.Psi_large_S}};
    put(j["equilibrium"], "sigma_R_large_S", eq.sigma_R_large_S);
    j["unstable_modes_exact_equilibrium"] = crit.unstable_exact;
    j["unstable_modes_large_S"] = crit.unstable_large_S;
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
    if (o.exact_C_star) j["C_star_exact_out_of_plane"] = exact_roots;
    std::cout << j.dump(2) << "\n";
    return kOk;
  }

  std::ostream& out = std::cout;
  out << std::setprecision(6);
  out << "Scene '" << s.name << "': lambda = " << p.lambda << ", Delta = " << p.Delta << ", Delta0 = " << p.Delta0
      << ", B = " << p.B << ", C = " << p.C << ", beta = " << s.beta << "\n";
  out << "Lambda = " << p.Lambda() << ", S = " << p.S() << ", alpha = " << alpha << ", r0 = " << r0 << "\n";
  out << "Truncation: " << sf.L_reason << "\n\n";
  out << "Continuous band (Eq. inst): l_* = " << l_star(alpha) << ", sigma_* = " << sigma_star(alpha)
      << "; l_* >= 2.5 <=> alpha >= (35/8)^2 = " << alpha_for_l_star(2.5) << ": "
      << (l_star_criterion(alpha) ? "met" : "not met") << "\n";
  if (s.L >= 3) out << "Surviving integer mode (largest sigma_l^c): l = " << surviving_mode(alpha, s.L) << "\n";
  out << "alpha_*^init = " << show(alpha_init(p)) << " (sigma_R(0) = " << sigma_R_initial(p) << ")\n";
  out << "<sigma_R^-> = " << show(mean_sigma_R_minus(p)) << ", <sigma_R^+> = " << show(mean_sigma_R_plus(p, r0))
      << "  (Eq. ss_st_red, S >> 1)\n";
  out << "C_*^- = " << show(C_star_minus(p)) << ", C_*^+ = " << show(C_star_plus(p, r0))
      << " (printed A^+: " << show(C_star_plus_printed(p, r0)) << ")\n";
  out << "lambda_*^- = " << show(lstar_m) << "\n";
  if (o.exact_C_star) {
    out << "Exact out-of-plane C_* (sigma_R^eq = sigma_*, C in [e^-5.5, e^2]):";
    for (double c : exact_roots) out << " " << c;
    out << (exact_roots.empty() ? " none\n" : "\n");
  }
  const OutOfPlaneEquilibrium& eq = crit.equilibrium;
  out << "\nExact out-of-plane equilibrium (every S): r = " << eq.r << ", Psi = " << eq.Psi
      << ", sigma_R = " << eq.sigma_R << ", " << (eq.stable ? "stable" : "unstable") << " (eigenvalues "
      << eq.eigenvalues[0] << ", " << eq.eigenvalues[1] << ")\n";
  out << "  S >> 1 (Eq. ss_red): r = " << eq.r_large_S << ", Psi = " << eq.Psi_large_S
      << ", <sigma_R> = " << show(eq.sigma_R_large_S) << "\n";
  out << "  unstable modes: exact " << mode_list(crit.unstable_exact) << "; S >> 1 " << mode_list(crit.unstable_large_S)
      << "\n";
  out << "\nReduced regime: " << to_string(pr.regime.regime) << " (" << pr.regime.reason << ")\n";
  out << "Asymptotic predictor: <sigma_R> = " << show(pr.sigma_R_asymptotic) << " from " << pr.asymptotic_source
      << "\n  unstable modes " << mode_list(pr.asymptotic.unstable) << ", l_Delta = " << pr.asymptotic.l_Delta << "\n";
  out << "Finite-horizon predictor (T = " << pr.horizon.T << ", <sigma_R>_T = " << pr.horizon.mean_sigma_R
      << "): unstable modes " << mode_list(pr.finite_horizon.unstable) << ", l_Delta = " << pr.finite_horizon.l_Delta
      << "\n";
  return kOk;
}
}  // namespace

static Runner add_thresholds(CLI::App& app) {
  auto o = std::make_shared<ThresholdsOptions>();
  o->scene.add_to(app);
  app.add_flag("--json", o->json, "print one JSON object on stdout");
  app.add_flag("--exact-C-star", o->exact_C_star,
               "also solve sigma_R(exact equilibrium) = sigma_* for C over the paper's range [e^-5.5, e^2]");
  return [o] { return run(*o); };
}

namespace {
const RegisterCommand kRegister{"thresholds", "Instability thresholds and predicted unstable modes of a scene (no simulation)",
                                add_thresholds, 30};
}  // namespace

}  // namespace rbcstab::cli
