// Fig. 3 of the paper: (a) the linear instability criterion at sigma_* and below it beside B Upsilon_l, (b)-(e)
// Delta_l(t) and sigma(t) of the OP and IP runs with their reduced companions, and the claims of its caption.
#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "rbcstab/analysis/thresholds.hpp"
#include "rbcstab/io/json.hpp"
#include "rbcstab/model/coefficients.hpp"
#include "rbcstab/report/detail/paper_draw_spec.hpp"
#include "rbcstab/report/detail/paper_figures.hpp"
#include "rbcstab/report/detail/parameter_labels.hpp"

namespace rbcstab::detail::paper {

using namespace rbcstab::paper_measure;

void fig3(Composer& c, int k, int n) {
  c.begin("fig3", "Fig. 3: linear instability criteria and dynamics", "Fig. 3", k, n);
  // (a): the formulas at alpha = B/C of the scene.
  const SceneFile a = c.scene("fig3a_criterion");
  const Parameters& p = a.scene.parameters;
  const double alpha = p.alpha(), s_star = sigma_star(alpha);
  auto crit = [&](double l, double s) {
    const double Pi = l * (l + 1);
    return -Pi * Pi - s * Pi - 4 * alpha;
  };
  // The paper does not print its sigma below sigma_*: the first sigma in (3 sigma_*, sigma_*) (steps of 0.01 sigma_*)
  // at which l_c rounds to another mode than the fastest-growing one, as its panel illustrates; 1.25 sigma_* if none.
  auto rate = [&](int l, double s) {
    return (Gamma1(p.lambda, l) + s * Gamma2(p.lambda, l)) / p.B + Gamma3(p.lambda, l) / p.C;
  };
  auto fastest_mode = [&](double s) {
    int best_mode = 2;
    for (int l = 3; l <= 40; ++l)
      if (rate(l, s) > rate(best_mode, s)) best_mode = l;
    return best_mode;
  };
  double s_below = 1.25 * s_star;
  for (int i = 1; i <= 200; ++i) {
    const double s = s_star * (1 + 0.01 * i);
    if (int(std::lround(unstable_band(s, alpha).l_c.value)) != fastest_mode(s)) {
      s_below = s;
      break;
    }
  }
  const std::string s_text = "sigma = " + num(s_below / s_star, 3) + " sigma_*";
  std::ostringstream ca, cb;
  ca << "l,criterion_sigma_star,criterion_below\n";
  for (int i = 0; i <= 400; ++i) {
    const double l = 1 + 7.0 * i / 400;
    ca << csv_number(l) << ',' << csv_number(crit(l, s_star)) << ',' << csv_number(crit(l, s_below)) << '\n';
  }
  cb << "l,B_Upsilon\n";
  const int fastest = fastest_mode(s_below);
  for (int l = 2; l <= 8; ++l) cb << l << ',' << csv_number(p.B * Upsilon_l(p, l, s_below)) << '\n';
  const std::string fa = c.put("criterion.csv", ca.str()), fb = c.put("growth_rates.csv", cb.str());
  const UnstableBand band = unstable_band(s_below, alpha);
  const double ls = l_star(alpha);
  json pa = {{"kind", "lines"},
             {"title", "(a) criterion at " + tex_value(SceneParameter::alpha, alpha)},
             {"xlabel", "$l$"},
             {"ylabel", "$-\\Pi^2-\\sigma\\Pi-4\\alpha$"},
             {"xscale", "linear"},
             {"yscale", "linear"},
             {"xlim", {1, 8}},
             {"ylim", {-4 * alpha, 1.2 * std::max(crit(band.l_c.value, s_below), 0.0) + 10}},
             {"series",
              {{{"data", fa},
                {"x", "l"},
                {"y", "criterion_sigma_star"},
                {"label", "$\\sigma=\\sigma_*$"},
                {"color", "black"},
                {"ls", "--"},
                {"lw", 1.5}},
               {{"data", fa},
                {"x", "l"},
                {"y", "criterion_below"},
                {"label", "$\\sigma=" + num(s_below / s_star, 3) + "\\,\\sigma_*$"},
                {"color", "black"},
                {"ls", "-"},
                {"lw", 1.8}},
               {{"data", fb},
                {"x", "l"},
                {"y", "B_Upsilon"},
                {"label", "$\\mathcal{B}\\Upsilon_l$ (right axis)"},
                {"color", "tab:green"},
                {"ls", "-"},
                {"lw", 1.2},
                {"marker", "o"},
                {"right", true}}}},
             {"hlines", {hline(0, "", "0.5", ":", 1.0)}},
             {"vlines",
              {{{"x", band.l_c.value}, {"label", "$l_c$"}, {"color", "black"}, {"ls", "--"}},
               {{"x", ls}, {"label", "$l_*$"}, {"color", "0.4"}, {"ls", ":"}},
               {{"x", band.l_plus.value}, {"label", "$l_+$"}, {"color", "0.4"}, {"ls", "-."}},
               {{"x", double(fastest)}, {"label", "fastest $\\Upsilon_l$"}, {"color", "tab:green"}, {"ls", "--"}}}}};
  // The closed forms drawn (sigma_*, l_* of the thresholds module) against a numerical maximisation of the criterion.
  c.claim("(a) At sigma = sigma_* = -4 sqrt(alpha) the criterion is marginal: its maximum over l is 0, at l_*",
          paper_check::marginal(alpha, s_star, ls),
          "alpha = B/C = " + num(alpha) + " from fig3a_criterion.toml; sigma_* = " + num(s_star) +
              " and l_* from their closed forms, the maximum found on a grid of continuous l refined to 1e-7");
  // The growth rates built from the paper's coefficients Gamma_1..3 as Eq. (growth) writes them, not from the
  // simplified form: the claim is that the two share their roots.
  std::vector<double> rates, criteria;
  for (double s : {s_below, s_star, 0.5 * s_star})
    for (int l = 2; l <= 40; ++l) {
      rates.push_back(rate(l, s));
      criteria.push_back(crit(l, s));
    }
  c.claim("(a) The roots of B Upsilon_l are those of the simplified criterion (same sign at every l)",
          paper_check::same_signs(rates, criteria, "l = 2..40 at three sigma"),
          s_text +
              ", sigma_* and sigma_* / 2 (the paper does not print its value below sigma_*); Upsilon_l = "
              "[Gamma_1 + sigma Gamma_2] / B + Gamma_3 / C");
  c.claim("(a) l_c can differ from the fastest-growing mode",
          paper_check::modes_differ(int(std::lround(band.l_c.value)), fastest,
                                    "round(l_c) (closed form) and the fastest-growing integer mode (Gamma_1..3)"),
          s_text +
              ": the first sigma below sigma_* (steps of 0.01 sigma_*, down to 3 sigma_*) where they differ; "
              "integer l only (Upsilon_l is defined at integer l)");

  // (b)-(e): OP and IP runs with their reduced companions (sigma_R).
  const std::vector<Line> runs = c.lines({"fig3_b_op", "fig3_c_ip"}, true);
  json panels = {pa};
  const double sc3 = sigma_c(3, runs[0].file.scene.parameters.alpha());
  const double sc4 = sigma_c(4, runs[0].file.scene.parameters.alpha());
  const char* lcolor[] = {"tab:blue", "tab:orange", "tab:green"};
  json delta_panels = json::array(), sigma_panels = json::array();
  for (int ip = 0; ip < 2; ++ip) {
    const Line& l = runs[std::size_t(2 * ip)];
    const Line& red = runs[std::size_t(2 * ip + 1)];
    const std::string tag = ip ? "IP" : "OP";
    std::vector<std::vector<double>> D;
    for (int m = 2; m <= 4; ++m) D.push_back(l.Delta(m));
    std::pair<double, double> xlim;
    const std::string xs =
        time_axis({{&l.t(), &D[0]}, {&l.t(), &D[1]}, {&l.t(), &D[2]}, {&l.t(), &l.run.trajectory.sigma}}, xlim);
    json s = json::array();
    for (int m = 2; m <= 4; ++m)
      s.push_back(series(l.csv, "Delta_" + std::to_string(m), "$\\Delta_" + std::to_string(m) + "$", lcolor[m - 2],
                         m == 2 ? "-" : (m == 3 ? "--" : "-.")));
    delta_panels.push_back(
        lines_panel(std::string(ip ? "(c)" : "(b)") + " $\\Delta_l(t)$, " + tag, "$\\Delta_l$", s, xs, xlim, "log"));
    json ps = lines_panel(std::string(ip ? "(e)" : "(d)") + " $\\sigma(t)$, " + tag, "$\\sigma$",
                          {series(red.csv, "sigma", "$\\sigma_R(t)$ (reduced)", "0.6", "-", 3.5),
                           series(l.csv, "sigma", "$\\sigma(t)$", "black", "-", 1.3)},
                          xs, xlim);
    ps["hlines"] = {hline(sc3, "$\\sigma_3^c$", "tab:blue", "--"), hline(sc4, "$\\sigma_4^c$", "tab:purple", "-.")};
    // sigma_R of a tumbling or swinging companion swings far: the axis follows sigma(t) and the thresholds.
    const auto [lo, hi] = std::minmax_element(l.run.trajectory.sigma.begin(), l.run.trajectory.sigma.end());
    const double ymin = std::min({*lo, sc3, sc4}), ymax = std::max({*hi, sc3, sc4}), pad = 0.08 * (ymax - ymin);
    ps["ylim"] = {ymin - pad, ymax + pad};
    sigma_panels.push_back(ps);

    const double T = l.t().back(), w = 50;
    const std::string run = "fig3_" + std::string(ip ? "c_ip" : "b_op") + ".toml run to T = " + num(T);
    c.claim(tag + ": Delta_2 decreases while Delta_3 and Delta_4 grow initially",
            paper_check::redistributes(D[0], D[1], D[2]), run);
    c.claim(tag + ": Delta_4 first grows, then decays (l = 4 is stabilised)",
            paper_check::grows_then_decays(D[2], 2, 0.5),
            run +
                "; samples on the scene's output grid; a factor 2 is the least rise seen as growth on the paper's "
                "logarithmic Delta_l axis");
    const std::vector<double> above = l.Delta_above2();
    c.claim(tag + ": Delta_3 takes the area (l = 3 keeps growing and holds the excess area beyond l = 2)",
            paper_check::takes_share(l.t(), D[1], above, w, 0.9),
            "Delta_3 / sum_{l>=3} Delta_l, means over t in [" + num(T - w) + ", " + num(T) + "]");
    c.claim(tag + (ip ? ": the period-averaged sigma settles at sigma_3^c" : ": sigma settles at sigma_3^c"),
            paper_check::settles_at(l.t(), l.run.trajectory.sigma, sc3, w, 0.02),
            "sigma_3^c = " + num(sc3) + " (closed form); means over the last two windows of " + num(w) + " of " + run);
    double onset = T;
    for (std::size_t i = 0; i < above.size(); ++i)
      if (above[i] > 10 * above.front()) {
        onset = l.t()[i];
        break;
      }
    c.claim(tag + ": sigma(t) initially follows the reduced system's sigma_R(t)",
            paper_check::follows(l.t(), l.run.trajectory.sigma, red.run.trajectory.sigma, onset, 0.05),
            "sigma of the full run against sigma_R of its reduced companion (another model level), while the "
            "instability develops: until sum_{l>=3} Delta_l has grown tenfold");
  }
  panels.push_back(delta_panels[0]);
  panels.push_back(delta_panels[1]);
  panels.push_back(sigma_panels[0]);
  panels.push_back(sigma_panels[1]);
  c.end(
      panels, 3, 2, 1300, 1450,
      "(a) the simplified criterion at alpha = 25, at sigma_* (dashed) and below it (solid), and B Upsilon_l (green). "
      "(b)-(c) Delta_l(t), l = 2..4, for C = 0.04, B = 2, Delta = 1, Delta0 = 0.01, lambda = 5, OP and IP; "
      "(d)-(e) sigma(t), sigma_R(t) (thick grey) and sigma_3^c, sigma_4^c.");
}

}  // namespace rbcstab::detail::paper
