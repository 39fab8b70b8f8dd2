// rbcstab bench: measured speed against accuracy.
//   work-precision: every level x stepper x rtol against a ~1e-13 reference by another level (CSV, JSON, PNG)
//   truncation:     convergence of Delta_l(T), sigma(T) and l_Delta with the truncation L
//   threshold:      error of the located critical C at fixed B against cost, per predictor and method
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <limits>
#include <memory>
#include <sstream>

#include "commands.hpp"
#include "exit_codes.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/integrate/work_precision.hpp"
#include "rbcstab/sweep/threshold_precision.hpp"
#include "rbcstab/io/files.hpp"
#include "rbcstab/io/json.hpp"
#include "rbcstab/report/report.hpp"
#include "progress.hpp"
#include "scene_options.hpp"

namespace rbcstab::cli {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct BenchOptions {
  std::string kind = "work-precision";
  SceneOptions scene;
  std::string output = "out/bench";
  std::vector<std::string> levels{"modal", "full"}, steppers{"rk8pd", "rkck", "rosenbrock", "msbdf"};
  std::vector<double> rtols{1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12};
  std::vector<int> Ls{4, 6, 8, 10, 12, 16, 20, 24, 30, 40};
  double max_seconds = 30;
  std::vector<double> ln_C_range{-5.5, 2.0};
  bool json = false;
  bool plot = true;
  ProgressOutput progress;
};

std::string work_precision_csv(const WorkPrecisionTable& t) {
  std::ostringstream ss;
  ss << std::setprecision(10);
  ss << "level,stepper,rtol,status,rhs_evaluations,jacobian_evaluations,steps,seconds,error_Delta,error_sigma,l_Delta,"
        "verdict_changed\n";
  for (const auto& r : t.rows)
    ss << to_string(r.level) << ',' << to_string(r.stepper) << ',' << csv_number(r.rtol) << ',' << to_string(r.status)
       << ',' << r.rhs_evaluations << ',' << r.jacobian_evaluations << ',' << r.steps << ',' << csv_number(r.seconds)
       << ',' << csv_number(r.error_Delta) << ',' << csv_number(r.error_sigma) << ',' << r.l_Delta << ','
       << (r.verdict_changed ? 1 : 0) << '\n';
  return ss.str();
}

// Why a row's number is not finite: its run's message when it stopped, else the overflowing inputs.
std::string row_reason(IntegrationStatus status, const std::string& reason, const Parameters& p) {
  return status == IntegrationStatus::success ? nonfinite_reason(p)
                                              : "the run ended with " + to_string(status) + ": " + run_reason(status, reason, p);
}

int run_work_precision(const BenchOptions& o, const SceneFile& sf) {
  WorkPrecisionOptions wp;
  wp.levels.clear();
  for (const auto& l : o.levels) wp.levels.push_back(model_level_from_string(l));
  wp.steppers.clear();
  for (const auto& s : o.steppers) wp.steppers.push_back(stepper_from_string(s));
  wp.rtols = o.rtols;
  wp.max_seconds = o.max_seconds;
  wp.on_progress = o.progress.callback("bench work-precision:", "runs");
  const WorkPrecisionTable t = work_precision(sf.scene, wp);
  std::filesystem::create_directories(o.output);
  const std::string base = o.output + "/" + sf.scene.name + "_work_precision";
  const Parameters& p = sf.scene.parameters;
  const bool reference_ok = t.reference_status == IntegrationStatus::success;
  nlohmann::json ref{{"level", "full"}, {"stepper", "rk8pd"}, {"rtol", wp.reference_rtol},
                     {"status", to_string(t.reference_status)}, {"reason", t.reference_reason},
                     {"Delta_final", by_mode(t.reference_Delta)}, {"l_Delta", t.reference_l_Delta}};
  const std::string ref_reason = row_reason(t.reference_status, t.reference_reason, p);
  put_number(ref, "sigma_final", reference_ok ? t.reference_sigma : kNaN, ref_reason);
  put_number(ref, "spread_vs_modal", reference_ok ? t.reference_spread : kNaN, ref_reason);
  explain_nulls(ref, ref_reason);
  nlohmann::json j{{"scene", to_json(sf.scene)}, {"reference", ref}, {"rows", nlohmann::json::array()}};
  for (const auto& r : t.rows) {
    nlohmann::json row{{"level", to_string(r.level)}, {"stepper", to_string(r.stepper)}, {"rtol", r.rtol},
                       {"status", to_string(r.status)}, {"rhs_evaluations", r.rhs_evaluations},
                       {"jacobian_evaluations", r.jacobian_evaluations}, {"steps", r.steps}, {"seconds", r.seconds},
                       {"l_Delta", r.l_Delta}, {"verdict_changed", r.verdict_changed}};
    const std::string why = row_reason(r.status, r.reason, p);
    put_number(row, "error_Delta", r.error_Delta, why);
    put_number(row, "error_sigma", r.error_sigma, why);
    j["rows"].push_back(row);
  }
  put_truncation(j, sf);
  write_files_atomic({{base + ".csv", work_precision_csv(t), "--output"}, {base + ".json", j.dump(2) + "\n", "--output"}});
  if (!reference_ok) {
    if (o.json) std::cout << j.dump(2) << "\n";
    std::cerr << "rbcstab: the work-precision reference run (full, rk8pd) failed: " << ref_reason
              << "; wrote " << base << ".csv, .json without rows\n";
    return kRunFailed;
  }
  if (o.plot) {
    check_python("/usr/bin/python3");
    const std::string dir = find_script_dir("");
    if (dir.empty()) throw std::runtime_error("cannot find the plotting scripts (set RBCSTAB_DATA_DIR)");
    const std::string log = base + ".plot.log";
    if (run_process({"/usr/bin/python3", dir + "/work_precision.py", base + ".csv", base + ".png",
                     "work-precision: " + sf.scene.name},
                    log) != 0)
      throw std::runtime_error("the work-precision figure failed: see " + log);
  }
  if (o.json) {
    std::cout << j.dump(2) << "\n";
  } else {
    std::cout << "scene " << sf.scene.name << ": reference full/rk8pd rtol " << wp.reference_rtol
              << ", l_Delta = " << t.reference_l_Delta << ", spread vs modal " << t.reference_spread << "\n";
    std::cout << std::setw(8) << "level" << std::setw(12) << "stepper" << std::setw(8) << "rtol" << std::setw(12)
              << "RHS evals" << std::setw(10) << "Jac" << std::setw(11) << "seconds" << std::setw(12) << "err Delta"
              << std::setw(12) << "err sigma" << "  l_Delta\n";
    for (const auto& r : t.rows)
      std::cout << std::setw(8) << to_string(r.level) << std::setw(12) << to_string(r.stepper) << std::setw(8)
                << std::setprecision(0) << std::scientific << r.rtol << std::defaultfloat << std::setprecision(4)
                << std::setw(12) << r.rhs_evaluations << std::setw(10) << r.jacobian_evaluations << std::setw(11)
                << r.seconds << std::setw(12) << r.error_Delta << std::setw(12) << r.error_sigma << "  " << r.l_Delta
                << (r.verdict_changed ? " (changed)" : "")
                << (r.status != IntegrationStatus::success ? "  " + to_string(r.status) : "") << "\n";
    std::cout << "wrote " << base << ".csv, .json" << (o.plot ? ", .png" : "") << "\n";
  }
  return kOk;
}

int run_truncation(const BenchOptions& o, const SceneFile& sf) {
  if (o.Ls.empty()) throw InvalidArgument("--Ls", "--Ls is empty: must list at least one L (the last is the reference)");
  for (int L : o.Ls) require_L(L, kMinL, kMaxL, {}, "--Ls");
  // Reference: the last L. The modal level is exact at every L, so differences are truncation alone.
  const ProgressCallback progress = o.progress.callback("bench truncation:", "runs");
  std::vector<SimulationResult> runs;
  for (int L : o.Ls) {
    Scene s = sf.scene;
    s.L = L;
    s.dt = s.T;
    SimulationOptions so = sf.options;
    so.integrator.rtol = std::min(so.integrator.rtol, 1e-10);
    so.integrator.atol = std::min(so.integrator.atol, 1e-14);
    so.record_trajectory = false;
    runs.push_back(simulate(s, so));
    if (progress) progress(double(runs.size()), double(o.Ls.size()));
  }
  const SimulationResult& ref = runs.back();
  const Parameters& p = sf.scene.parameters;
  const bool reference_ok = ref.status == IntegrationStatus::success;
  nlohmann::json rows = nlohmann::json::array();
  std::ostringstream csv;
  csv << std::setprecision(10) << "L,status,l_Delta,sigma_final,error_Delta,error_sigma,rhs_evaluations,seconds\n";
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const SimulationResult& r = runs[i];
    double e = 0;
    for (std::size_t k = 0; k < r.Delta_final.size(); ++k) e = std::max(e, std::abs(r.Delta_final[k] - ref.Delta_final[k]));
    for (std::size_t k = r.Delta_final.size(); k < ref.Delta_final.size(); ++k) e = std::max(e, ref.Delta_final[k]);
    e /= sf.scene.parameters.Delta;
    double es = std::abs(r.sigma_final - ref.sigma_final) / std::max(1.0, std::abs(ref.sigma_final));
    // An error against a reference that stopped measures nothing.
    if (!reference_ok) e = es = kNaN;
    csv << o.Ls[i] << ',' << to_string(r.status) << ',' << r.l_Delta << ',' << csv_number(r.sigma_final) << ','
        << csv_number(e) << ',' << csv_number(es) << ',' << r.counters.rhs_evaluations << ',' << csv_number(r.seconds)
        << '\n';
    nlohmann::json row{{"L", o.Ls[i]}, {"status", to_string(r.status)}, {"reason", r.reason}, {"l_Delta", r.l_Delta},
                       {"rhs_evaluations", r.counters.rhs_evaluations}, {"seconds", r.seconds}};
    const std::string why = row_reason(r.status, r.reason, p);
    put_number(row, "sigma_final", r.sigma_final, why);
    const std::string error_why =
        reference_ok ? why : "the reference (L = " + std::to_string(o.Ls.back()) + ") " + row_reason(ref.status, ref.reason, p);
    put_number(row, "error_Delta", e, error_why);
    put_number(row, "error_sigma", es, error_why);
    rows.push_back(row);
  }
  std::filesystem::create_directories(o.output);
  const std::string base = o.output + "/" + sf.scene.name + "_truncation";
  nlohmann::json j{{"scene", to_json(sf.scene)}, {"reference_L", o.Ls.back()}, {"rows", rows}};
  put_truncation(j, sf);
  write_files_atomic({{base + ".csv", csv.str(), "--output"}, {base + ".json", j.dump(2) + "\n", "--output"}});
  std::cout << (o.json ? j.dump(2) + "\n" : csv.str());
  if (reference_ok) return kOk;
  std::cerr << "rbcstab: the truncation reference (L = " << o.Ls.back() << ") failed: "
            << row_reason(ref.status, ref.reason, p) << "\n";
  return kRunFailed;
}

void plot(const BenchOptions& o, const std::string& script, const std::string& base, const std::string& title) {
  if (!o.plot) return;
  check_python("/usr/bin/python3");
  const std::string dir = find_script_dir("");
  if (dir.empty()) throw std::runtime_error("cannot find the plotting scripts (set RBCSTAB_DATA_DIR)");
  const std::string log = base + ".plot.log";
  if (run_process({"/usr/bin/python3", dir + "/" + script, base + ".csv", base + ".png", title}, log) != 0)
    throw std::runtime_error("the figure failed: see " + log);
}

int run_threshold(const BenchOptions& o, const SceneFile& sf) {
  if (o.ln_C_range.size() != 2)
    throw InvalidArgument("--lnC-range", "--lnC-range takes two numbers (lo hi), got " + std::to_string(o.ln_C_range.size()));
  if (!(o.ln_C_range[0] < o.ln_C_range[1]))
    throw InvalidArgument("--lnC-range", "--lnC-range = " + format_value(o.ln_C_range[0]) + " " +
                                             format_value(o.ln_C_range[1]) + ": needs lo < hi (finite)");
  ThresholdPrecisionOptions tp;
  tp.ln_C_lo = o.ln_C_range[0];
  tp.ln_C_hi = o.ln_C_range[1];
  tp.on_progress = o.progress.callback("bench threshold:", "rows");
  const ThresholdPrecision t = threshold_precision(sf.scene, tp);
  std::ostringstream csv;
  csv << std::setprecision(12)
      << "predictor,method,rtol,budget,ln_C,error,evaluations,rhs_evaluations,seconds,status\n";
  nlohmann::json rows = nlohmann::json::array(), refs = nlohmann::json::array();
  // A number is missing only with a status other than "ok", which says why.
  auto why = [&](const std::string& status) { return status == "ok" ? nonfinite_reason(sf.scene.parameters) : status; };
  for (const auto& r : t.rows) {
    csv << r.predictor << ',' << r.method << ',' << csv_number(r.rtol) << ',' << r.budget << ',' << csv_number(r.ln_C)
        << ',' << csv_number(r.error) << ',' << r.evaluations << ',' << r.rhs_evaluations << ','
        << csv_number(r.seconds) << ",\"" << r.status << "\"\n";
    nlohmann::json row{{"predictor", r.predictor}, {"method", r.method}, {"rtol", r.rtol}, {"budget", r.budget},
                       {"evaluations", r.evaluations}, {"rhs_evaluations", r.rhs_evaluations}, {"seconds", r.seconds},
                       {"status", r.status}};
    put_number(row, "ln_C", r.ln_C, why(r.status));
    std::string error_why = why(r.status);
    for (const auto& ref : t.references)
      if (ref.predictor == r.predictor && ref.status != "ok") error_why = "no reference: " + ref.status;
    put_number(row, "error", r.error, error_why);
    rows.push_back(row);
  }
  for (const auto& r : t.references) {
    nlohmann::json ref{{"predictor", r.predictor}, {"status", r.status},
                       {"rtol", r.predictor == "asymptotic" ? 0.0 : tp.reference_rtol}};
    put_number(ref, "ln_C", r.ln_C, why(r.status));
    put_number(ref, "bracket", r.bracket, why(r.status));
    refs.push_back(ref);
  }
  std::filesystem::create_directories(o.output);
  const std::string base = o.output + "/" + sf.scene.name + "_threshold";
  nlohmann::json j{{"scene", to_json(sf.scene)}, {"B", t.B}, {"ln_C_range", o.ln_C_range},
                   {"references", refs}, {"rows", rows}};
  put_truncation(j, sf);
  write_files_atomic({{base + ".csv", csv.str(), "--output"}, {base + ".json", j.dump(2) + "\n", "--output"}});
  std::ostringstream title;
  title << "critical C at B = " << t.B << ": " << sf.scene.name;
  plot(o, "threshold_precision.py", base, title.str());
  // A reference that could not be computed makes every error meaningless: the run failed (exit 1), not the input.
  int rc = kOk;
  for (const auto& r : t.references)
    if (r.status != "ok") {
      std::cerr << "rbcstab: " << r.predictor << " reference failed: " << r.status << "\n";
      rc = kRunFailed;
    }
  if (o.json) {
    std::cout << j.dump(2) << "\n";
    return rc;
  }
  std::cout << std::setprecision(12) << "critical ln C at B = " << t.B << " (scene " << sf.scene.name << ")\n";
  for (const auto& r : t.references)
    std::cout << "  reference " << std::setw(15) << r.predictor << ": ln C = " << r.ln_C << " (bracket " << r.bracket
              << ")" << (r.status == "ok" ? "" : "  " + r.status) << "\n";
  std::cout << std::setprecision(4) << std::setw(15) << "predictor" << std::setw(12) << "method" << std::setw(8) << "rtol"
            << std::setw(8) << "budget" << std::setw(12) << "error" << std::setw(8) << "evals" << std::setw(12) << "RHS"
            << std::setw(11) << "seconds\n";
  for (const auto& r : t.rows)
    std::cout << std::setw(15) << r.predictor << std::setw(12) << r.method << std::setw(8) << r.rtol << std::setw(8)
              << r.budget << std::setw(12) << r.error << std::setw(8) << r.evaluations << std::setw(12)
              << r.rhs_evaluations << std::setw(11) << r.seconds << (r.status == "ok" ? "" : "  " + r.status) << "\n";
  std::cout << "wrote " << base << ".csv, .json" << (o.plot ? ", .png" : "") << "\n";
  return rc;
}

int run(const BenchOptions& o) {
  const SceneFile sf = o.scene.resolve(TruncationUse::measurement);
  if (o.kind == "truncation") return run_truncation(o, sf);
  if (o.kind == "threshold") return run_threshold(o, sf);
  return run_work_precision(o, sf);
}
}  // namespace

static Runner add_bench(CLI::App& app) {
  auto o = std::make_shared<BenchOptions>();
  app.add_option("kind", o->kind, "what to measure")
      ->check(CLI::IsMember({"work-precision", "truncation", "threshold"}))
      ->capture_default_str();
  o->scene.add_to(app);
  app.add_option("--output", o->output, "folder for the CSV, JSON and PNG")->capture_default_str();
  app.add_option("--levels", o->levels, "model levels to compare (work-precision)")->delimiter(',')->capture_default_str();
  app.add_option("--steppers", o->steppers, "steppers to compare (work-precision)")->delimiter(',')->capture_default_str();
  app.add_option("--rtols", o->rtols, "tolerances (work-precision), each in [1e-14, 0.1]")
      ->delimiter(',')
      ->capture_default_str();
  app.add_option("--Ls", o->Ls, "truncations (truncation), each an integer in [2, 100]; the last is the reference")
      ->delimiter(',')
      ->capture_default_str();
  app.add_option("--max-seconds", o->max_seconds, "wall-clock budget per run (> 0)")->capture_default_str();
  app.add_option("--lnC-range", o->ln_C_range, "bracket of the critical ln C at the scene's B (threshold)")
      ->expected(2)
      ->capture_default_str();
  app.add_flag("!--no-plot", o->plot, "skip the PNG figure");
  app.add_flag("--json", o->json, "print the table as JSON");
  o->progress.add_flags(app);
  return [o] { return run(*o); };
}

namespace {
const RegisterCommand kRegisterBench{"bench", "Speed against accuracy: work-precision, truncation in L, threshold precision",
                                add_bench, 80};
}  // namespace

}  // namespace rbcstab::cli
