// rbcstab bench: measured speed against accuracy. The studies and their renderers are the library's:
//   work-precision: every level x stepper x rtol against a ~1e-13 reference by another level
//                   (integrate/work_precision.hpp, io/work_precision_io.hpp)
//   truncation:     convergence of Delta_l(T), sigma(T) and l_Delta with the truncation L
//                   (analysis/truncation_convergence.hpp, analysis/analysis_io.hpp)
//   threshold:      error of the located critical C at fixed B against cost, per predictor and method
//                   (sweep/threshold_precision.hpp, sweep/sweep_io.hpp)
// Each writes OUTPUT/<scene>_<study>.csv and .json (and a PNG drawn from the CSV).
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>

#include "commands.hpp"
#include "progress.hpp"
#include "rbcstab/analysis/analysis_io.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/io/files.hpp"
#include "rbcstab/io/json.hpp"
#include "rbcstab/io/work_precision_io.hpp"
#include "rbcstab/report/report.hpp"
#include "rbcstab/sweep/sweep_io.hpp"
#include "scene_options.hpp"

namespace rbcstab::cli {

namespace {
struct BenchOptions {
  std::string kind = "work-precision";
  SceneOptions scene;
  std::string output = "out/bench";
  std::vector<std::string> levels{"modal", "full"}, steppers{"rk8pd", "rkck", "rosenbrock", "msbdf"};
  WorkPrecisionOptions work_precision;      // --rtols, --max-seconds
  TruncationConvergenceOptions truncation;  // --Ls
  std::vector<double> ln_C_range{-5.5, 2.0};
  bool json = false;
  bool plot = true;
  ProgressOutput progress;
};

// The study's CSV and JSON as OUTPUT/<scene>_<study>.csv and .json, written together; returns that prefix.
std::string write_study(const BenchOptions& o, const SceneFile& sf, const std::string& study, const std::string& csv,
                        const nlohmann::json& j) {
  std::filesystem::create_directories(o.output);
  const std::string base = o.output + "/" + sf.scene.name + "_" + study;
  write_files_atomic({{base + ".csv", csv, "--output"}, {base + ".json", j.dump(2) + "\n", "--output"}});
  return base;
}

// The JSON, or the text and the files written.
void print(const BenchOptions& o, const nlohmann::json& j, const std::string& text, const std::string& base) {
  std::cout << (o.json ? j.dump(2) + "\n" : text + "wrote " + base + ".csv, .json" + (o.plot ? ", .png" : "") + "\n");
}

int run_work_precision(const BenchOptions& o, const SceneFile& sf) {
  WorkPrecisionOptions wp = o.work_precision;
  wp.levels.clear();
  for (const auto& l : o.levels) wp.levels.push_back(model_level_from_string(l));
  wp.steppers.clear();
  for (const auto& s : o.steppers) wp.steppers.push_back(stepper_from_string(s));
  wp.on_progress = o.progress.callback("bench work-precision:", "runs");
  const WorkPrecisionTable t = work_precision(sf.scene, wp);
  const nlohmann::json j = work_precision_json(sf, t);
  const std::string base = write_study(o, sf, "work_precision", work_precision_csv(t), j);
  if (t.reference_status != IntegrationStatus::success) {
    if (o.json) std::cout << j.dump(2) << "\n";
    std::cerr << "rbcstab: the work-precision reference run (full, rk8pd) failed: "
              << row_reason(t.reference_status, t.reference_reason, sf.scene.parameters) << "; wrote " << base
              << ".csv, .json without rows\n";
    return kRunFailed;
  }
  if (o.plot)
    draw_csv_figure("work_precision.py", base, "work-precision: " + sf.scene.name, "the work-precision figure");
  print(o, j, work_precision_text(t), base);
  return kOk;
}

int run_truncation(const BenchOptions& o, const SceneFile& sf) {
  TruncationConvergenceOptions ts = o.truncation;
  ts.on_progress = o.progress.callback("bench truncation:", "runs");
  const TruncationConvergence t = truncation_convergence(sf.scene, sf.options, ts);
  const std::string csv = truncation_convergence_csv(t);
  const nlohmann::json j = truncation_convergence_json(sf, t);
  write_study(o, sf, "truncation", csv, j);
  std::cout << (o.json ? j.dump(2) + "\n" : csv);
  if (t.reference_ok()) return kOk;
  std::cerr << "rbcstab: the truncation reference (L = " << t.reference().L
            << ") failed: " << row_reason(t.reference().status, t.reference().reason, sf.scene.parameters) << "\n";
  return kRunFailed;
}

int run_threshold(const BenchOptions& o, const SceneFile& sf) {
  if (o.ln_C_range.size() != 2)
    throw InvalidArgument("--lnC-range",
                          "--lnC-range takes two numbers (lo hi), got " + std::to_string(o.ln_C_range.size()));
  if (!(o.ln_C_range[0] < o.ln_C_range[1]))
    throw InvalidArgument("--lnC-range", "--lnC-range = " + format_value(o.ln_C_range[0]) + " " +
                                             format_value(o.ln_C_range[1]) + ": needs lo < hi (finite)");
  ThresholdPrecisionOptions tp;
  tp.ln_C_lo = o.ln_C_range[0];
  tp.ln_C_hi = o.ln_C_range[1];
  tp.on_progress = o.progress.callback("bench threshold:", "rows");
  const ThresholdPrecision t = threshold_precision(sf.scene, tp);
  const nlohmann::json j = threshold_precision_json(sf, tp, t);
  const std::string base = write_study(o, sf, "threshold", threshold_precision_csv(t), j);
  std::ostringstream title;
  title << "critical C at B = " << t.B << ": " << sf.scene.name;
  if (o.plot) draw_csv_figure("threshold_precision.py", base, title.str(), "the figure");
  // A reference that could not be computed makes every error meaningless: the run failed (exit 1), not the input.
  int rc = kOk;
  for (const auto& r : t.references)
    if (r.status != "ok") {
      std::cerr << "rbcstab: " << r.predictor << " reference failed: " << r.status << "\n";
      rc = kRunFailed;
    }
  print(o, j, threshold_precision_text(sf, t), base);
  return rc;
}

int run(const BenchOptions& o) {
  const SceneFile sf = o.scene.resolve(TruncationUse::measurement);
  if (o.kind == "truncation") return run_truncation(o, sf);
  if (o.kind == "threshold") return run_threshold(o, sf);
  return run_work_precision(o, sf);
}

Runner add_bench(CLI::App& app) {
  auto o = std::make_shared<BenchOptions>();
  app.add_option("kind", o->kind, "what to measure")
      ->check(CLI::IsMember({"work-precision", "truncation", "threshold"}))
      ->capture_default_str();
  o->scene.add_to(app);
  app.add_option("--output", o->output, "folder for the CSV, JSON and PNG")->capture_default_str();
  app.add_option("--levels", o->levels, "model levels to compare (work-precision)")
      ->delimiter(',')
      ->capture_default_str();
  app.add_option("--steppers", o->steppers, "steppers to compare (work-precision)")
      ->delimiter(',')
      ->capture_default_str();
  app.add_option("--rtols", o->work_precision.rtols, "tolerances (work-precision), each in [1e-14, 0.1]")
      ->delimiter(',')
      ->capture_default_str();
  app.add_option("--Ls", o->truncation.Ls,
                 "truncations (truncation), each an integer in [2, 100]; the last is the reference")
      ->delimiter(',')
      ->capture_default_str();
  app.add_option("--max-seconds", o->work_precision.max_seconds, "wall-clock budget per run (> 0)")
      ->capture_default_str();
  app.add_option("--lnC-range", o->ln_C_range, "bracket of the critical ln C at the scene's B (threshold)")
      ->expected(2)
      ->capture_default_str();
  app.add_flag("!--no-plot", o->plot, "skip the PNG figure");
  app.add_flag("--json", o->json, "print the table as JSON");
  o->progress.add_flags(app);
  return [o] { return run(*o); };
}

const RegisterCommand kRegisterBench{
    "bench", "Speed against accuracy: work-precision, truncation in L, threshold precision", add_bench, 80};
}  // namespace

}  // namespace rbcstab::cli
