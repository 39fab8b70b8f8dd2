// Fig. 6 of the paper: the post-instability dynamics Delta_l(t), sigma(t) at lambda = 5 and 1 with the shapes the
// runs end in as insets, (e) the Fig. 6e table of Delta~_2 against Delta-bar_2, and the claims of its caption.
#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "rbcstab/analysis/post_instability.hpp"
#include "rbcstab/analysis/thresholds.hpp"
#include "rbcstab/model/scene.hpp"
#include "rbcstab/report/detail/paper_draw_spec.hpp"
#include "rbcstab/report/detail/paper_figures.hpp"
#include "rbcstab/report/detail/parameter_labels.hpp"
#include "rbcstab/report/shape.hpp"
#include "rbcstab/sweep/fig6e.hpp"

namespace rbcstab::detail::paper {

using namespace rbcstab::paper_measure;

namespace {

// The Fig. 6 insets: the shapes the OP and IP runs end in (Sec. V: "an initially OP RBC evolves into a stomatocyte
// ..., while an IP RBC evolves into a multi-lobed shape"), written on a (theta, phi) grid and drawn by the report's
// shape renderer, with a check of each shape's mode pattern from the final amplitudes.
json shape_insets(Composer& c, const std::vector<const Line*>& runs, const std::string& tag) {
  json insets = json::array();
  ShapeGridOptions grid;
  grid.n_theta = 48;  // an inset is ~200 px wide: finer facets are not seen
  grid.n_phi = 96;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const Line& l = *runs[i];
    const bool ip = i == 1;
    const ModeAmplitudes f = final_amplitudes(l.file.scene, l.run);
    const std::string csv = c.put(l.file.scene.name + "_shape_T.csv", to_csv(shape_on_grid(f, grid)));
    insets.push_back(
        {{"data", csv},
         {"in_plane", ip},
         {"label", std::string(ip ? "IP, from above" : "OP, from below") + ", $t=" + num(l.run.t_reached) + "$"},
         {"bounds", {0.6, ip ? 0.02 : 0.4, 0.4, 0.36}}});
    // Sec. V: "the long-time structures inherit their symmetry from their initial state and their orientation
    // with respect to the flow": the dominant mode's azimuthal pattern at T is its pattern at t = 0.
    int top = 3;
    for (int m = 4; m <= f.L; ++m)
      if (f.excess_area(m) > f.excess_area(top)) top = m;
    const std::vector<double> end = azimuthal_shares(f, top);
    const std::vector<double> start = azimuthal_shares(initial_state(l.file.scene).f, top);
    const std::string how =
        "final amplitudes f_{l,m}(T) of the delta = 1e-3 run (dominant mode Delta_" + std::to_string(top) + " = " +
        num(f.excess_area(top), 3) +
        "); m about the vorticity axis z; shares at t = 0 from the scene's initial state. The |m| shares of a "
        "mode l >= 3 keep their t = 0 values exactly in this model (f_{l,m}(t) = f_{l,m}(0) "
        "e^{i omega m t} sqrt(Delta_l(t) / Delta_l(0))): the inherited symmetry is the model's, "
        "what the run decides is the dominant mode";
    if (!ip)
      c.claim(tag +
                  ", OP: the cell evolves into a stomatocyte: its dominant l >= 3 mode is odd (a cup) and "
                  "axisymmetric about the vorticity axis, the symmetry it started with",
              paper_check::stomatocyte(top, end, start), how);
    else
      c.claim(tag +
                  ", IP: the cell evolves into a trilobe (the caption's word): its dominant l >= 3 mode is l = 3, "
                  "with no axisymmetric part about the vorticity axis and most area at |m| = 3 (three lobes in the "
                  "shear plane), the pattern it started with",
              paper_check::lobed(top, end, start, 3), how);
  }
  return insets;
}

}  // namespace

void fig6(Composer& c, int k, int n) {
  c.begin("fig6", "Fig. 6: post-instability dynamics", "Fig. 6", k, n);
  json panels = json::array();
  const char* lstyle[] = {"-", "--", "-."};
  const char* rcolor[] = {"tab:blue", "tab:cyan", "tab:red", "tab:orange"};
  for (int lam : {5, 1}) {
    const std::string pre = lam == 5 ? "fig6_ab_lambda5_" : "fig6_cd_lambda1_";
    const std::vector<std::string> names{pre + "op_delta1e-3", pre + "op_delta1e-10", pre + "ip_delta1e-3",
                                         pre + "ip_delta1e-10"};
    const std::string d3 = tex_value(SceneParameter::delta, 1e-3), d10 = tex_value(SceneParameter::delta, 1e-10);
    const std::string rlabel[] = {"OP, " + d3, "OP, " + d10, "IP, " + d3, "IP, " + d10};
    const std::vector<Line> runs = c.lines(names);
    const Parameters& p = runs[0].file.scene.parameters;
    const PostInstability post = post_instability(p, runs[0].file.scene.L);
    const double tilde = post.continuous.Delta2_tilde.value, s_star = sigma_star(p.alpha());
    const double T = runs[0].t().back(), w = 50;
    std::vector<double> bar2, bar_sigma;
    for (const Line& l : runs) {
      bar2.push_back(tail_mean(l.t(), l.Delta(2), w));
      bar_sigma.push_back(tail_mean(l.t(), l.run.trajectory.sigma, w));
    }
    double mean_bar = 0;
    for (double v : bar2) mean_bar += v / double(bar2.size());
    json sd = json::array(), ss = json::array();
    for (std::size_t i = 0; i < runs.size(); ++i) {
      for (int m = 2; m <= 4; ++m)
        sd.push_back(series(runs[i].csv, "Delta_" + std::to_string(m), "", rcolor[i], lstyle[m - 2], 1.3));
      ss.push_back(series(runs[i].csv, "sigma", rlabel[i], rcolor[i], "-", 1.2));
    }
    const std::string a = lam == 5 ? "(a)" : "(c)", b = lam == 5 ? "(b)" : "(d)";
    json pd = lines_panel(a + " $\\Delta_l(t)$, " + tex_value(SceneParameter::lambda, lam) +
                              " (solid $l=2$, dashed 3, dash-dot 4; runs as in " + b + ")",
                          "$\\Delta_l$", sd, "log", {1, T}, "log");
    pd["hlines"] = {hline(tilde, "$\\tilde\\Delta_2$ (theory)", "black", "-", 3),
                    hline(mean_bar, "$\\bar\\Delta_2$ (simulations)", "tab:green", "--", 2)};
    // The runs' legend is (b)'s and (d)'s, as in the paper; the right half below the curves holds the shapes.
    pd["legend_loc"] = "center left";
    json ps =
        lines_panel(b + " $\\sigma(t)$, " + tex_value(SceneParameter::lambda, lam), "$\\sigma$", ss, "log", {1, T});
    ps["hlines"] = {hline(s_star, "$\\sigma_*$", "black", "-", 3)};
    const std::string how = "means over t in [" + num(T - w) + ", " + num(T) + "]";
    const std::string tag = "lambda = " + std::to_string(lam);
    pd["insets"] = shape_insets(c, {&runs[0], &runs[2]}, tag);
    panels.push_back(pd);
    panels.push_back(ps);
    for (int ip = 0; ip < 2; ++ip) {
      const std::size_t i1 = std::size_t(2 * ip), i2 = i1 + 1;
      c.claim(tag + (ip ? ", IP" : ", OP") + ": the long-time Delta_2 and sigma do not depend on delta",
              paper_check::close({bar2[i1], bar_sigma[i1]}, {bar2[i2], bar_sigma[i2]}, 0.05,
                                 "Delta-bar_2; sigma at delta = 1e-3 / 1e-10"),
              how);
    }
    for (int ip = 0; ip < 2; ++ip)
      c.claim(
          tag + (ip ? ", IP" : ", OP") + ": the predicted Delta~_2 agrees with the simulated Delta-bar_2",
          paper_check::close({bar2[std::size_t(2 * ip)]}, {post.continuous.Delta2_tilde.valid() ? tilde : std::nan("")},
                             0.1, "Delta-bar_2 (simulated) / Delta~_2 (Eq. Delta2_tilde)"),
          how + "; delta = 1e-3; Delta~_2 with the continuous l_* (Eq. ss)");
    c.claim(tag + ": sigma saturates at ~sigma_*",
            paper_check::settles_at(runs[0].t(), runs[0].run.trajectory.sigma, s_star, w, 0.1),
            "sigma of the OP delta = 1e-3 run against sigma_* = -4 sqrt(alpha) = " + num(s_star) +
                " (closed form); means over the last two windows of " + num(w));
  }
  // (e): the Fig. 6e table.
  SceneFile e = c.scene("fig6e");
  apply_truncation(e, truncation_use(PanelKind::fig6e));
  Fig6eOptions f = fig6e_options(e);
  if (c.quick()) {
    f.B = {1, 4, 10};
    f.C = {0.01, 0.04};
  }
  std::vector<Fig6eRow> rows;
  {
    // fig6e_table runs its rows in turn: split it by lambda x B over the workers.
    std::vector<Fig6eOptions> parts;
    for (double lam : f.lambdas)
      for (double B : f.B) {
        Fig6eOptions part = f;
        part.lambdas = {lam};
        part.B = {B};
        parts.push_back(part);
      }
    std::vector<std::vector<Fig6eRow>> out(parts.size());
    parallel_for(parts.size(), c.threads(), [&](std::size_t i) { out[i] = fig6e_table(parts[i]); });
    for (auto& v : out) rows.insert(rows.end(), v.begin(), v.end());
  }
  const std::string table = c.put("fig6e.csv", fig6e_csv(f, rows));
  panels.push_back({{"kind", "fig6e"},
                    {"title", "(e) $\\tilde\\Delta_2$ against $\\bar\\Delta_2$"},
                    {"data", table},
                    {"lambda_symbol", parameter_row(SceneParameter::lambda).symbol}});
  std::vector<double> dev;
  std::map<double, std::vector<std::pair<double, double>>> by_lambda;  // (ln alpha, |ratio - 1|)
  for (const auto& r : rows)
    if (r.ratio.valid()) {
      dev.push_back(std::abs(r.ratio.value - 1));
      by_lambda[r.lambda].push_back({r.ln_alpha, std::abs(r.ratio.value - 1)});
    }
  c.claim("(e) Systematic agreement between Delta~_2 and Delta-bar_2",
          paper_check::median_below(dev, 0.1, "unstable rows' |Delta~_2 / Delta-bar_2 - 1|"),
          std::to_string(rows.size()) + " runs (lambda x B x C)");
  for (auto& [lam, v] : by_lambda)
    c.claim("(e) inset, lambda = " + num(lam) +
                ": the ratio Delta~_2 / Delta-bar_2 deviates more as alpha decreases "
                "towards the boundary",
            paper_check::falls_with(v, "|ratio - 1| by ln alpha"), std::to_string(v.size()) + " unstable rows");
  c.end(panels, 3, 2, 1300, 1750,
        "(a)-(d) Delta_l(t), l = 2..4, and sigma(t) for B = 2, C = 0.04, Delta = 1, Delta0 = 0.01, lambda = 5 (a, b) "
        "and 1 (c, d), delta = 1e-3, 1e-10, OP and IP; black: Delta~_2 and sigma_*; green: the simulations' "
        "Delta-bar_2. Insets of (a), (c): the shapes the delta = 1e-3 runs end in at T, OP (a stomatocyte, seen "
        "obliquely "
        "from below) and IP (a multi-lobed shape, seen from above the shear plane), coloured by the distance from the "
        "origin. (e) Delta~_2 against Delta-bar_2 over lambda = 1, 5, B, C; inset: the ratio against ln alpha.");
}

}  // namespace rbcstab::detail::paper
