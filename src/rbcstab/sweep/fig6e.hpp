#pragma once
// The Fig. 6e grid (paper Sec. V): the post-instability Delta~2 (both variants, analysis/post_instability.hpp)
// against the simulated long-time Delta-bar_2 (tail mean of the modal run), one run per (lambda, B, C).
#include <vector>

#include "rbcstab/analysis/post_instability.hpp"
#include "rbcstab/analysis/quantity.hpp"
#include "rbcstab/core/progress.hpp"
#include "rbcstab/integrate/simulation.hpp"

namespace rbcstab {

struct Fig6eOptions {
  std::vector<double> lambdas = {1, 5};                     // the paper's two panels
  std::vector<double> B = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10};  // "B = 1-10"
  std::vector<double> C = {0.01, 0.02, 0.04, 0.08};         // alpha = B/C from 12.5 to 1000
  double Delta = 1, Delta0 = 0.01;                          // as Fig. 6 (a)-(d)
  double beta = 0.001, delta = 1e-3;                        // out of plane, the paper's perturbation
  int L = 10;
  double T = 500;                // the paper's horizon
  SimulationOptions simulation;  // tail_window = 10: the paper's average
  ProgressCallback on_progress;  // runs done of the grid's, after each run
  void validate() const;
};
struct Fig6eRow {
  double lambda = 0, B = 0, C = 0, alpha = 0, ln_alpha = 0;
  int surviving_mode = 3, l_Delta = 2;
  Quantity Delta2_tilde, Delta2_tilde_integer;  // predicted
  Quantity Delta2_bar;                          // simulated (outside_domain if the run failed or stayed stable)
  Quantity ratio, ratio_integer;                // Delta~2 / Delta-bar_2
};
std::vector<Fig6eRow> fig6e_table(const Fig6eOptions& options = {});

}  // namespace rbcstab
