#include "rbcstab/sweep/fig6e.hpp"

#include <algorithm>
#include <cmath>

#include "rbcstab/core/error.hpp"
#include "rbcstab/model/scene.hpp"
#include "rbcstab/verdict/certified_run.hpp"

namespace rbcstab {

void Fig6eOptions::validate() const {
  require(!lambdas.empty() && !B.empty() && !C.empty(), "lambdas/B/C", 0, "non-empty lists");
  simulation.validate();
  require_L(L, 3, kMaxL, "the Fig. 6e runs need a mode l >= 3");
}

std::vector<Fig6eRow> fig6e_table(const Fig6eOptions& options) {
  options.validate();
  std::vector<Fig6eRow> rows;
  for (double lambda : options.lambdas)
    for (double B : options.B)
      for (double C : options.C) {
        Scene s;
        s.name = "fig6e";
        s.parameters.lambda = lambda;
        s.parameters.B = B;
        s.parameters.C = C;
        s.parameters.Delta = options.Delta;
        s.parameters.Delta0 = options.Delta0;
        s.beta = options.beta;
        s.delta = options.delta;
        s.L = options.L;
        s.T = options.T;
        s.dt = std::max(1.0, options.T / 100);
        s.validate();
        Fig6eRow row;
        row.lambda = lambda;
        row.B = B;
        row.C = C;
        row.alpha = s.parameters.alpha();
        row.ln_alpha = std::log(row.alpha);
        const PostInstability post = post_instability(s.parameters, s.L, 0.0);
        row.surviving_mode = post.surviving_mode;
        row.Delta2_tilde = post.continuous.Delta2_tilde;
        row.Delta2_tilde_integer = post.integer_mode.Delta2_tilde;
        SimulationOptions so = options.simulation;
        so.record_trajectory = false;
        const SimulationResult r = simulate_certified(s, so);
        row.l_Delta = r.l_Delta;
        if (r.status != IntegrationStatus::success)
          row.Delta2_bar = Quantity::outside("simulation stopped: " + r.reason);
        else if (r.l_Delta == 2)
          row.Delta2_bar = Quantity::outside("stable: l_Delta = 2, no post-instability state");
        else
          row.Delta2_bar = Quantity::of(r.Delta_tail_mean[0]);
        auto ratio = [&](const Quantity& q) {
          if (!q.valid()) return Quantity::outside(q.reason);
          if (!row.Delta2_bar.valid()) return Quantity::outside(row.Delta2_bar.reason);
          return Quantity::of(q.value / row.Delta2_bar.value);
        };
        row.ratio = ratio(row.Delta2_tilde);
        row.ratio_integer = ratio(row.Delta2_tilde_integer);
        rows.push_back(row);
        if (options.on_progress)
          options.on_progress(double(rows.size()),
                              double(options.lambdas.size() * options.B.size() * options.C.size()));
      }
  return rows;
}

}  // namespace rbcstab
