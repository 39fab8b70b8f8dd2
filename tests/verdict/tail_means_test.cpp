// Tail means by quadrature (SimulationOptions::tail_means = quadrature, integrate/simulation.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "rbcstab/core/error.hpp"
#include "rbcstab/io/scene_file.hpp"
#include "rbcstab/sweep/diagram.hpp"
#include "rbcstab/sweep/diagram_file.hpp"
#include "rbcstab/verdict/certified_run.hpp"

namespace rbcstab {
namespace {

SceneFile panel(const std::string& name) { return load_scene(std::string(RBCSTAB_SCENES_DIR) + "/" + name + ".toml"); }

SimulationOptions with(SimulationOptions o, TailMeans m, double rtol = 0) {
  o.tail_means = m;
  if (rtol > 0) {
    o.integrator.rtol = rtol;
    o.integrator.atol = 1e-16;
  }
  return o;
}

// Largest difference of the tail means, Delta_l on the scale Delta_total and sigma on max(1, |sigma|).
struct MeanDifference {
  double Delta = 0, sigma = 0;
};
MeanDifference mean_difference(const SimulationResult& a, const SimulationResult& b) {
  MeanDifference d;
  for (std::size_t k = 0; k < a.Delta_tail_mean.size(); ++k)
    d.Delta = std::max(d.Delta, std::abs(a.Delta_tail_mean[k] - b.Delta_tail_mean[k]) / b.Delta_total_initial);
  d.sigma = std::abs(a.sigma_tail_mean - b.sigma_tail_mean) / std::max(1.0, std::abs(b.sigma_tail_mean));
  return d;
}

struct Case {
  std::string name;
  Scene scene;
  SimulationOptions options;
};

std::vector<Case> cases() {
  std::vector<Case> v;
  for (const char* name : {"fig3_c_ip", "fig3_b_op"}) {
    const SceneFile sf = panel(name);
    v.push_back({name, sf.scene, sf.options});
    SimulationOptions o = sf.options;
    o.record_trajectory = false;
    v.push_back({std::string(name) + " (no trajectory)", sf.scene, o});
  }
  for (const char* name : {"appE_a_ip", "appE_b_ip", "appE_c_ip"}) {
    const SceneFile sf = panel(name);
    DiagramSpec spec = diagram_spec(sf);
    SimulationOptions o = sf.options;
    o.record_trajectory = false;
    for (std::size_t idx : {0u, 1000u, 2080u, 2600u, 3100u, 4095u})
      v.push_back({std::string(name) + " point " + std::to_string(idx), point_scene(sf.scene, spec, idx), o});
  }
  return v;
}

TEST(TailMeans, QuadratureAgreesWithGrid) {
  for (const Case& c : cases()) {
    const SimulationResult g = simulate(c.scene, with(c.options, TailMeans::grid));
    const SimulationResult q = simulate(c.scene, with(c.options, TailMeans::quadrature));
    const SimulationResult n = simulate(c.scene, with(c.options, TailMeans::none));
    const SimulationResult ref = simulate(c.scene, with(c.options, TailMeans::grid, 1e-12));
    const SimulationResult refq = simulate(c.scene, with(c.options, TailMeans::quadrature, 1e-12));
    const MeanDifference qg = mean_difference(q, g), gr = mean_difference(g, ref), qr = mean_difference(q, ref),
                         rr = mean_difference(refq, ref);
    double state = 0;
    for (std::size_t k = 0; k < q.y_final.size(); ++k) state = std::max(state, std::abs(q.y_final[k] - n.y_final[k]) / std::max(1.0, std::abs(n.y_final[k])));
    std::printf("%-28s q-g %.2e %.2e  g-ref %.2e %.2e  q-ref %.2e %.2e  ref-ref %.2e %.2e  state q-n %.2e  steps g %zu q %zu n %zu osc %d%d%d\n",
                c.name.c_str(), qg.Delta, qg.sigma, gr.Delta, gr.sigma, qr.Delta, qr.sigma, rr.Delta, rr.sigma, state,
                g.counters.steps, q.counters.steps, n.counters.steps, g.oscillating, q.oscillating, n.oscillating);
  }
}

}  // namespace
}  // namespace rbcstab
