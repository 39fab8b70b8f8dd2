// rbcstab bench: measured speed against accuracy. The studies, their files and renderers are the library's
// (report/bench.hpp run_bench); this maps flags to a BenchSpec and prints.
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "progress.hpp"
#include "rbcstab/report/bench.hpp"
#include "scene_options.hpp"

namespace rbcstab::cli {

namespace {
struct BenchOptions {
  std::string kind = "work-precision";
  SceneOptions scene;
  BenchSpec spec;
  std::vector<std::string> levels{"modal", "full"}, steppers{"rk8pd", "rkck", "rosenbrock", "msbdf"};
  std::vector<double> ln_C_range{-5.5, 2.0};
  bool json = false;
  ProgressOutput progress;
};

int run(const BenchOptions& o) {
  const SceneFile sf = o.scene.resolve(TruncationUse::measurement);
  BenchSpec spec = o.spec;
  spec.study = from_string<BenchStudy>(o.kind, "kind");
  spec.work_precision.levels.clear();
  for (const auto& l : o.levels) spec.work_precision.levels.push_back(model_level_from_string(l));
  spec.work_precision.steppers.clear();
  for (const auto& s : o.steppers) spec.work_precision.steppers.push_back(stepper_from_string(s));
  spec.threshold.ln_C_lo = o.ln_C_range.at(0);
  spec.threshold.ln_C_hi = o.ln_C_range.at(1);
  spec.on_progress =
      o.progress.callback("bench " + o.kind + ":", spec.study == BenchStudy::threshold ? "rows" : "runs");
  const BenchResult r = run_bench(sf, spec);
  std::cout << (o.json ? r.json.dump(2) + "\n" : r.text);
  for (const std::string& f : r.failures) std::cerr << "rbcstab: " << f << "\n";
  return r.failures.empty() ? kOk : kRunFailed;
}

Runner add_bench(CLI::App& app) {
  auto o = std::make_shared<BenchOptions>();
  app.add_option("kind", o->kind, "what to measure")
      ->check(CLI::IsMember(enum_names<BenchStudy>()))
      ->capture_default_str();
  o->scene.add_to(app);
  app.add_option("--output", o->spec.output, "folder for the CSV, JSON and PNG")->capture_default_str();
  app.add_option("--levels", o->levels, "model levels to compare (work-precision)")
      ->delimiter(',')
      ->capture_default_str();
  app.add_option("--steppers", o->steppers, "steppers to compare (work-precision)")
      ->delimiter(',')
      ->capture_default_str();
  app.add_option("--rtols", o->spec.work_precision.rtols, "tolerances (work-precision), each in [1e-14, 0.1]")
      ->delimiter(',')
      ->capture_default_str();
  app.add_option("--Ls", o->spec.truncation.Ls,
                 "truncations (truncation), each an integer in [2, 100]; the last is the reference")
      ->delimiter(',')
      ->capture_default_str();
  app.add_option("--max-seconds", o->spec.work_precision.max_seconds, "wall-clock budget per run (> 0)")
      ->capture_default_str();
  app.add_option("--lnC-range", o->ln_C_range, "bracket of the critical ln C at the scene's B (threshold)")
      ->expected(2)
      ->capture_default_str();
  app.add_flag("!--no-plot", o->spec.plot, "skip the PNG figure");
  app.add_flag("--json", o->json, "print the table as JSON");
  o->progress.add_flags(app);
  return [o] { return run(*o); };
}

const RegisterCommand kRegisterBench{"bench",
                                     "Speed against accuracy: work-precision, truncation in L, threshold precision",
                                     add_bench,
                                     80,
                                     {{"ln_C_lo", "--lnC-range"}, {"ln_C_hi", "--lnC-range"}}};
}  // namespace

}  // namespace rbcstab::cli
