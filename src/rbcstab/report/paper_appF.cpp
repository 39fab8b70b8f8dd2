// Fig. app2 of the paper, App. F: an initial growth of the perturbations suppressed by the reduced dynamics,
// Delta_l(t) of every mode at two values of C, and the claim on each run.
#include <algorithm>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include "rbcstab/report/detail/paper_draw_spec.hpp"
#include "rbcstab/report/detail/paper_figures.hpp"
#include "rbcstab/report/detail/parameter_labels.hpp"

namespace rbcstab::detail::paper {

namespace {

std::string tex_params(const Scene& s) {
  std::string text;
  for (SceneParameter q : stored_parameters("parameters"))
    text += (text.empty() ? "" : ", ") + tex_value(q, get_parameter(s, q));
  return text;
}

}  // namespace

void app_suppressed(Composer& c, int k, int n) {
  c.begin("appF", "Fig. app2: suppressed initial instability", "Fig. app2", k, n);
  const std::vector<Line> runs = c.lines({"appF_a", "appF_b"});
  json panels = json::array();
  for (int i = 0; i < 2; ++i) {
    const Line& l = runs[std::size_t(i)];
    json s = json::array();
    for (int m = 2; m <= l.run.L; ++m)  // every mode: the fastest initial growth is at l = 7-9 in (a)
      s.push_back(series(l.csv, "Delta_" + std::to_string(m), "$\\Delta_{" + std::to_string(m) + "}$",
                         "C" + std::to_string((m - 2) % 10), m == 2 ? "-" : (m % 2 ? "--" : "-.")));
    // The growth lasts a fraction of a time unit: a log time axis from the first sample.
    panels.push_back(lines_panel(std::string(i ? "(b)" : "(a)") + " " + tex_params(l.file.scene), "$\\Delta_l$", s,
                                 "log", {l.t()[1], l.t().back()}, "log"));
    std::vector<std::vector<double>> Delta;
    for (int m = 3; m <= l.run.L; ++m) Delta.push_back(l.Delta(m));
    c.claim(std::string(i ? "(b)" : "(a)") +
                ": an initial growth of the perturbations, suppressed by the reduced "
                "dynamics",
            paper_check::grows_then_suppressed(Delta, l.Delta_above2(), 2),
            "run to T = " + num(l.t().back()) + " sampled every " + num(l.t()[1]) +
                "; l_Delta = " + std::to_string(l.run.l_Delta) +
                "; a factor 2 is the least rise seen as growth on the figure's logarithmic Delta_l axis; beta = " +
                num(l.file.scene.beta) + " and delta = " + num(l.file.scene.delta) +
                " are this repository's choice (the caption prints neither)");
  }
  c.end(panels, 1, 2, 1300, 500,
        "Delta = 0.1, Delta0 = 0.01, lambda = 5, B = e^4, C = e^-2.7 (a) and e^-1 (b): an initial growth suppressed by "
        "the underlying reduced dynamics.");
}

}  // namespace rbcstab::detail::paper
