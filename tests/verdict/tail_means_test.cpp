// Tail means by quadrature (SimulationOptions::tail_means, integrate/simulation.hpp), on the Fig. 3 scenes and
// points of the App. E panels.
//
// Oracle: Simpson's rule on 1280 intervals over the window, from the samples of an rtol 1e-12 run whose output
// grid (dt = 10/1280) ends a step at each of them; its quadrature error is (160/1280)^4 = 1/4096 of the 160-point
// grid's (measured: the rtol 1e-12 quadrature means agree with it to 1.7e-12 in Delta, on Delta_total). At rtol
// 1e-8 both methods carry the run's integration error up to the window, the same for both (the runs are
// bit-identical until then): measured 2e-8 in Delta, and 1.6e-5 in sigma's mean at App. E(b) point 4095, a
// sensitive point. Quadrature against grid at the same rtol, which isolates the window: 3.8e-9 (Delta) and 2.7e-7
// (sigma, App. E(b) point 4095: the grid's own Simpson error there, 2.8e-7 between the two at rtol 1e-12).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "rbcstab/core/error.hpp"
#include "rbcstab/io/scene_file.hpp"
#include "rbcstab/sweep/diagram.hpp"
#include "rbcstab/sweep/diagram_table.hpp"
#include "rbcstab/verdict/certified_run.hpp"
#include "verdict/panel_scene.hpp"

namespace rbcstab {
namespace {

using test::panel;

SimulationOptions with(SimulationOptions o, TailMeans m, double rtol = 0) {
  o.tail_means = m;
  if (rtol > 0) {
    o.integrator.rtol = rtol;
    o.integrator.atol = 1e-16;
  }
  return o;
}

// The means of Delta_l (index l - 2) and sigma (last).
using Means = std::vector<double>;
Means means(const SimulationResult& r) {
  Means m = r.Delta_tail_mean;
  m.push_back(r.sigma_tail_mean);
  return m;
}

// The oracle: Simpson on 1280 intervals over [T - w, T] from an rtol 1e-12 run sampled there.
constexpr int kOracleIntervals = 1280;
Means oracle_means(Scene s, const SimulationOptions& options) {
  const double w = options.tail_window;
  s.dt = w / kOracleIntervals;
  SimulationOptions o = with(options, TailMeans::none, 1e-12);
  o.record_trajectory = true;
  const SimulationResult r = simulate(s, o);
  EXPECT_EQ(r.status, IntegrationStatus::success);
  const Trajectory& tr = r.trajectory;
  const std::size_t first = tr.t.size() - kOracleIntervals - 1;
  EXPECT_NEAR(tr.t[first], s.T - w, 1e-9);
  Means m(r.Delta_final.size() + 1, 0.0);
  for (int k = 0; k <= kOracleIntervals; ++k) {
    const double weight = (k == 0 || k == kOracleIntervals ? 1.0 : (k % 2 ? 4.0 : 2.0)) / (3.0 * kOracleIntervals);
    const std::size_t i = first + std::size_t(k);
    for (std::size_t j = 0; j < tr.Delta_l[i].size(); ++j) m[j] += weight * tr.Delta_l[i][j];
    m.back() += weight * tr.sigma[i];
  }
  return m;
}

// Largest difference: Delta_l on the scale Delta_total, sigma on max(1, |sigma|).
struct Difference {
  double Delta = 0, sigma = 0;
};
Difference difference(const Means& a, const Means& b, double Delta_total) {
  Difference d;
  for (std::size_t k = 0; k + 1 < a.size(); ++k) d.Delta = std::max(d.Delta, std::abs(a[k] - b[k]) / Delta_total);
  d.sigma = std::abs(a.back() - b.back()) / std::max(1.0, std::abs(b.back()));
  return d;
}

struct Case {
  std::string name;
  Scene scene;
  SimulationOptions options;
};

// The Fig. 3 scenes with their output grid (dt = 0.1) and without (as a diagram runs), and App. E points across
// each panel (oscillating and monotonic tails, l_Delta = 2 and 3).
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
    const DiagramSpec spec = diagram_spec(sf);
    SimulationOptions o = sf.options;
    o.record_trajectory = false;
    for (std::size_t idx : {0u, 1000u, 2080u, 2600u, 3100u, 4095u})
      v.push_back({std::string(name) + " point " + std::to_string(idx), point_scene(sf.scene, spec, idx), o});
  }
  return v;
}

TEST(TailMeans, QuadratureAgreesWithGridAndOracle) {
  for (const Case& c : cases()) {
    const SimulationResult g = simulate(c.scene, with(c.options, TailMeans::grid));
    const SimulationResult q = simulate(c.scene, with(c.options, TailMeans::quadrature));
    const SimulationResult q12 = simulate(c.scene, with(c.options, TailMeans::quadrature, 1e-12));
    ASSERT_EQ(q.status, IntegrationStatus::success) << c.name;
    const Means exact = oracle_means(c.scene, c.options);
    const double scale = q.Delta_total_initial;
    const Difference qg = difference(means(q), means(g), scale), q_oracle = difference(means(q), exact, scale),
                     g_oracle = difference(means(g), exact, scale), q12_oracle = difference(means(q12), exact, scale);
    std::printf("%-28s quadrature - grid %.2e %.2e, - oracle %.2e %.2e (grid %.2e %.2e, rtol 1e-12 %.2e %.2e)\n",
                c.name.c_str(), qg.Delta, qg.sigma, q_oracle.Delta, q_oracle.sigma, g_oracle.Delta, g_oracle.sigma,
                q12_oracle.Delta, q12_oracle.sigma);
    // Same rtol: the runs are bit-identical up to the window, then differ by the grid's Simpson error and the
    // quadrature run's integration error over the window (measured 3.8e-9, 2.7e-7 above).
    EXPECT_LE(qg.Delta, 1e-8) << c.name;
    EXPECT_LE(qg.sigma, 1e-6) << c.name;
    // At rtol 1e-12 the quadrature means are the oracle's up to the runs' integration error (sigma at App. E(b)
    // point 4095, which amplifies it ~1e3 times: 1.6e-9).
    EXPECT_LE(q12_oracle.Delta, 1e-11) << c.name;
    EXPECT_LE(q12_oracle.sigma, 1e-8) << c.name;
    // At rtol 1e-8 they are as accurate as the grid means, up to 1e-8 (Delta) and the grid's Simpson error in
    // sigma (up to 2.8e-7: it may cancel part of the integration error either way).
    EXPECT_LE(q_oracle.Delta, g_oracle.Delta + 1e-8) << c.name;
    EXPECT_LE(q_oracle.sigma, g_oracle.sigma + 1e-6) << c.name;
  }
}

// The quadratures do not feed back: with the Fig. 3 output grid (dt = 0.1, every step in the window ends on it in
// both runs, the first one starting at T - 10) the run is bit-identical to one without tail means, since an RK
// step's base components do not depend on the quadrature components and their error never set the step there.
// Without the output grid the quadrature run stops once more, at T - 10, so the state at T differs by the
// integration error (measured 9.3e-10, App. E(b) point 4095): within 1e-8 (max(1, |y|)). oscillating is judged on
// the accepted steps in the window in both; the split costs at most one step (measured 0 or 1).
TEST(TailMeans, StateIsThatOfThePlainRun) {
  for (const Case& c : cases()) {
    const SimulationResult q = simulate(c.scene, with(c.options, TailMeans::quadrature));
    const SimulationResult n = simulate(c.scene, with(c.options, TailMeans::none));
    ASSERT_EQ(q.y_final.size(), n.y_final.size()) << c.name;
    EXPECT_EQ(q.oscillating, n.oscillating) << c.name;
    EXPECT_LE(q.counters.steps, n.counters.steps + 1) << c.name;
    EXPECT_NE(means(q), means(n)) << c.name;  // the means are not the values at T
    if (c.options.record_trajectory) {
      EXPECT_EQ(q.y_final, n.y_final) << c.name;
      EXPECT_EQ(q.Delta_final, n.Delta_final) << c.name;
      EXPECT_EQ(q.sigma_final, n.sigma_final) << c.name;
      EXPECT_EQ(q.r_final, n.r_final) << c.name;
      EXPECT_EQ(q.Psi_final, n.Psi_final) << c.name;
      EXPECT_EQ(q.trajectory.t, n.trajectory.t) << c.name;
      EXPECT_EQ(q.trajectory.Delta_l, n.trajectory.Delta_l) << c.name;
      EXPECT_EQ(q.trajectory.sigma, n.trajectory.sigma) << c.name;
      EXPECT_EQ(q.trajectory.Psi, n.trajectory.Psi) << c.name;
    } else {
      for (std::size_t k = 0; k < q.y_final.size(); ++k)
        EXPECT_NEAR(q.y_final[k], n.y_final[k], 1e-8 * std::max(1.0, std::abs(n.y_final[k]))) << c.name << " " << k;
      EXPECT_NEAR(q.sigma_final, n.sigma_final, 1e-8 * std::max(1.0, std::abs(n.sigma_final))) << c.name;
    }
  }
}

// After certified early termination the run resumes before the window (resumed_at <= T - 10) and integrates the
// quadratures over it: its means agree with the full-horizon grid run's to CertifiedRun's 1e-6 (Delta_total,
// max(1, |sigma|)) and l_Delta is the same.
TEST(TailMeans, EarlyTerminationGetsQuadratureMeans) {
  int terminated = 0;
  for (const Case& c : cases()) {
    if (c.options.record_trajectory) continue;
    const SimulationResult full = simulate(c.scene, with(c.options, TailMeans::grid));
    const SimulationResult early = simulate_certified(c.scene, with(c.options, TailMeans::quadrature));
    ASSERT_EQ(early.status, IntegrationStatus::success) << c.name;
    if (!early.early.terminated) continue;
    ++terminated;
    EXPECT_LE(early.early.resumed_at, c.scene.T - c.options.tail_window) << c.name;
    const Difference d = difference(means(early), means(full), full.Delta_total_initial);
    EXPECT_LE(d.Delta, 1e-6) << c.name;
    EXPECT_LE(d.sigma, 1e-6) << c.name;
    EXPECT_EQ(early.l_Delta, full.l_Delta) << c.name;
    EXPECT_NE(means(early), [&] {
      Means m = early.Delta_final;
      m.push_back(early.sigma_final);
      return m;
    }()) << c.name;
  }
  EXPECT_GE(terminated, 6);
}

TEST(TailMeans, Validation) {
  SimulationOptions o;
  o.tail_means = TailMeans::quadrature;
  o.integrator.stepper = Stepper::rosenbrock;
  try {
    o.validate();
    ADD_FAILURE() << "rosenbrock with quadrature means accepted";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.parameter(), "tail_means");
    EXPECT_NE(std::string(e.what()).find("rosenbrock"), std::string::npos) << e.what();
  }
  o.tail_means = static_cast<TailMeans>(7);
  o.integrator.stepper = Stepper::rk8pd;
  EXPECT_THROW(o.validate(), InvalidArgument);
  for (TailMeans m : {TailMeans::grid, TailMeans::quadrature, TailMeans::none}) {
    o.tail_means = m;
    EXPECT_NO_THROW(o.validate()) << to_string(m);
  }
}

}  // namespace
}  // namespace rbcstab
