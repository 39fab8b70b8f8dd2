// Fig. 5 of the paper: OP stability in the ln C - lambda plane at alpha = 40, 100, 500 (Delta = 1 and 0.1) with
// the lambda_*^- curves, and the claims on how alpha, Delta and lambda move the boundary.
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "rbcstab/report/bifurcation_plot.hpp"
#include "rbcstab/report/detail/paper_composer.hpp"
#include "rbcstab/report/detail/paper_figures.hpp"
#include "rbcstab/report/detail/parameter_labels.hpp"
#include "rbcstab/sweep/trace.hpp"

namespace rbcstab::detail::paper {

void fig5(Composer& c, int k, int n) {
  c.begin("fig5", "Fig. 5: out-of-plane stability in the ln C - lambda plane at alpha = 40, 100, 500", "Fig. 5", k, n);
  const int alphas[] = {40, 100, 500};
  const char* colors[] = {"tab:blue", "tab:orange", "tab:red"};
  const char* markers[] = {"o", "s", "^"};
  json panels = json::array();
  std::map<std::pair<char, int>, std::size_t> count;
  std::map<std::pair<char, int>, std::pair<std::size_t, std::size_t>> halves;  // unstable at lambda < 5, >= 5
  std::string grid;
  for (char panel : {'a', 'b'}) {
    json sets = json::array(), curves = json::array();
    for (int i = 0; i < 3; ++i) {
      const std::string name = std::string("fig5") + panel + "_op_alpha" + std::to_string(alphas[i]);
      const Diagram d = c.diagram(name, "Fig. 5");
      if (c.stopped()) return;
      grid = std::to_string(d.spec.x.count) + " x " + std::to_string(d.spec.y.count) + " grid per alpha";
      count[{panel, alphas[i]}] = d.unstable();
      halves[{panel, alphas[i]}] = {d.unstable([](const PointResult& p) { return p.y < 5; }),
                                    d.unstable([](const PointResult& p) { return p.y >= 5; })};
      sets.push_back({{"data", d.csv},
                      {"label", "unstable, " + tex_value(SceneParameter::alpha, alphas[i])},
                      {"color", colors[i]},
                      {"marker", markers[i]}});
      for (const Overlay& o : analytic_overlays(d.file.scene, d.spec, 200))
        if (o.name == "lambda_star_minus")
          curves.push_back({{"x", o.x},
                            {"y", o.y},
                            {"color", colors[i]},
                            {"style", "dashed"},
                            {"label", "$\\lambda_*^-$, " + tex_value(SceneParameter::alpha, alphas[i])}});
    }
    const std::string curves_file =
        c.put(std::string("fig5") + panel + "_lambda_star.json", json{{"curves", curves}}.dump(1) + "\n");
    panels.push_back({{"kind", "markers"},
                      {"title", std::string(panel == 'a' ? "(a) " : "(b) ") +
                                    tex_value(SceneParameter::Delta, panel == 'a' ? 1 : 0.1)},
                      {"sets", sets},
                      {"overlay", curves_file},
                      {"xlabel", tex_symbol("lnC")},
                      {"ylabel", tex_symbol("lambda")}});
  }
  auto counts = [&](char p) { return std::vector<std::size_t>{count[{p, 40}], count[{p, 100}], count[{p, 500}]}; };
  c.claim("(b) alpha = 40 is below alpha_*^init: the whole ln C - lambda plane is stable",
          paper_check::none(count[{'b', 40}], "unstable points at alpha = 40, Delta = 0.1"), grid);
  for (char p : {'a', 'b'})
    c.claim(std::string("(") + p + ") Increasing alpha pushes the boundary to higher C (more of the plane unstable)",
            paper_check::increasing(counts(p), "unstable points at alpha = 40, 100, 500"), grid);
  c.claim(
      "A similar effect for increased Delta: (a) Delta = 1 at least as unstable as (b) Delta = 0.1 at every alpha",
      paper_check::at_least_each(counts('a'), counts('b'), "unstable points at alpha = 40, 100, 500, (a) against (b)"),
      grid);
  const auto [low, high] = halves[{'a', 500}];
  c.claim("Increasing lambda destabilises RBCs with large C (panel (a), alpha = 500)",
          paper_check::more_than(high, low, "unstable points at lambda >= 5 against lambda < 5"), grid);
  c.end(
      panels, 1, 2, 1500, 650,
      "OP stability in ln C - lambda at alpha = 40, 100, 500 for Delta = 1 (a) and 0.1 (b); markers: unstable points; "
      "dashed: lambda_*^-(C) of Eq. ss_lambda_red for each alpha.");
}

}  // namespace rbcstab::detail::paper
