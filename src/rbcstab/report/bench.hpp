#pragma once
// The benchmark studies (`rbcstab bench`) as one library call: the study runs on the scene, its CSV and JSON are
// written as OUTPUT/<scene>_<study>.csv and .json (and a PNG drawn from the CSV), and the result holds the
// views a front end prints and the failures that make the run fail.
//   work-precision: every level x stepper x rtol against a ~1e-13 reference by another level
//                   (integrate/work_precision.hpp, io/work_precision_io.hpp)
//   truncation:     convergence of Delta_l(T), sigma(T) and l_Delta with the truncation L
//                   (analysis/truncation_convergence.hpp, analysis/analysis_io.hpp)
//   threshold:      error of the located critical C at fixed B against cost, per predictor and method
//                   (sweep/threshold_precision.hpp, sweep/sweep_io.hpp)
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "rbcstab/analysis/truncation_convergence.hpp"
#include "rbcstab/core/enum_table.hpp"
#include "rbcstab/core/progress.hpp"
#include "rbcstab/integrate/work_precision.hpp"
#include "rbcstab/io/scene_file.hpp"
#include "rbcstab/sweep/threshold_precision.hpp"

namespace rbcstab {

enum class BenchStudy { work_precision, truncation, threshold };
template <>
struct EnumTable<BenchStudy> {
  static constexpr EnumName<BenchStudy> entries[] = {{BenchStudy::work_precision, "work-precision"},
                                                     {BenchStudy::truncation, "truncation"},
                                                     {BenchStudy::threshold, "threshold"}};
};

struct BenchSpec {
  BenchStudy study = BenchStudy::work_precision;
  std::string output = "out/bench";  // folder, created if missing
  WorkPrecisionOptions work_precision;
  TruncationConvergenceOptions truncation;
  ThresholdPrecisionOptions threshold;
  bool plot = true;  // the PNG (python3 with matplotlib)
  ProgressCallback on_progress;
};

struct BenchResult {
  std::string base;     // OUTPUT/<scene>_<study>: the .csv and .json written
  nlohmann::json json;  // the study's JSON, as written
  std::string text;     // the text view and the files written; empty when the reference failed (work-precision)
  std::vector<std::string> failures;  // references that failed: every error is then meaningless (exit 1)
};

// `file` is resolved for a measurement (apply_truncation). Bad options throw InvalidArgument naming the field;
// a failed reference is a failure, not an exception, and the files are still written.
BenchResult run_bench(const SceneFile& file, const BenchSpec& spec);

}  // namespace rbcstab
