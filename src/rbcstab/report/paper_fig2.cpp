// Fig. 2 of the paper: the reduced dynamics r(t), Psi(t) of OP and IP cells at Delta = 0.01 and 1, and the claims
// of its caption (steady OP states; IP swinging at small Delta, tumbling at large; larger Delta lowers r).
#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "rbcstab/core/constants.hpp"
#include "rbcstab/report/detail/paper_draw_spec.hpp"
#include "rbcstab/report/detail/paper_figures.hpp"

namespace rbcstab::detail::paper {

using namespace rbcstab::paper_measure;

void fig2(Composer& c, int k, int n) {
  c.begin("fig2", "Fig. 2: reduced system dynamics with different excess areas", "Fig. 2", k, n);
  const std::vector<std::string> names{"fig2_op_Delta0.01", "fig2_op_Delta1", "fig2_ip_Delta0.01", "fig2_ip_Delta1"};
  const std::vector<Line> runs = c.lines(names);
  const char* colors[] = {"tab:cyan", "tab:blue", "tab:orange", "tab:red"};
  const char* labels[] = {"OP, $\\Delta=0.01$", "OP, $\\Delta=1$", "IP, $\\Delta=0.01$", "IP, $\\Delta=1$"};
  const char* styles[] = {"--", "-", "--", "-"};
  json sr = json::array(), sp = json::array();
  for (std::size_t i = 0; i < runs.size(); ++i) {
    sr.push_back(series(runs[i].csv, "r", labels[i], colors[i], styles[i]));
    sp.push_back(psi_series(runs[i], labels[i], colors[i], styles[i]));
  }
  const double T = runs[0].t().back(), w = T / 5;
  std::pair<double, double> xlim;
  std::vector<Curve> rs;
  for (const Line& l : runs) rs.push_back({&l.t(), &l.run.trajectory.r});
  const std::string xs = time_axis(rs, xlim);
  json panels = {lines_panel("(a) $r(t)$", "$r$", sr, xs, xlim),
                 lines_panel("(b) $\\Psi(t)$", "$\\Psi$ (rad)", sp, xs, xlim)};
  const std::string how = "tail: the last " + num(w) + " time units of each run";
  for (int op = 0; op < 2; ++op) {
    const Line& small = runs[std::size_t(2 * op)];
    const Line& large = runs[std::size_t(2 * op + 1)];
    c.claim(std::string(op ? "IP" : "OP") + ": increasing Delta lowers r at long times (a less elongated cell)",
            paper_check::lower_at_long_times(small.t(), small.run.trajectory.r, large.t(), large.run.trajectory.r, w),
            how + "; r at Delta = 1 against r at Delta = 0.01");
  }
  for (int i = 0; i < 2; ++i) {
    const Line& l = runs[std::size_t(i)];
    c.claim(std::string("OP, ") + (i ? "Delta = 1" : "Delta = 0.01") +
                ": r saturates to a fixed value at a fixed angle Psi (steady state)",
            paper_check::steady(l.t(), l.run.trajectory.r, l.run.trajectory.Psi, w, 1e-3), how);
  }
  c.claim("IP, Delta = 0.01: swinging, Psi oscillates about a fixed angle",
          paper_check::swings(runs[2].t(), runs[2].run.trajectory.Psi, w), how);
  c.claim("IP, Delta = 1: r oscillates with a continuous rotation (Psi decreases): the cell deforms and tumbles",
          paper_check::tumbles(runs[3].run.trajectory.Psi),
          "Psi unwrapped along the run, steps modulo pi (r -> -r, Psi -> Psi + pi is the same shape)");
  c.end(panels, 1, 2, 1300, 500,
        "Reduced dynamics r(t), Psi(t) at C = 0.04, lambda = 5, Delta0 = 0.01, for beta = 0.001 (OP) and pi/2 (IP), "
        "Delta = 0.01 and 1. OP: steady r and Psi; IP: swinging at Delta = 0.01, tumbling at Delta = 1.");
}

}  // namespace rbcstab::detail::paper
