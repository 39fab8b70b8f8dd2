// Threshold precision (sweep/threshold_precision.hpp) on the Fig. 4(b) plane at B = 2 (the Fig. 3 scene).
// Oracles: the asymptotic boundary by a different root method (Illinois regula falsi on the continuous margin
// sigma_R^eq - max_l sigma_l^c, from analysis/steady_states and model/coefficients directly); the verdicts of
// each predictor on either side of its reference; the exact error bounds of the two methods (bisection:
// half the final bracket; grid: half a cell) when the boundary is unique in the bracket.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "rbcstab/analysis/predictors.hpp"
#include "rbcstab/analysis/steady_states.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/integrate/simulation.hpp"
#include "rbcstab/io/json.hpp"
#include "rbcstab/io/scene_file.hpp"
#include "rbcstab/model/coefficients.hpp"
#include "rbcstab/sweep/sweep_io.hpp"
#include "rbcstab/sweep/threshold_precision.hpp"

namespace rbcstab {
namespace {

Scene fig4b_at_B2() {
  Scene s;
  s.parameters = Parameters{5.0, 1.0, 0.01, 2.0, 0.04};
  s.beta = 1e-3;
  s.delta = 1e-3;
  s.L = 10;
  s.T = 500;
  s.dt = 500;
  return s;
}

ThresholdPrecisionOptions small_options() {
  ThresholdPrecisionOptions o;
  o.bisections = {4, 8, 16, 24};
  o.rtols = {1e-6};
  o.grid_points = {5, 17};
  o.reference_bisections = 36;  // 7.5 / 2^36 ~ 1e-10 in ln C
  o.trace_max_steps = {};       // continuation has its own test (its finite-horizon trace costs seconds)
  return o;
}

const ThresholdPrecision& result() {
  static const ThresholdPrecision r = threshold_precision(fig4b_at_B2(), small_options());
  return r;
}

const ThresholdReference& reference(const std::string& predictor) {
  for (const auto& r : result().references)
    if (r.predictor == predictor) return r;
  throw std::runtime_error("no reference for " + predictor);
}

double margin(double ln_C) {
  Parameters p = fig4b_at_B2().parameters;
  p.C = std::exp(ln_C);
  double sc = -1e300;
  for (int l = 3; l <= 10; ++l) sc = std::max(sc, sigma_c(l, p.alpha()));
  return out_of_plane_equilibrium(p).sigma_R - sc;
}

TEST(ThresholdPrecision, AsymptoticReferenceMatchesRegulaFalsi) {
  // Illinois regula falsi on the continuous margin: a different root method on independently assembled pieces.
  double a = -5.5, b = 2.0, fa = margin(a), fb = margin(b);
  ASSERT_LT(fa * fb, 0);
  int side = 0;
  double c = a;
  for (int it = 0; it < 200 && std::abs(b - a) > 1e-13; ++it) {
    c = (a * fb - b * fa) / (fb - fa);
    const double fc = margin(c);
    if (fc == 0) break;
    if (fc * fb < 0) {
      a = b, fa = fb;
      side = 0;
    } else {
      fa = side == -1 ? fa / 2 : fa;
      side = -1;
    }
    b = c, fb = fc;
  }
  const ThresholdReference& r = reference("asymptotic");
  ASSERT_EQ(r.status, "ok");
  // Tolerance: the reference bracket (~1e-10) plus the regula falsi stopping width.
  EXPECT_NEAR(r.ln_C, c, 2e-10);
}

TEST(ThresholdPrecision, EachReferenceSeparatesItsVerdicts) {
  // 1e-8 in ln C is 100x the reference bracket: each predictor's verdict must differ on the two sides.
  const Scene s = fig4b_at_B2();
  for (const std::string name : {"finite_horizon", "simulation"}) {
    const ThresholdReference& r = reference(name);
    ASSERT_EQ(r.status, "ok") << name;
    EXPECT_LT(r.bracket, 1e-9) << name;
    bool unstable[2];
    for (int side = 0; side < 2; ++side) {
      Scene t = s;
      t.parameters.C = std::exp(r.ln_C + (side == 0 ? -1e-8 : 1e-8));
      if (name == "finite_horizon") {
        PredictorOptions po;
        po.integrator.rtol = 1e-12;
        po.integrator.atol = 1e-16;
        const FiniteHorizon h = finite_horizon_growth(t, t.T, po);
        unstable[side] = *std::max_element(h.G.begin() + 1, h.G.end()) > 0;
      } else {
        SimulationOptions so;
        so.integrator.rtol = 1e-12;
        so.integrator.atol = 1e-16;
        so.record_trajectory = false;
        unstable[side] = simulate(t, so).l_Delta >= 3;
      }
    }
    EXPECT_TRUE(unstable[0]) << name << ": small C is the unstable side in this plane";
    EXPECT_FALSE(unstable[1]) << name;
  }
}

TEST(ThresholdPrecision, MethodErrorsObeyTheirBounds) {
  const double width = 7.5;
  for (const ThresholdRow& row : result().rows) {
    if (row.method == "closed_form" || row.method == "continuation") continue;
    ASSERT_EQ(row.status, "ok") << row.predictor << " " << row.method << " " << row.budget;
    const double ref_err = reference(row.predictor).bracket;
    // rtol enters only beyond 1e-8 here (measured: the boundary moves < 1e-9 between rtol 1e-4 and 1e-12,
    // because the verdict depends on exp(2 G_3(T)) whose slope in ln C is ~1e4); allow 1e-8 for it.
    if (row.method == "bisection") {
      EXPECT_LE(row.error, width / std::ldexp(1.0, row.budget + 1) + ref_err + 1e-8)
          << row.predictor << " k = " << row.budget;
    } else {
      EXPECT_LE(row.error, 0.5 * width / (row.budget - 1) + ref_err + 1e-8) << row.predictor << " n = " << row.budget;
    }
    EXPECT_EQ(row.evaluations, std::size_t(row.method == "bisection" ? row.budget + 2 : row.budget));
    if (row.predictor != "asymptotic") {
      EXPECT_GT(row.rhs_evaluations, 0u);
    }
  }
}

TEST(ThresholdPrecision, PredictorsAgreeOnTheBoundaryToModelAccuracy) {
  // Different criteria (attractor, finite horizon, nonlinear run) of the same instability: measured 1.6e-3 apart
  // in ln C at B = 2; a gross error (wrong mode, wrong side) would be O(0.1) or more.
  EXPECT_NEAR(reference("asymptotic").ln_C, reference("simulation").ln_C, 1e-2);
  EXPECT_NEAR(reference("finite_horizon").ln_C, reference("simulation").ln_C, 1e-2);
}

TEST(ThresholdPrecision, ContinuationPointsInterpolateTheBoundary) {
  // The traced curve is Newton-corrected onto the boundary; read at ln B by linear interpolation between points
  // at most max_step apart (in the unit square of the strip: 0.05 * 7.5 in ln C), its error is the chord's,
  // ~ h^2 |y''| / 8; measured 1.4e-7 at this step, bound 1e-5 (a wrong crossing or piece would be >= 1e-3).
  ThresholdPrecisionOptions o = small_options();
  o.predictors = {"asymptotic"};
  o.bisections = {1};
  o.grid_points = {2};
  o.trace_max_steps = {0.05};
  const ThresholdPrecision t = threshold_precision(fig4b_at_B2(), o);
  bool seen = false;
  for (const ThresholdRow& row : t.rows) {
    if (row.method != "continuation") continue;
    seen = true;
    ASSERT_EQ(row.status, "ok");
    EXPECT_LT(row.error, 1e-5);
    EXPECT_EQ(row.budget, 20);
    EXPECT_GT(row.evaluations, 0u);
  }
  EXPECT_TRUE(seen);
  ASSERT_EQ(t.references.size(), 1u);
  EXPECT_NEAR(t.references[0].ln_C, reference("asymptotic").ln_C, 1e-10);
}

TEST(ThresholdPrecision, NoSignChangeIsAStatusAndBadOptionsThrow) {
  ThresholdPrecisionOptions o = small_options();
  o.ln_C_lo = 1.0;  // both ends stable
  o.ln_C_hi = 2.0;
  o.rtols = {1e-6};
  const ThresholdPrecision t = threshold_precision(fig4b_at_B2(), o);
  for (const auto& r : t.references) EXPECT_NE(r.status, "ok") << r.predictor;
  ThresholdPrecisionOptions bad;
  bad.ln_C_lo = 3;
  bad.ln_C_hi = 2;
  EXPECT_THROW(threshold_precision(fig4b_at_B2(), bad), InvalidArgument);
  bad = {};
  bad.reference_rtol = 1e-6;
  EXPECT_THROW(threshold_precision(fig4b_at_B2(), bad), InvalidArgument);
  bad = {};
  bad.predictors = {"oracle"};
  EXPECT_THROW(threshold_precision(fig4b_at_B2(), bad), InvalidArgument);
  bad = {};
  bad.trace_max_steps = {0.0};
  EXPECT_THROW(threshold_precision(fig4b_at_B2(), bad), InvalidArgument);
}

// The study's one CSV, JSON and text: a row without a boundary is an empty field, a null with its status as the
// reason and "n/a"; a failed reference explains every error of its predictor.
TEST(ThresholdPrecision, RenderersExplainMissingNumbers) {
  const SceneFile sf = parse_scene("");
  ThresholdPrecisionOptions o;
  ThresholdPrecision t;
  t.B = 2;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  t.references = {{"asymptotic", -2.5, 1e-11, "ok"}, {"simulation", 0, 0, "run failed"}};
  t.rows = {{"asymptotic", "bisection", 0, 8, -2.49, 0.01, 8, 0, 0.1, "ok"},
            {"asymptotic", "grid", 0, 5, nan, nan, 5, 0, 0.1, "no verdict change on the grid"},
            {"simulation", "bisection", 1e-6, 4, -2.4, nan, 4, 100, 0.2, "ok"}};
  const std::string csv = threshold_precision_csv(t);
  EXPECT_NE(csv.find("asymptotic,grid,0,5,,,5,0,0.1,\"no verdict change on the grid\"\n"), std::string::npos) << csv;
  const nlohmann::json j = threshold_precision_json(sf, o, t);
  EXPECT_TRUE(unexplained_nulls(j).empty());
  EXPECT_EQ(j["ln_C_range"], nlohmann::json({-5.5, 2.0}));
  EXPECT_EQ(j["rows"][1]["ln_C_reason"], "no verdict change on the grid");
  EXPECT_EQ(j["rows"][2]["error_reason"], "no reference: run failed");
  EXPECT_EQ(j["references"][1]["rtol"], o.reference_rtol);
  const std::string text = threshold_precision_text(sf, t);
  EXPECT_EQ(text.rfind("critical ln C at B = 2 (scene fig3_op)\n", 0), 0u) << text;
  EXPECT_EQ(text.find("nan"), std::string::npos);
  EXPECT_NE(text.find("n/a"), std::string::npos);
}

}  // namespace
}  // namespace rbcstab
