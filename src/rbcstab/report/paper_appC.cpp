// Figs. app3 (OP) and app4 (IP) of the paper, App. C: the unperturbed reduced dynamics r(t), Psi(t) of the
// vesicle-like, unstressed and enucleated cell at lambda = 1, 3, 5, and the claims on tank-treading, swinging
// and tumbling.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "rbcstab/core/constants.hpp"
#include "rbcstab/report/detail/paper_draw_spec.hpp"
#include "rbcstab/report/detail/paper_figures.hpp"
#include "rbcstab/report/detail/parameter_labels.hpp"

namespace rbcstab::detail::paper {

using namespace rbcstab::paper_measure;

// App. C: unperturbed reduced dynamics of the three cells at lambda = 1, 3, 5 (OP: Fig. app3, IP: Fig. app4).
void app_vesicle(Composer& c, bool ip, int k, int n) {
  const std::string o = ip ? "ip" : "op";
  c.begin(std::string("appC_") + o,
          std::string("Fig. app") + (ip ? "4" : "3") + ": unperturbed dynamics, " + (ip ? "in plane" : "out of plane") +
              ": vesicle-like, unstressed and enucleated RBC",
          std::string("Fig. app") + (ip ? "4" : "3"), k, n);
  const char* cases[] = {"vesicle", "unstressed", "enucleated"};
  const char* colors[] = {"tab:green", ip ? "tab:brown" : "lightskyblue", ip ? "tab:red" : "tab:blue"};
  const char* styles[] = {"--", "-.", "-"};
  std::vector<std::string> names;
  for (int lam : {1, 3, 5})
    for (const char* cs : cases) names.push_back("appC_" + o + "_lambda" + std::to_string(lam) + "_" + cs);
  const std::vector<Line> runs = c.lines(names);
  json top = json::array(), bottom = json::array();
  const char* letters = "abcdef";
  const double T = runs[0].t().back(), w = 20;
  for (int j = 0; j < 3; ++j) {
    json sr = json::array(), sp = json::array();
    for (int i = 0; i < 3; ++i) {
      const Line& l = runs[std::size_t(3 * j + i)];
      sr.push_back(series(l.csv, "r", cases[i], colors[i], styles[i], i == 2 ? 1.8 : 1.4));
      sp.push_back(psi_series(l, cases[i], colors[i], styles[i], i == 2 ? 1.8 : 1.4));
    }
    const std::string lam = tex_value(SceneParameter::lambda, 2 * j + 1);
    std::pair<double, double> xlim;
    std::vector<Curve> rs;
    for (int i = 0; i < 3; ++i) {
      const Line& l = runs[std::size_t(3 * j + i)];
      rs.push_back({&l.t(), &l.run.trajectory.r});
    }
    const std::string xs = time_axis(rs, xlim);
    top.push_back(lines_panel(std::string("(") + letters[j] + ") $r(t)$, " + lam, "$r$", sr, xs, xlim));
    bottom.push_back(
        lines_panel(std::string("(") + letters[j + 3] + ") $\\Psi(t)$, " + lam, "$\\Psi$ (rad)", sp, xs, xlim));
  }
  auto at = [&](int lam, int cs) -> const Line& { return runs[std::size_t(3 * (lam / 2) + cs)]; };
  auto turn = [](const Line& l) { return net_turn(l.run.trajectory.Psi); };
  const std::string how = "T = " + num(T) + ", tail window " + num(w) +
                          "; turns of Psi with steps modulo pi (r -> -r, Psi -> Psi + pi is the same shape)";
  if (!ip) {
    double worst = 0, worst_r = 0;
    for (int cs = 0; cs < 3; ++cs) {
      worst = std::max(worst, std::abs(tail_mean(at(1, cs).t(), at(1, cs).run.trajectory.Psi, w) - kPi / 2));
      worst_r = std::max(worst_r, tail_range(at(1, cs).t(), at(1, cs).run.trajectory.r, w));
    }
    const double Lambda = at(1, 0).file.scene.parameters.Lambda();
    c.claim("lambda = 1: all three converge to tank-treading along Psi = pi/2",
            "max |<Psi> - pi/2| = " + num(worst, 3) + ", max tail range of r = " + num(worst_r, 3), "< 0.05 and < 1e-3",
            worst < 0.05 && worst_r < 1e-3,
            how + "; the reduced equations' tank-treading state at S >> 1 has cos Psi = Lambda r, i.e. Psi = arccos(" +
                num(Lambda, 3) + ") = " + num(std::acos(std::min(1.0, Lambda)), 3) + " at r = 1, not pi/2");
    // The text's Psi = pi/2 against the paper's own steady state (Eq. ss_red_TT: r = 1, Psi = arccos Lambda for
    // Lambda < 1, leading order in 1/S): at Delta = 1 (this repository's choice; App. C prints no Delta) Lambda =
    // 0.708 and arccos Lambda = 0.785, i.e. pi/4, the value the text gives for psi = Psi/2.
    double worst_ss = 0, worst_r1 = 0;
    std::string cells;
    for (int cs : {0, 2}) {  // vesicle-like (C = 1e6) and enucleated: S >> 1; the unstressed cell has S = 4.9
      const Line& l = at(1, cs);
      const double ss = std::acos(l.file.scene.parameters.Lambda());
      worst_ss = std::max(worst_ss, std::abs(tail_mean(l.t(), l.run.trajectory.Psi, w) - ss));
      worst_r1 = std::max(worst_r1, std::abs(tail_mean(l.t(), l.run.trajectory.r, w) - 1));
      cells += (cells.empty() ? "S = " : ", ") + num(l.file.scene.parameters.S(), 3);
    }
    c.claim(
        "lambda = 1: the tank-treading state is the reduced steady state r = 1, Psi = arccos Lambda (Eq. ss_red, "
        "Lambda < 1) for the vesicle-like and enucleated RBC",
        "max |<Psi> - arccos Lambda| = " + num(worst_ss, 3) + ", max |<r> - 1| = " + num(worst_r1, 3) +
            " (arccos Lambda = " + num(std::acos(std::min(1.0, Lambda)), 3) + ")",
        "< 0.02 and < 0.01", worst_ss < 0.02 && worst_r1 < 0.01,
        how + "; leading order in 1/S (" + cells +
            "); the unstressed RBC (S = " + num(at(1, 1).file.scene.parameters.S(), 3) + ") is left out");
    for (int lam : {3, 5})
      c.claim("lambda = " + std::to_string(lam) + ": the vesicle-like RBC tumbles",
              "net turn of Psi = " + num(turn(at(lam, 0))), "< -2 pi", turn(at(lam, 0)) < -2 * kPi, how);
    for (auto [lam, paper_t] : {std::pair{3, 20.0}, std::pair{5, 40.0}}) {
      const Line& u = at(lam, 1);
      const double ts = settle_time(u.t(), u.run.trajectory.r, 1e-3);
      c.claim("lambda = " + std::to_string(lam) + ": the unstressed RBC converges to a steady state quickly (t ~ " +
                  num(paper_t) + ")",
              "r within 1e-3 of its final value after t = " + num(ts, 3), "within a factor 2 of " + num(paper_t),
              ts > paper_t / 2 && ts < 2 * paper_t, how);
      const Line& e = at(lam, 2);
      const double te = settle_time(e.t(), e.run.trajectory.r, 1e-3);
      c.claim("lambda = " + std::to_string(lam) +
                  ": the enucleated RBC's oscillations are damped more slowly than the "
                  "unstressed RBC's",
              "settling time of r: enucleated " + num(te, 3) + ", unstressed " + num(ts, 3), "enucleated > unstressed",
              te > ts, "r within 1e-3 of its final value; " + how);
    }
  } else {
    const double ru = tail_range(at(1, 1).t(), at(1, 1).run.trajectory.Psi, w);
    const double re = tail_range(at(1, 2).t(), at(1, 2).run.trajectory.Psi, w);
    c.claim("lambda = 1: the unstressed RBC swings (small-angle Psi oscillations), reduced when Delta0 < Delta",
            "tail range of Psi: unstressed " + num(ru, 3) + ", enucleated " + num(re, 3),
            "unstressed > 1e-3 and > enucleated", ru > 1e-3 && ru > re, how);
    const Line& u3 = at(3, 1);
    const double drift_u = u3.run.trajectory.Psi.back() - tail_mean(u3.t(), u3.run.trajectory.Psi, T / 2);
    c.claim("lambda = 3: the vesicle-like RBC tumbles while the unstressed RBC swings",
            "vesicle net turn of Psi = " + num(turn(at(3, 0))) +
                "; unstressed Psi(T) minus its second-half mean = " + num(drift_u, 3),
            "vesicle < -2 pi; |unstressed| < pi/2", turn(at(3, 0)) < -2 * kPi && std::abs(drift_u) < kPi / 2, how);
    double worst = -1e300;
    for (int cs = 0; cs < 3; ++cs) worst = std::max(worst, turn(at(5, cs)));
    c.claim("lambda = 5: all three RBCs perform deformed tumbling",
            "largest net turn of Psi of the three = " + num(worst), "< -2 pi", worst < -2 * kPi, how);
  }
  json panels = top;
  for (auto& p : bottom) panels.push_back(p);
  c.end(
      panels, 2, 3, 1800, 900,
      std::string("Unperturbed reduced dynamics, ") + (ip ? "in plane" : "out of plane") +
          ": vesicle-like (C = 1e6, dashed green), unstressed (Delta = Delta0 = 1, C = 1, dash-dot) and enucleated RBC "
          "(Delta = 1, Delta0 = 0.01, C = 1, solid) at lambda = 1, 3, 5; top r(t), bottom Psi(t). Delta = 1 and "
          "Delta0 = 0.01 are this repository's choice (not printed in the paper).");
}

}  // namespace rbcstab::detail::paper
