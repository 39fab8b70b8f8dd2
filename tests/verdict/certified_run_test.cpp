// Certified early termination (verdict/certified_run.hpp). Oracle: the full-horizon run of the same scene
// (simulate without a certifier), point by point over 16 x 16 grids of the paper's panels; near-threshold and
// non-attracting scenes that must not stop early; the certificate in every output.
//
// Tolerances. Verdicts, l_Delta and the oscillation flag must be equal. Delta_l(T), the tail means, sigma(T) and
// its tail mean differ by the full run's own integration error: at rtol 1e-8 it reaches 4.3e-8 (Delta) and 7e-5
// (sigma, App. E(c)) against rtol 1e-12 references, while the early runs, integrated over the last periods only,
// stay closer to the references (measured 4.5e-9 and 2.8e-6 there). So each value must agree to 1e-6 (Delta_total,
// max(1, |sigma|)); where it does not, an rtol 1e-12 reference of that point must find the early value at least as
// accurate as the full one (to 1e-8), and no difference may exceed 1e-4. A decayed mode's Delta_l(T) (ln Delta_l
// advanced over the skipped periods to first order) matched to 1.3e-5 in ln Delta_l: 1e-4.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numbers>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "model/test_scenes.hpp"
#include "rbcstab/analysis/post_instability.hpp"
#include "rbcstab/analysis/steady_states.hpp"
#include "rbcstab/analysis/thresholds.hpp"
#include "rbcstab/analysis/truncation.hpp"
#include "rbcstab/core/constants.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/io/json.hpp"
#include "rbcstab/io/scene_file.hpp"
#include "rbcstab/io/simulation_io.hpp"
#include "rbcstab/model/coefficients.hpp"
#include "rbcstab/sweep/diagram.hpp"
#include "rbcstab/sweep/diagram_document.hpp"
#include "rbcstab/sweep/diagram_table.hpp"
#include "rbcstab/sweep/point_record.hpp"
#include "rbcstab/verdict/certified_run.hpp"
#include "rbcstab/verdict/verdict_io.hpp"
#include "verdict/panel_scene.hpp"

namespace rbcstab {
namespace {

using test::panel;

// The diagram classifier's l: argmax_l [X_l - Delta_l(0)] with X per the panel's rule.
int classified_mode(const SimulationResult& r, Classifier c) {
  const bool tail = c == Classifier::tail_mean || (c == Classifier::automatic && r.oscillating);
  const std::vector<double>& X = tail ? r.Delta_tail_mean : r.Delta_final;
  std::size_t best = 0;
  for (std::size_t k = 1; k < X.size(); ++k)
    if (X[k] - r.Delta_initial[k] > X[best] - r.Delta_initial[best]) best = k;
  return int(best) + 2;
}

// What every certificate must say (EarlyTerminationOptions defaults, the run's rtol 1e-8).
void expect_certificate(const SimulationResult& r, const SimulationOptions& o, const std::string& where) {
  const EarlyTermination& e = r.early;
  EXPECT_EQ(e.kind, "periodic_orbit") << where;
  EXPECT_EQ(e.period, kTwoPi) << where;
  EXPECT_GE(e.margin - e.margin_error, 1 - std::exp(-kTwoPi * 1e-3)) << where;
  EXPECT_GE(e.rate, 1e-3) << where;
  EXPECT_LE(e.distance, 1e-3) << where;
  EXPECT_LE(e.residual, 1e-9) << where;
  EXPECT_LE(e.decay_bound, o.integrator.rtol / 10) << where;
  EXPECT_LE(e.resumed_at, r.T - o.tail_window) << where;
  const double periods = (e.resumed_at - e.terminated_at) / kTwoPi;
  EXPECT_NEAR(periods, std::round(periods), 1e-9) << where;
  EXPECT_GE(periods, 1) << where;
  EXPECT_GE(e.attempts, 1) << where;
  EXPECT_GT(e.work.rhs_evaluations, 0u) << where;
}

// The values a run reports at T, each with its scale: Delta_l(T) and the tail means (Delta_total), sigma(T) and
// its tail mean (max(1, |sigma|)), r(T) (1).
std::vector<std::pair<double, double>> reported(const SimulationResult& r) {
  std::vector<std::pair<double, double>> v;
  for (std::size_t k = 0; k < r.Delta_final.size(); ++k) {
    v.emplace_back(r.Delta_final[k], r.Delta_total_initial);
    v.emplace_back(r.Delta_tail_mean[k], r.Delta_total_initial);
  }
  v.emplace_back(r.sigma_final, std::max(1.0, std::abs(r.sigma_final)));
  v.emplace_back(r.sigma_tail_mean, std::max(1.0, std::abs(r.sigma_tail_mean)));
  v.emplace_back(r.r_final, 1.0);
  return v;
}

void expect_values_agree(const Scene& s, const SimulationOptions& o, const SimulationResult& early,
                         const SimulationResult& full, const std::string& where) {
  const auto a = reported(early), b = reported(full);
  bool close = true;
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_NEAR(a[k].first, b[k].first, 1e-4 * b[k].second) << where << " value " << k;
    close = close && std::abs(a[k].first - b[k].first) <= 1e-6 * b[k].second;
  }
  if (close) return;
  SimulationOptions tight = o;
  tight.integrator.rtol = 1e-12;
  tight.integrator.atol = 1e-15;
  const auto ref = reported(simulate(s, tight));
  for (std::size_t k = 0; k < a.size(); ++k)
    EXPECT_LE(std::abs(a[k].first - ref[k].first), std::abs(b[k].first - ref[k].first) + 1e-8 * b[k].second)
        << where << " value " << k << ": early " << a[k].first << ", full " << b[k].first << ", reference "
        << ref[k].first;
}

// Every point of a 16 x 16 grid of the panel, early against full horizon. Also counts the points stopped early
// (at least min_terminated: measured 134 for Fig. 4(b) and App. E(b), >= 252 for the others).
void compare_panel(const std::string& name, int min_terminated) {
  const SceneFile sf = panel(name);
  DiagramSpec spec = diagram_spec(sf);
  spec.x.count = spec.y.count = 16;
  SimulationOptions o = sf.options;
  o.record_trajectory = false;
  int terminated = 0;
  for (std::size_t idx = 0; idx < spec.size(); ++idx) {
    const Scene s = point_scene(sf.scene, spec, idx);
    const std::string where = name + " point " + std::to_string(idx);
    const SimulationResult full = simulate(s, o);
    const SimulationResult early = simulate_certified(s, o);
    ASSERT_EQ(full.status, IntegrationStatus::success) << where;
    ASSERT_EQ(early.status, IntegrationStatus::success) << where;
    EXPECT_EQ(classified_mode(early, spec.classifier), classified_mode(full, spec.classifier)) << where;
    EXPECT_EQ(early.l_Delta, full.l_Delta) << where;
    EXPECT_EQ(early.l_Delta_final, full.l_Delta_final) << where;
    EXPECT_EQ(early.oscillating, full.oscillating) << where;
    for (std::size_t k = 0; k < full.Delta_final.size(); ++k)
      if (full.Delta_final[k] > 1e-290 && early.Delta_final[k] > 1e-290) {
        EXPECT_NEAR(std::log(early.Delta_final[k]), std::log(full.Delta_final[k]), 1e-4) << where << " l = " << k + 2;
      }
    expect_values_agree(s, o, early, full, where);
    if (early.early.terminated) {
      ++terminated;
      expect_certificate(early, o, where);
      EXPECT_LT(early.counters.steps, full.counters.steps) << where;
    } else {
      // No certificate: the same integration as the full run, bit for bit, and a note saying why.
      EXPECT_EQ(early.Delta_final, full.Delta_final) << where;
      EXPECT_EQ(early.counters.steps, full.counters.steps) << where;
      EXPECT_FALSE(early.early.note.empty()) << where;
    }
  }
  EXPECT_GE(terminated, min_terminated) << name;
}

TEST(CertifiedRun, Fig4aPanelEqualsFullHorizon) { compare_panel("fig4a_op", 200); }
TEST(CertifiedRun, Fig4bPanelEqualsFullHorizon) { compare_panel("fig4b_op", 100); }
TEST(CertifiedRun, Fig4cPanelEqualsFullHorizon) { compare_panel("fig4c_op", 200); }
TEST(CertifiedRun, AppEaPanelEqualsFullHorizon) { compare_panel("appE_a_ip", 200); }
TEST(CertifiedRun, AppEbPanelEqualsFullHorizon) { compare_panel("appE_b_ip", 100); }
TEST(CertifiedRun, AppEcPanelEqualsFullHorizon) { compare_panel("appE_c_ip", 200); }

// The diagram's savings together (certified early termination, and no tail-window samples under the final
// classifier, which reads Delta_l(T) only, or tail means by quadrature under the tail classifier), point by point
// against the full-horizon panel (every run to T, tail sampled) on 16 x 16 grids of the Fig. 4 and App. E(b) panels:
// verdict and l_Delta equal; the growth and sigma(T) within 1e-5 (Delta_total, max(1, |sigma|): the hard bound of
// compare_panel is 1e-4, its typical 1e-6; the values are printed). The oscillation flag is then judged on the accepted
// steps (~0.5 apart) instead of the 161-point grid: it may miss an oscillation shorter than a step (8 of 4096 points on
// the 64 x 64 Fig. 4(b) panel): at most 2 %. The tail classifier does not read the flag; on App. E(b) it differs more
// often (61 of 4096 points on 64 x 64, 9 of 256 on 16 x 16): at most 5 % there.
void compare_diagram(const std::string& name, Classifier classifier = Classifier::final,
                     double max_oscillation = 0.02) {
  const SceneFile sf = panel(name);
  DiagramSpec spec = diagram_spec(sf);
  ASSERT_EQ(spec.classifier, classifier);
  spec.x.count = spec.y.count = 16;
  DiagramOptions ro;
  ro.threads = 2;
  SimulationOptions full_options = sf.options;
  full_options.full_horizon = true;
  const DiagramRun full = run_diagram(sf.scene, full_options, spec, ro);
  const DiagramRun fast = run_diagram(sf.scene, sf.options, spec, ro);
  ASSERT_EQ(full.points.size(), fast.points.size());
  double growth = 0, sigma = 0;
  std::size_t oscillation = 0, work_full = 0, work_fast = 0;
  for (std::size_t k = 0; k < full.points.size(); ++k) {
    const PointResult &a = fast.points[k], &b = full.points[k];
    EXPECT_EQ(a.verdict, b.verdict) << name << " point " << k;
    EXPECT_EQ(a.l_Delta, b.l_Delta) << name << " point " << k;
    growth = std::max(growth, std::abs(a.growth - b.growth));
    sigma = std::max(sigma, std::abs(a.sigma_final - b.sigma_final) / std::max(1.0, std::abs(b.sigma_final)));
    oscillation += a.oscillating != b.oscillating;
    work_fast += a.rhs_evaluations;
    work_full += b.rhs_evaluations;
  }
  std::printf(
      "%s: max |growth difference| %.3g, max sigma(T) difference %.3g, oscillation flags differing %zu, "
      "RHS evaluations %zu -> %zu\n",
      name.c_str(), growth, sigma, oscillation, work_full, work_fast);
  EXPECT_LE(growth, 1e-5 * sf.scene.parameters.Delta) << name;
  EXPECT_LE(sigma, 1e-5) << name;
  EXPECT_LE(double(oscillation), max_oscillation * double(spec.size())) << name;
  EXPECT_LT(work_fast, work_full) << name;
}

TEST(CertifiedRun, Fig4aDiagramEqualsFullHorizon) { compare_diagram("fig4a_op"); }
TEST(CertifiedRun, Fig4bDiagramEqualsFullHorizon) { compare_diagram("fig4b_op"); }
TEST(CertifiedRun, Fig4cDiagramEqualsFullHorizon) { compare_diagram("fig4c_op"); }
TEST(CertifiedRun, AppEbDiagramEqualsFullHorizon) { compare_diagram("appE_b_ip", Classifier::tail_mean, 0.05); }

// The Fig. 4(b) out-of-plane scene (beta = 0: the ellipsoid is an equilibrium) at ln B = lnB and the ln C where
// the slowest mode l >= 3 grows at exactly `rate` at the exact equilibrium, found by bisection on
// max_l Upsilon_l(sigma_R^eq) (continuous in C; sigma_R^eq from analysis/steady_states).
Scene at_growth_rate(double lnB, double rate, double delta) {
  Scene s = panel("fig4b_op").scene;
  s.beta = 0;
  s.delta = delta;
  s.T = 500;
  s.dt = 500;
  s.parameters.B = std::exp(lnB);
  auto top = [&](double lnC) {
    Parameters p = s.parameters;
    p.C = std::exp(lnC);
    const double sigma = out_of_plane_equilibrium(p).sigma_R;
    double best = -INFINITY;
    for (int l = 3; l <= s.L; ++l) best = std::max(best, Upsilon_l(p, l, sigma));
    return best - rate;
  };
  double lo = -5.5, hi = 2.0;
  EXPECT_LT(top(lo) * top(hi), 0);  // a crossing in the panel
  for (int it = 0; it < 200 && hi - lo > 1e-14; ++it) {
    const double mid = 0.5 * (lo + hi);
    (top(mid) * top(lo) > 0 ? lo : hi) = mid;
  }
  s.parameters.C = std::exp(0.5 * (lo + hi));
  return s;
}

// |Upsilon_l| = 1e-4 (slow decay and slow growth), with the paper's perturbation delta = 1e-3 (the slow mode
// keeps its amplitude: no refinement converges near it) and with delta = 1e-14 (the slow mode is among the
// decayed ones: its multiplier exp(+-2 pi 1e-4) fails the margin, min_rate 1e-3): no certificate, and the run is
// the full-horizon run bit for bit. A clearly decaying mode (-3e-2) in the same plane does stop early, with the
// same settings.
TEST(CertifiedRun, NearThresholdSceneIsNotTerminatedEarly) {
  SimulationOptions o;
  o.record_trajectory = false;
  for (double delta : {1e-3, 1e-14})
    for (double rate : {-1e-4, 1e-4}) {
      const std::string what = "rate " + std::to_string(rate) + ", delta " + std::to_string(delta);
      const Scene s = at_growth_rate(0.0, rate, delta);
      const SimulationResult full = simulate(s, o);
      const SimulationResult early = simulate_certified(s, o);
      EXPECT_FALSE(early.early.terminated) << what;
      EXPECT_GE(early.early.attempts, 1) << what;
      EXPECT_FALSE(early.early.note.empty()) << what;
      if (delta < 1e-10) {
        EXPECT_NE(early.early.note.find("not attracting"), std::string::npos) << what << ": " << early.early.note;
      }
      EXPECT_EQ(early.Delta_final, full.Delta_final) << what;
      EXPECT_EQ(early.l_Delta, full.l_Delta) << what;
    }
  const Scene clear = at_growth_rate(0.0, -3e-2, 1e-3);
  const SimulationResult full = simulate(clear, o);
  const SimulationResult early = simulate_certified(clear, o);
  ASSERT_TRUE(early.early.terminated) << early.early.note;
  EXPECT_EQ(early.early.kind, "equilibrium");  // beta = 0: the forcing is constant in the co-rotating frame
  EXPECT_LE(early.early.rate, 3.1e-2);         // the slowest direction is the slow mode
  EXPECT_EQ(early.l_Delta, full.l_Delta);
  expect_values_agree(clear, o, early, full, "clearly decaying");
}

// A growing mode too small ever to leave the linearisation radius (delta = 1e-14, Upsilon_l = +1e-2: its
// amplitude stays below 1e-4 until T): the ellipsoidal state is periodic to every tolerance but not attracting.
// No certificate; the run is the full run bit for bit, and that run sees the growth (l_Delta = the mode).
TEST(CertifiedRun, NonAttractingOrbitIsNotTerminatedEarly) {
  SimulationOptions o;
  o.record_trajectory = false;
  const Scene s = at_growth_rate(2.0, 1e-2, 1e-14);
  const SimulationResult full = simulate(s, o);
  const SimulationResult early = simulate_certified(s, o);
  EXPECT_FALSE(early.early.terminated);
  EXPECT_NE(early.early.note.find("not attracting"), std::string::npos) << early.early.note;
  EXPECT_EQ(early.Delta_final, full.Delta_final);
  EXPECT_GE(full.l_Delta, 3);
  EXPECT_EQ(early.l_Delta, full.l_Delta);
}

// The margins in the simulate and summary JSON; full_horizon turns the termination off and says so.
TEST(CertifiedRun, CertificateIsReportedInTheJson) {
  const Scene s;  // the default scene (Fig. 3, out of plane)
  const SimulationResult r = simulate_certified(s);
  ASSERT_TRUE(r.early.terminated) << r.early.note;
  expect_certificate(r, {}, "default scene");
  const nlohmann::json j = to_json(r);
  EXPECT_EQ(j.at("terminated_at").get<double>(), r.early.terminated_at);
  const nlohmann::json& e = j.at("early_termination");
  for (const char* key : {"terminated_at", "resumed_at", "kind", "period", "margin", "margin_error", "rate", "residual",
                          "distance", "decay_bound", "attempts", "rhs_evaluations"})
    EXPECT_TRUE(e.contains(key)) << key;
  EXPECT_EQ(e.at("margin").get<double>(), r.early.margin);
  EXPECT_TRUE(unexplained_nulls(j).empty());

  SimulationOptions full;
  full.full_horizon = true;
  const SimulationResult f = simulate_certified(s, full);
  EXPECT_FALSE(f.early.terminated);
  EXPECT_EQ(f.early.attempts, 0);
  const nlohmann::json jf = to_json(f);
  EXPECT_TRUE(jf.at("terminated_at").is_null());
  EXPECT_EQ(jf.at("terminated_at_reason"), "full horizon requested");
  EXPECT_TRUE(unexplained_nulls(jf).empty());

  SceneFile sf;
  const SummaryRun sum = run_summary(sf);
  const nlohmann::json js = summary_json(sum.file, sum.run, sum.prediction);
  EXPECT_TRUE(js.at("terminated_at").is_number());
  EXPECT_TRUE(js.at("early_termination").contains("margin"));
  EXPECT_NE(summary_text(sum.file, sum.run, sum.prediction).find("Early stop: at t = "), std::string::npos);
}

// run.full_horizon is a scene key (TOML true/false, round trip through to_toml) that the diagram honours; the
// diagram's points carry terminated_at and margin through the JSON and the journal records.
TEST(CertifiedRun, FullHorizonSceneKeyAndDiagramPoints) {
  const SceneFile on = parse_scene("[run]\nfull_horizon = true\n");
  EXPECT_TRUE(on.options.full_horizon);
  EXPECT_TRUE(parse_scene(to_toml(on)).options.full_horizon);
  EXPECT_FALSE(parse_scene(to_toml(SceneFile{})).options.full_horizon);
  EXPECT_THROW(parse_scene("[run]\nfull_horizon = 1\n"), InvalidArgument);

  const SceneFile sf = panel("fig4a_op");
  DiagramSpec spec = diagram_spec(sf);
  spec.x.count = spec.y.count = 3;
  const DiagramRun early = run_diagram(sf.scene, sf.options, spec, {});
  SimulationOptions full_options = sf.options;
  full_options.full_horizon = true;
  const DiagramRun full = run_diagram(sf.scene, full_options, spec, {});
  EXPECT_NE(config_hash(sf.scene, sf.options, spec), config_hash(sf.scene, full_options, spec));
  ASSERT_EQ(early.points.size(), full.points.size());
  int terminated = 0;
  const std::string hash = config_hash(sf.scene, sf.options, spec);
  for (std::size_t k = 0; k < early.points.size(); ++k) {
    const PointResult& a = early.points[k];
    const PointResult& b = full.points[k];
    EXPECT_EQ(a.verdict, b.verdict) << k;
    EXPECT_EQ(a.l_Delta, b.l_Delta) << k;
    EXPECT_TRUE(std::isnan(b.terminated_at) && std::isnan(b.margin)) << k;
    if (std::isfinite(a.terminated_at)) {
      ++terminated;
      EXPECT_GT(a.margin, 0) << k;
    }
    const std::optional<PointResult> back = point_from_line(point_to_line(a, hash), hash, spec);
    ASSERT_TRUE(back) << k;
    EXPECT_EQ(std::isnan(back->terminated_at), std::isnan(a.terminated_at)) << k;
    if (std::isfinite(a.terminated_at)) {
      EXPECT_EQ(back->terminated_at, a.terminated_at) << k;
    }
  }
  EXPECT_GT(terminated, 0);
  const nlohmann::json doc = diagram_json(diagram_header(sf.scene, sf.options, spec), spec, early.points, {}, {false});
  EXPECT_EQ(doc.at("summary").at("terminated_early").get<int>(), terminated);
  const std::vector<PointResult> read = points_from_json(doc, spec);
  for (std::size_t k = 0; k < read.size(); ++k)
    if (std::isfinite(early.points[k].margin)) {
      EXPECT_EQ(read[k].margin, early.points[k].margin) << k;
    }
}

// A recorded trajectory describes every row of the grid: integrated up to terminated_at and from resumed_at on,
// skipped in between, where only the span is stored (Trajectory::skipped) and the CSV shows empty fields and
// integrated = 0 (so that no plot joins across the skip).
TEST(CertifiedRun, TrajectoryMasksTheSkippedSpan) {
  Scene s;
  s.dt = 0.5;
  const SimulationResult r = simulate_certified(s);
  ASSERT_TRUE(r.early.terminated);
  const std::vector<double> grid = sampling_grid(s.T, s.dt);
  const Trajectory& tr = r.trajectory;
  ASSERT_EQ(tr.rows(), grid.size());
  std::size_t skipped = 0;
  for (std::size_t k = 0; k < grid.size(); ++k) {
    const bool integrated = grid[k] <= r.early.terminated_at || grid[k] >= r.early.resumed_at;
    EXPECT_EQ(tr.integrated(k), integrated) << grid[k];
    EXPECT_EQ(tr.time(k), grid[k]) << k;  // bit for bit, skipped rows included
    if (integrated) {
      EXPECT_EQ(tr.t[tr.sample(k)], grid[k]) << k;
    }
    skipped += integrated ? 0 : 1;
  }
  EXPECT_GT(skipped, 0u);
  EXPECT_EQ(tr.skipped.count, skipped);
  EXPECT_EQ(tr.t.size(), grid.size() - skipped);  // the skipped rows take no memory
  EXPECT_EQ(tr.integrated_count(), grid.size() - skipped);
  for (const auto& D : tr.Delta_l)
    for (double d : D) EXPECT_TRUE(std::isfinite(d));
  EXPECT_EQ(tr.Delta_l.back(), r.Delta_final);
  const nlohmann::json j = to_json(r);
  EXPECT_EQ(j["samples"], grid.size());
  EXPECT_EQ(j["samples_integrated"], grid.size() - skipped);
  // The CSV: one line per row of the grid; a skipped row is its time, empty fields and integrated = 0.
  const std::string csv = trajectory_csv(r);
  std::istringstream lines(csv);
  std::string line;
  std::getline(lines, line);
  EXPECT_EQ(line, "t,Delta_2,Delta_3,Delta_4,Delta_5,Delta_6,Delta_7,Delta_8,Delta_9,Delta_10,sigma,r,Psi,integrated");
  std::size_t row = 0, empty_rows = 0;
  for (; std::getline(lines, line); ++row) {
    ASSERT_LT(row, grid.size());
    EXPECT_EQ(std::count(line.begin(), line.end(), ','), 13) << line;
    EXPECT_EQ(std::stod(line), grid[row]) << line;
    const bool blank = line.ends_with(",,,,,,,,,,,,,0");
    EXPECT_EQ(blank, !tr.integrated(row)) << line;
    EXPECT_EQ(line.back(), tr.integrated(row) ? '1' : '0') << line;
    empty_rows += blank ? 1 : 0;
  }
  EXPECT_EQ(row, grid.size());
  EXPECT_EQ(empty_rows, skipped);
}

// The same on a t_eval grid: the skipped times are the caller's (stored), the others integrated there.
TEST(CertifiedRun, TrajectoryMasksTheSkippedSpanOfTEval) {
  Scene s;
  SimulationOptions o;
  for (double t = 0; t <= s.T; t += 0.75) o.t_eval.push_back(t);
  const SimulationResult r = simulate_certified(s, o);
  ASSERT_TRUE(r.early.terminated);
  const Trajectory& tr = r.trajectory;
  ASSERT_EQ(tr.rows(), o.t_eval.size());
  EXPECT_GT(tr.skipped.count, 0u);
  for (std::size_t k = 0; k < o.t_eval.size(); ++k) {
    EXPECT_EQ(tr.time(k), o.t_eval[k]) << k;
    EXPECT_EQ(tr.integrated(k), o.t_eval[k] <= r.early.terminated_at || o.t_eval[k] >= r.early.resumed_at) << k;
  }
}

// The automatic L's reduced transient with the certified early stop, against the one integrated to T (the oracle):
// every checkpoint's int_0^t sigma_R agrees to within the skip's error, the decision and the run are the same, and
// its work no longer grows with T.
// Measured 1.3e-9 (relative, worst checkpoint) at the predictor's rtol 1e-10: the full run's own global error over
// T = 2000 is of that size, and the skip's is first order in a distance the certificate keeps below sqrt(rtol / 10).
// An error of one forcing period's integral would be ~0.1 at the first skipped checkpoint (checked below).
constexpr double kTransientTolerance = 1e-8;
TEST(CertifiedRun, TransientStopsEarlyAndAgreesWithTheFullHorizon) {
  Scene s;  // the default scene (Fig. 3's material, in plane): its reduced run settles on an attracting orbit
  s.T = 2000;
  const TruncationOptions o;
  const ReducedTransient full = truncation_transient(s, o);
  const ReducedTransient early = certified_transient(validated(s), o);
  ASSERT_EQ(early.status, IntegrationStatus::success) << early.reason;
  ASSERT_EQ(early.t, full.t);
  EXPECT_EQ(early.t_end, full.t_end);
  auto worst = [&](const std::vector<double>& integral) {
    double w = 0;
    for (std::size_t k = 0; k < full.t.size(); ++k)
      w = std::max(w, std::abs(integral[k] - full.integral[k]) / std::abs(full.integral[k]));
    return w;
  };
  EXPECT_LT(worst(early.integral), kTransientTolerance);
  // A wrong count of skipped periods fails it: one period's integral too many at the last checkpoint.
  std::vector<double> slipped = early.integral;
  slipped.back() += 2 * kPi * full.integral.back() / full.t.back();
  EXPECT_GT(worst(slipped), 1e4 * kTransientTolerance);
  EXPECT_EQ(early.integral_end, early.integral.back());
  EXPECT_LT(5 * early.counters.rhs_evaluations, full.counters.rhs_evaluations);  // it did stop early

  // The decision and everything reported, with the full transient given instead.
  SceneFile a, b;
  a.scene = b.scene = s;
  const SimulationResult ra = simulate_scene(a, a.options), rb = simulate_scene(b, b.options, &full);
  EXPECT_EQ(a.scene.L, b.scene.L);
  EXPECT_EQ(a.L_reason, b.L_reason);
  nlohmann::json ja = simulation_json(a, ra), jb = simulation_json(b, rb);
  ja.erase("seconds");
  jb.erase("seconds");
  EXPECT_EQ(ja, jb);

  // Its work: about the same at T = 1e5 as at T = 2000 (integrated to T it grows 50 times).
  Scene far = s;
  far.T = 1e5;
  const ReducedTransient longer = certified_transient(validated(far), o);
  ASSERT_EQ(longer.status, IntegrationStatus::success);
  EXPECT_LT(longer.counters.rhs_evaluations, 2 * early.counters.rhs_evaluations);
}

// The first number of `a` that differs from `b`'s by more than rel max(1, |b|), or another value that differs
// (strings, structure), as "path: a vs b"; "" if none. Keys in `skip` (cost, the early stop's own report) are
// not compared.
std::string json_difference(const nlohmann::json& a, const nlohmann::json& b, double rel,
                            const std::vector<std::string>& skip, const std::string& path = "") {
  if (a.is_number() && b.is_number()) {
    const double x = a.get<double>(), y = b.get<double>();
    return std::abs(x - y) <= rel * std::max(1.0, std::abs(y)) ? "" : path + ": " + a.dump() + " vs " + b.dump();
  }
  if (a.is_object() && b.is_object()) {
    for (const auto& [key, value] : b.items()) {
      if (std::find(skip.begin(), skip.end(), key) != skip.end()) continue;
      if (!a.contains(key)) return path + "/" + key + ": missing";
      if (std::string d = json_difference(a[key], value, rel, skip, path + "/" + key); !d.empty()) return d;
    }
    return "";
  }
  if (a.is_array() && b.is_array() && a.size() == b.size()) {
    for (std::size_t k = 0; k < a.size(); ++k)
      if (std::string d = json_difference(a[k], b[k], rel, skip, path + "/" + std::to_string(k)); !d.empty()) return d;
    return "";
  }
  return a == b ? "" : path + ": " + a.dump() + " vs " + b.dump();
}

TEST(CertifiedRun, JsonDifferenceFindsWhatDiffers) {
  const nlohmann::json a = {{"x", 1.0}, {"s", "a"}, {"v", {1.0, 2.0}}, {"seconds", 1.0}};
  nlohmann::json b = a;
  EXPECT_EQ(json_difference(a, b, 1e-9, {}), "");
  b["v"][1] = 2.0 + 1e-6;
  EXPECT_EQ(json_difference(a, b, 1e-9, {}), "/v/1: 2.0 vs 2.000001");
  EXPECT_EQ(json_difference(a, b, 1e-6, {}), "");
  b["s"] = "b";
  EXPECT_NE(json_difference(a, b, 1e-6, {}), "");
  b = a;
  b["seconds"] = 2.0;
  EXPECT_EQ(json_difference(a, b, 1e-9, {"seconds"}), "");
}

// summary, post, report and shape stop integrating where the output needs only the attractor: the automatic L
// (apply_scene_truncation, run_summary, run_post) from the certified transient and a certified candidate run, the
// summary's finite-horizon predictor from the certified transient, post's run certified. The oracle: the same
// computation from the transient integrated to T and plain (full-horizon) runs, as before. Everything reported
// (but the cost and the early stop's own report) agrees to the run's rtol (relative, or absolute below 1): measured
// 1.2e-9 in the summary (a finite-horizon rate), 1e-16 in post (its attractor is an equilibrium), and the same L and
// L_reason. A transient one forcing period's integral off (2 pi / T = 3e-3 of <sigma_R>_T) fails that comparison.
TEST(CertifiedRun, SummaryPostAndLDecisionAgreeWithTheFullHorizon) {
  SceneFile file;
  file.scene.T = 2000;
  const double rtol = file.options.integrator.rtol;  // 1e-8
  const std::vector<std::string> cost = {"seconds",
                                         "rhs_evaluations",
                                         "steps",
                                         "failed_steps",
                                         "jacobian_evaluations",
                                         "terminated_at",
                                         "terminated_at_reason",
                                         "early_termination",
                                         "samples",
                                         "samples_integrated",
                                         "counters"};

  // The L decision of report and shape.
  SceneFile certified = file, plain = file;
  apply_scene_truncation(certified, TruncationUse::simulation);
  apply_truncation(plain, TruncationUse::simulation);
  EXPECT_EQ(certified.scene.L, plain.scene.L);
  EXPECT_EQ(certified.L_reason, plain.L_reason);
  EXPECT_TRUE(certified.truncation_check.has_value());  // a candidate was run and checked

  // summary: its prediction from the certified transient against the one integrated to T, on the same run.
  const SummaryRun s = run_summary(file);
  EXPECT_EQ(s.file.scene.L, plain.scene.L);
  const ValidScene valid = validated(s.file);
  const ReducedTransient full = truncation_transient(valid);
  const nlohmann::json early = summary_json(s.file, s.run, s.prediction);
  const nlohmann::json oracle = summary_json(s.file, s.run, predict(valid, full, &s.run));
  EXPECT_EQ(json_difference(early, oracle, rtol, cost), "");
  ReducedTransient slipped = full;  // one forcing period's integral too many
  slipped.integral_end += 2 * kPi * full.integral_end / full.T;
  slipped.integral.back() = slipped.integral_end;
  EXPECT_NE(json_difference(summary_json(s.file, s.run, predict(valid, slipped, &s.run)), oracle, rtol, cost), "");

  // post: its certified run against the plain run at the plainly decided L (run_post before).
  const PostRun p = run_post(file);
  SimulationOptions o = plain.options;
  o.record_trajectory = false;
  SceneFile q = file;
  const SimulationResult full_run = simulate_truncated(q, o);
  ASSERT_EQ(p.file.scene.L, q.scene.L);
  EXPECT_TRUE(p.run.early.terminated);
  const nlohmann::json post_early = post_json(p.file, p.post, p.run);
  const nlohmann::json post_oracle = post_json(q, post_instability(q.scene.parameters, q.scene.L, 0.0), full_run);
  EXPECT_EQ(json_difference(post_early, post_oracle, rtol, cost), "");
}

// The reduced level (in plane, no perturbation) and the modal level at L = 2 (out of plane: m = 1 content)
// stop early and match; the full level (stress-free l >= 3 content) never does and says why.
TEST(CertifiedRun, EveryLevel) {
  SimulationOptions o;
  o.record_trajectory = false;
  Scene reduced;
  reduced.beta = std::numbers::pi / 2;
  reduced.L = 2;
  reduced.delta = 0;
  Scene modal2;
  modal2.L = 2;
  for (const Scene& s : {reduced, modal2}) {
    const SimulationResult full = simulate(s, o);
    const SimulationResult early = simulate_certified(s, o);
    const std::string level = to_string(early.level.level);
    EXPECT_TRUE(early.early.terminated) << level << ": " << early.early.note;
    EXPECT_EQ(early.l_Delta, full.l_Delta) << level;
    EXPECT_NEAR(early.sigma_final, full.sigma_final, 1e-6 * std::max(1.0, std::abs(full.sigma_final))) << level;
    EXPECT_NEAR(early.Delta_final[0], full.Delta_final[0], 1e-6 * full.Delta_total_initial) << level;
    EXPECT_NEAR(early.Psi_final, full.Psi_final, 1e-6) << level;
  }
  EXPECT_EQ(simulate_certified(reduced, o).level.level, ModelLevel::reduced);
  EXPECT_EQ(simulate_certified(modal2, o).level.level, ModelLevel::modal);
  Scene full_level;
  full_level.L = 4;
  full_level.T = 60;
  full_level.dt = 60;
  full_level.rest_delta_l = {{3, 1e-4}};
  const SimulationResult f = simulate_certified(full_level, o);
  EXPECT_EQ(f.level.level, ModelLevel::full);
  EXPECT_FALSE(f.early.terminated);
  EXPECT_NE(f.early.note.find("full level"), std::string::npos) << f.early.note;
}

TEST(CertifiedRun, OptionsAreValidated) {
  EXPECT_NO_THROW(EarlyTerminationOptions{}.validate());
  EarlyTerminationOptions o;
  o.min_rate = 0;
  EXPECT_THROW(simulate_certified(Scene{}, {}, o), InvalidArgument);
  o = {};
  o.max_distance = 2;
  EXPECT_THROW(o.validate(), InvalidArgument);
  o = {};
  o.attempt_growth = 0.5;
  EXPECT_THROW(o.validate(), InvalidArgument);
}

#ifdef RBCSTAB_CLI
// --full-horizon on the command line.
TEST(CertifiedRun, FullHorizonFlag) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("rbcstab_early_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  auto run = [&](const std::string& flags) {
    const std::string out = (dir / "out.json").string();
    EXPECT_EQ(std::system((std::string(RBCSTAB_CLI) + " simulate --json " + flags + " > " + out).c_str()), 0);
    std::ifstream in(out);
    return nlohmann::json::parse(in);
  };
  EXPECT_TRUE(run("").at("terminated_at").is_number());
  const nlohmann::json full = run("--full-horizon");
  EXPECT_TRUE(full.at("terminated_at").is_null());
  EXPECT_EQ(full.at("terminated_at_reason"), "full horizon requested");
  std::filesystem::remove_all(dir);
}
#endif

// The skip's error against the full run, relative, over Delta_l(T) (every mode) and sigma(T).
double skip_error(const Scene& s, double rtol, const EarlyTerminationOptions& early = {}) {
  SimulationOptions o;
  o.integrator.rtol = rtol;
  o.integrator.atol = rtol * 1e-4;
  const SimulationResult certified = simulate_certified(s, o, early);
  EXPECT_TRUE(certified.early.terminated) << "rtol " << rtol << ": " << certified.early.note;
  o.full_horizon = true;
  const SimulationResult full = simulate(s, o);
  double err = std::abs(certified.sigma_final - full.sigma_final) / std::abs(full.sigma_final);
  for (std::size_t j = 0; j < full.Delta_final.size(); ++j)
    err = std::max(err, std::abs(certified.Delta_final[j] - full.Delta_final[j]) / full.Delta_final[j]);
  return err;
}

// Fig. 3 (Delta_4 decays on the l = 3 orbit): the skip's error falls with rtol, as the full runs' own error
// does (at a fixed radius 1e-3 it stays at ~1e-6 relative for every rtol, below). Tolerance: 100 rtol,
// the full runs' own global error at these rtols being ~10 rtol.
TEST(CertifiedRun, SkipErrorFallsWithRtol) {
  Scene s = testing::fig3_scene(0.0);
  s.T = 300;
  const double coarse = skip_error(s, 1e-8), fine = skip_error(s, 1e-10);
  std::cout << "skip error: rtol 1e-8 " << coarse << ", rtol 1e-10 " << fine << "\n";
  EXPECT_LT(coarse, 100 * 1e-8);
  EXPECT_LT(fine, 100 * 1e-10);
  EXPECT_LT(fine, coarse / 10);
  // A fixed state tolerance (the radius stays 1e-3): the error no longer follows rtol, which the check sees.
  EarlyTerminationOptions fixed;
  fixed.state_tolerance = 1e-6;
  const double fixed_fine = skip_error(s, 1e-10, fixed);
  std::cout << "fixed radius 1e-3: rtol 1e-10 " << fixed_fine << "\n";
  EXPECT_FALSE(fixed_fine < 100 * 1e-10);
}

// The automatic L's candidate run stops early too (it used to run to T: 22 s of 36 s at T = 1e7), and its check
// bounds the dropped modes over the skip: the default scene seeded with delta = 1e-10 (whose candidate L = 4
// passes) decides as the full-horizon candidate does, with a bound at least the one the full run's steps give,
// and outputs within 100 rtol of the full run's.
TEST(CertifiedRun, AutomaticLCandidateStopsEarly) {
  Scene s;
  s.delta = 1e-10;
  s.T = 3000;
  SceneFile f, g;
  f.scene = g.scene = s;
  g.options.full_horizon = true;
  const SimulationResult r = simulate_scene(f, f.options), full = simulate_scene(g, g.options);
  ASSERT_TRUE(f.truncation_check && g.truncation_check);
  ASSERT_TRUE(f.truncation_check->passed) << f.truncation_check->verdict;
  ASSERT_TRUE(g.truncation_check->passed) << g.truncation_check->verdict;
  EXPECT_EQ(f.scene.L, g.scene.L);
  EXPECT_LT(f.scene.L, s.L);
  ASSERT_TRUE(r.early.terminated) << r.early.note;
  EXPECT_FALSE(full.early.terminated);
  EXPECT_LT(r.counters.steps, full.counters.steps / 2);
  for (std::size_t i = 0; i < f.truncation_check->dropped.size(); ++i)
    EXPECT_GE(f.truncation_check->dropped[i].Delta_max, g.truncation_check->dropped[i].Delta_max * (1 - 1e-6));
  for (std::size_t j = 0; j < r.Delta_final.size(); ++j)
    EXPECT_NEAR(r.Delta_final[j], full.Delta_final[j], 100 * 1e-8 * full.Delta_final[j]) << "l = " << j + 2;
  EXPECT_NEAR(r.sigma_final, full.sigma_final, 100 * 1e-8 * std::abs(full.sigma_final));

  // A skip the run cannot account for fails the check, saying why: the recorded integral of sigma over it
  // (used where no kept mode gives the integral exactly) missing.
  SceneFile h;
  h.scene = s;
  (void)simulate_truncated(h, h.options, nullptr, [](const ValidScene& v, const SimulationOptions& o) {
    SimulationResult run = simulate_certified(v, o);
    run.early.sigma_integral = std::numeric_limits<double>::quiet_NaN();
    return run;
  });
  ASSERT_TRUE(h.truncation_check);
  EXPECT_FALSE(h.truncation_check->passed);
  EXPECT_NE(h.truncation_check->verdict.find("without the integral of sigma"), std::string::npos)
      << h.truncation_check->verdict;
}

}  // namespace
}  // namespace rbcstab
