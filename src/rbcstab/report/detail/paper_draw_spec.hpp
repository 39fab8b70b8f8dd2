#pragma once
// The pieces of the drawing spec (paper.json, rendered by python/paper_draw.py) the figures share
// (module-private): a curve of a run's CSV, Psi(t) wrapped when the run tumbles, reference lines, a panel of
// curves against t and the choice of its time axis.
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "rbcstab/report/detail/paper_composer.hpp"

namespace rbcstab::detail::paper {

json series(const std::string& csv, const std::string& y, const std::string& label, const std::string& color,
            const std::string& ls = "-", double lw = 1.5);
// Psi(t) as a series. A tumbling run's Psi falls without bound and flattens every other curve of its panel: it is
// drawn modulo pi in (-pi/2, pi/2] (Psi and Psi + pi are one orientation of the l = 2 shape), its line broken at
// each wrap; the claims read the unwrapped Psi (net_turn).
json psi_series(const Line& l, const std::string& label, const std::string& color, const std::string& ls,
                double lw = 1.5);
json hline(double y, const std::string& label, const std::string& color, const std::string& ls, double lw = 1.2);
json lines_panel(const std::string& title, const std::string& ylabel, json s, const std::string& xscale,
                 std::pair<double, double> xlim, const std::string& yscale = "linear");

// One drawn curve x(t) on its run's samples (runs of one panel may have different grids and horizons).
struct Curve {
  const std::vector<double>* t;
  const std::vector<double>* x;
};

// The time axis: logarithmic from t = 1 when every drawn curve settles (to 1% of its swing) before T/5, so the
// fast transient is visible; when a curve still oscillates at the end, linear over the transient and a few cycles
// ([0, 4 t_band], t_band: when every curve has entered the band it oscillates in over the last 10% of its run), so
// the cycles stay readable (the CSV holds the whole run); linear over the run otherwise. T is the shortest run's
// horizon: no curve stops inside the drawn window.
std::string time_axis(const std::vector<Curve>& curves, std::pair<double, double>& xlim);

}  // namespace rbcstab::detail::paper
