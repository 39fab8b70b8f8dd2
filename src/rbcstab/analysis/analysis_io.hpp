#pragma once
// JSON and text views of the analysis results, shared by the command line, the report and any other front end:
// a quantity outside its domain is null with "<key>_reason" beside it in JSON and "n/a (reason)" in text,
// never silently missing.
#include <complex>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "rbcstab/analysis/post_instability.hpp"
#include "rbcstab/analysis/quantity.hpp"
#include "rbcstab/analysis/truncation_convergence.hpp"
#include "rbcstab/integrate/simulation.hpp"
#include "rbcstab/io/scene_file.hpp"

namespace rbcstab {

// j[key] = the value (null outside the domain), and j[key + "_reason"] when there is a reason.
void put(nlohmann::json& j, const std::string& key, const Quantity& q);
// [re, im], each null when not finite.
nlohmann::json to_json(const std::complex<double>& z);
nlohmann::json to_json(const Delta2Prediction& d);
// The value with 6 significant digits, or "n/a (reason)" outside its domain.
std::string to_text(const Quantity& q);
// "3, 4" or "none".
std::string mode_list(const std::vector<int>& modes);

// The simulated long-time Delta-bar_2 (tail mean of Delta_2), or why there is none: the run stopped, or it
// stayed stable (l_Delta = 2) and has no post-instability state.
Quantity simulated_Delta2(const SimulationResult& r);

// The post-instability state of a scene file's scene: Eq. ss's predictions (post) beside the simulation r of
// the same scene (tail window: file.options.tail_window).
nlohmann::json post_json(const SceneFile& file, const PostInstability& post, const SimulationResult& r);
std::string post_text(const SceneFile& file, const PostInstability& post, const SimulationResult& r);

// The post command's computation on a scene file: the out-of-plane Delta~2 beside the run (run_post,
// verdict/verdict_io.hpp: the run is certified, which this module cannot do).
struct PostRun {
  SceneFile file;
  PostInstability post;
  SimulationResult run;
};

// The truncation study (analysis/truncation_convergence.hpp): one CSV row per L (L, status, l_Delta, sigma_final,
// error_Delta, error_sigma, rhs_evaluations, seconds; an empty field for a missing number), which is also its text,
// and the document {scene, reference_L, rows, L, L_reason}, whose missing numbers are null with their reason.
std::string truncation_convergence_csv(const TruncationConvergence& t);
nlohmann::json truncation_convergence_json(const SceneFile& file, const TruncationConvergence& t);

}  // namespace rbcstab
