#pragma once
// JSON and text views of a scene's verdicts: the summary (a run and its analysis) and the threshold report
// (no run), shared by the command line, the report and any other front end.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "rbcstab/analysis/analysis_io.hpp"
#include "rbcstab/analysis/steady_states.hpp"
#include "rbcstab/io/experiments.hpp"
#include "rbcstab/io/scene_file.hpp"
#include "rbcstab/verdict/physical_map.hpp"
#include "rbcstab/verdict/predict.hpp"

namespace rbcstab {

// The glossary defining every term the summary prints; the summary names it (text and JSON "glossary").
inline constexpr const char* kGlossary = "docs/glossary.md";

nlohmann::json to_json(const ModePrediction& m);
// Each orientation's first unstable shear rate: orientation, beta, found, alpha, evaluations, then shear_rate
// [1/s], bracket, B, C when found (else reason and side: below/above the range), and l, shape when a mode is named.
nlohmann::json to_json(const std::vector<ShearRateThreshold>& thresholds);
// The physical phase diagram: the cell (SI), the spreads, per viscosity [Pa s] lambda, Lambda and each boundary
// (tumbling_to_swinging, onset_out_of_plane, onset_in_plane: found, shear_rate [1/s], bracket, l, or reason and
// side -- below/above the searched shear_rate_range; and its band: cells, found, lo, hi, lo_from, hi_from), then the
// assumption checks.
nlohmann::json to_json(const PhysicalMap& map);
// The same with the published observations drawn over it: "experiments" (io/experiments.hpp's rows) and
// "experiments_file" (where they were read; "" for none). What the report's and Python's drawing read.
nlohmann::json to_json(const PhysicalMap& map, const std::vector<PublishedObservation>& observed,
                       const std::string& experiments_file);

// The summary of a scene file's run r and its prediction (predict(scene, transient, &r)): the keys of
// to_json(SimulationResult) (without the trajectory), the truncation, then the analysis.
nlohmann::json summary_json(const SceneFile& file, const SimulationResult& r, const ScenePrediction& prediction);
// The same as readable text, from the "rbcstab <version> -- scene" line to "Status:".
std::string summary_text(const SceneFile& file, const SimulationResult& r, const ScenePrediction& prediction);

// The paper's thresholds for a scene, each with its domain, beside the exact finite-S out-of-plane criterion and
// the asymptotic and finite-horizon predictions (no modal simulation).
struct ThresholdReport {
  double r0 = 0;  // stress_free_r0
  OutOfPlaneCriterion criterion;
  ScenePrediction prediction;
  Quantity lambda_star_minus;  // outside its domain unless C is finite and alpha > 0
  bool has_exact_C_star = false;
  std::vector<double> exact_C_star;  // the roots on the paper's range [e^-5.5, e^2] when has_exact_C_star
};
ThresholdReport threshold_report(const Scene& scene, bool exact_C_star);
ThresholdReport threshold_report(const ValidScene& scene, bool exact_C_star);
nlohmann::json thresholds_json(const SceneFile& file, const ThresholdReport& t);
std::string thresholds_text(const SceneFile& file, const ThresholdReport& t);

// The summary's computation on a scene file (L as it gives it): the truncation for a simulation and the
// finite-horizon predictor share one reduced transient; then the run and its prediction. Every front end calls this.
struct SummaryRun {
  SceneFile file;
  SimulationResult run;
  ScenePrediction prediction;
};
// The run, the prediction and, on a physical scene, the shear-rate thresholds searched over `search`. Checks the
// file once (validated(SceneFile), io): its caller need not.
SummaryRun run_summary(SceneFile file, const ShearRateSearchOptions& search = {});

// The post command's computation on a scene file (L as it gives it): the run without its trajectory as
// simulate_scene runs it (certified early stop: the tail means are integrated along the attractor), and the
// out-of-plane Delta~2 (r0 = 0: the paper's case) at the L run. Every front end calls this.
PostRun run_post(SceneFile file);

}  // namespace rbcstab
