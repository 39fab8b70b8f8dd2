#include "rbcstab/report/bench.hpp"

#include <filesystem>
#include <sstream>

#include "rbcstab/analysis/analysis_io.hpp"
#include "rbcstab/io/files.hpp"
#include "rbcstab/io/json.hpp"
#include "rbcstab/io/work_precision_io.hpp"
#include "rbcstab/report/report.hpp"
#include "rbcstab/sweep/sweep_io.hpp"

namespace rbcstab {

namespace {
// The study's CSV and JSON as OUTPUT/<scene>_<study>.csv and .json, written together; returns that prefix.
std::string write_study(const BenchSpec& spec, const SceneFile& sf, const std::string& study, const std::string& csv,
                        const nlohmann::json& j) {
  std::filesystem::create_directories(spec.output);
  const std::string base = spec.output + "/" + sf.scene.name + "_" + study;
  write_files_atomic({{base + ".csv", csv, "--output"}, {base + ".json", j.dump(2) + "\n", "--output"}});
  return base;
}

std::string files_written(const BenchSpec& spec, const std::string& base) {
  return "wrote " + base + ".csv, .json" + (spec.plot ? ", .png" : "") + "\n";
}

BenchResult work_precision_study(const SceneFile& sf, const BenchSpec& spec) {
  WorkPrecisionOptions wp = spec.work_precision;
  wp.on_progress = spec.on_progress;
  const WorkPrecisionTable t = work_precision(sf.scene, wp);
  BenchResult r;
  r.json = work_precision_json(sf, t);
  r.base = write_study(spec, sf, "work_precision", work_precision_csv(t), r.json);
  if (t.reference_status != IntegrationStatus::success) {
    r.failures.push_back("the work-precision reference run (full, rk8pd) failed: " +
                         row_reason(t.reference_status, t.reference_reason, sf.scene.parameters) + "; wrote " + r.base +
                         ".csv, .json without rows");
    return r;
  }
  if (spec.plot)
    draw_csv_figure("work_precision.py", r.base, "work-precision: " + sf.scene.name, "the work-precision figure");
  r.text = work_precision_text(t) + files_written(spec, r.base);
  return r;
}

BenchResult truncation_study(const SceneFile& sf, const BenchSpec& spec) {
  TruncationConvergenceOptions ts = spec.truncation;
  ts.on_progress = spec.on_progress;
  const TruncationConvergence t = truncation_convergence(sf.scene, sf.options, ts);
  BenchResult r;
  r.text = truncation_convergence_csv(t);
  r.json = truncation_convergence_json(sf, t);
  r.base = write_study(spec, sf, "truncation", r.text, r.json);
  if (!t.reference_ok())
    r.failures.push_back("the truncation reference (L = " + std::to_string(t.reference().L) +
                         ") failed: " + row_reason(t.reference().status, t.reference().reason, sf.scene.parameters));
  return r;
}

BenchResult threshold_study(const SceneFile& sf, const BenchSpec& spec) {
  ThresholdPrecisionOptions tp = spec.threshold;
  tp.on_progress = spec.on_progress;
  const ThresholdPrecision t = threshold_precision(sf.scene, tp);
  BenchResult r;
  r.json = threshold_precision_json(sf, tp, t);
  r.base = write_study(spec, sf, "threshold", threshold_precision_csv(t), r.json);
  std::ostringstream title;
  title << "critical C at B = " << t.B << ": " << sf.scene.name;
  if (spec.plot) draw_csv_figure("threshold_precision.py", r.base, title.str(), "the figure");
  for (const auto& ref : t.references)
    if (ref.status != "ok") r.failures.push_back(ref.predictor + " reference failed: " + ref.status);
  r.text = threshold_precision_text(sf, t) + files_written(spec, r.base);
  return r;
}
}  // namespace

BenchResult run_bench(const SceneFile& file, const BenchSpec& spec) {
  switch (spec.study) {
    case BenchStudy::truncation:
      return truncation_study(file, spec);
    case BenchStudy::threshold:
      return threshold_study(file, spec);
    case BenchStudy::work_precision:
      break;
  }
  return work_precision_study(file, spec);
}

}  // namespace rbcstab
