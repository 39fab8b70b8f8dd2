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

std::string shares_text(const std::vector<double>& share) {
  std::string out;
  for (std::size_t m = 0; m < share.size(); ++m)
    out += (m ? ", " : "") + std::string("|m| = ") + std::to_string(m) + ": " + pct(share[m]);
  return out;
}

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
    double moved = 0;
    for (std::size_t m = 0; m < end.size(); ++m) moved = std::max(moved, std::abs(end[m] - start[m]));
    const std::size_t largest = std::size_t(std::max_element(end.begin(), end.end()) - end.begin());
    const std::string measured = "dominant l >= 3 mode at T: l = " + std::to_string(top) +
                                 " (Delta_l = " + num(f.excess_area(top), 3) + "); shares at T: " + shares_text(end) +
                                 "; largest change from t = 0: " + num(100 * moved, 3) + " points";
    const std::string how = "final amplitudes f_{l,m}(T) of the delta = 1e-3 run; m about the vorticity axis z";
    if (!ip)
      c.claim(tag +
                  ", OP: the cell evolves into a stomatocyte: its dominant l >= 3 mode is odd (a cup) and "
                  "axisymmetric about the vorticity axis, the symmetry it started with",
              measured, "odd l, |m| = 0 share >= 99%, shares within 1 point of t = 0",
              top % 2 == 1 && end[0] >= 0.99 && moved < 0.01, how);
    else
      c.claim(tag +
                  ", IP: the cell evolves into a multi-lobed shape: its dominant l >= 3 mode has no axisymmetric "
                  "part about the vorticity axis and most area at |m| = l (l lobes in the shear plane), the pattern "
                  "it started with",
              measured, "|m| = 0 share < 1%, |m| = l the largest share, shares within 1 point of t = 0",
              end[0] < 0.01 && largest == std::size_t(top) && moved < 0.01, how);
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
      const double d1 = bar2[std::size_t(2 * ip)], d2 = bar2[std::size_t(2 * ip + 1)];
      const double s1 = bar_sigma[std::size_t(2 * ip)], s2 = bar_sigma[std::size_t(2 * ip + 1)];
      const double gd = std::abs(d1 - d2) / std::abs(d1), gs = std::abs(s1 - s2) / std::abs(s1);
      c.claim(tag + (ip ? ", IP" : ", OP") + ": the long-time Delta_2 and sigma do not depend on delta",
              "Delta-bar_2 = " + num(d1) + " / " + num(d2) + ", sigma = " + num(s1) + " / " + num(s2) +
                  " (delta = 1e-3 / 1e-10; gaps " + pct(gd) + ", " + pct(gs) + ")",
              "both gaps < 5%", gd < 0.05 && gs < 0.05, how);
    }
    for (int ip = 0; ip < 2; ++ip) {
      const double ratio = tilde / bar2[std::size_t(2 * ip)];
      c.claim(tag + (ip ? ", IP" : ", OP") + ": the predicted Delta~_2 agrees with the simulated Delta-bar_2",
              "Delta~_2 = " + num(tilde) + ", Delta-bar_2 = " + num(bar2[std::size_t(2 * ip)]) + " (ratio " +
                  num(ratio) + ")",
              "|ratio - 1| < 10%", post.continuous.Delta2_tilde.valid() && std::abs(ratio - 1) < 0.1,
              how + "; delta = 1e-3; Delta~_2 with the continuous l_* (Eq. ss)");
    }
    const double sgap = std::abs(bar_sigma[0] - s_star) / std::abs(s_star);
    c.claim(tag + ": sigma saturates at ~sigma_*",
            "mean sigma (OP, delta = 1e-3) = " + num(bar_sigma[0]) + ", sigma_* = " + num(s_star) + " (gap " +
                pct(sgap) + ")",
            "gap < 10%", sgap < 0.1, how);
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
  if (dev.empty()) {
    c.claim("(e) Systematic agreement between Delta~_2 and Delta-bar_2", "no unstable row with a prediction",
            "some rows", false, "fig6e grid");
  } else {
    std::sort(dev.begin(), dev.end());
    const double median = dev[dev.size() / 2];
    c.claim("(e) Systematic agreement between Delta~_2 and Delta-bar_2",
            "median |ratio - 1| = " + pct(median) + " over " + std::to_string(dev.size()) + " unstable rows", "< 10%",
            median < 0.1, std::to_string(rows.size()) + " runs (lambda x B x C)");
  }
  for (auto& [lam, v] : by_lambda) {
    std::sort(v.begin(), v.end());
    double lo = 0, hi = 0;
    const std::size_t h = v.size() / 2;
    for (std::size_t i = 0; i < v.size(); ++i) (i < h ? lo : hi) += v[i].second;
    lo /= double(std::max<std::size_t>(h, 1));
    hi /= double(std::max<std::size_t>(v.size() - h, 1));
    c.claim("(e) inset, lambda = " + num(lam) +
                ": the ratio Delta~_2 / Delta-bar_2 deviates more as alpha decreases "
                "towards the boundary",
            "mean |ratio - 1| at the lower half of ln alpha = " + pct(lo) + ", upper half = " + pct(hi),
            "lower half > upper half", v.size() >= 2 && lo > hi, std::to_string(v.size()) + " unstable rows");
  }
  c.end(panels, 3, 2, 1300, 1750,
        "(a)-(d) Delta_l(t), l = 2..4, and sigma(t) for B = 2, C = 0.04, Delta = 1, Delta0 = 0.01, lambda = 5 (a, b) "
        "and 1 (c, d), delta = 1e-3, 1e-10, OP and IP; black: Delta~_2 and sigma_*; green: the simulations' "
        "Delta-bar_2. Insets of (a), (c): the shapes the delta = 1e-3 runs end in at T, OP (a stomatocyte, seen "
        "obliquely "
        "from below) and IP (a multi-lobed shape, seen from above the shear plane), coloured by the distance from the "
        "origin. (e) Delta~_2 against Delta-bar_2 over lambda = 1, 5, B, C; inset: the ratio against ln alpha.");
}

}  // namespace rbcstab::detail::paper
