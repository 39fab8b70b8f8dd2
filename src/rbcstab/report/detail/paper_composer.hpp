#pragma once
// What every figure of the paper is composed with (module-private): the Composer, which runs the scenes (curves
// to T, phase diagrams as their report panels), writes the data behind each figure and collects its drawing spec
// and its claims; the runs it returns (Line, Diagram); and the number formats of the claims' text.
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <functional>
#include <iomanip>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "rbcstab/core/error.hpp"
#include "rbcstab/core/parallel.hpp"
#include "rbcstab/integrate/simulation.hpp"
#include "rbcstab/io/files.hpp"
#include "rbcstab/io/scene_file.hpp"
#include "rbcstab/io/simulation_io.hpp"
#include "rbcstab/report/panels.hpp"
#include "rbcstab/report/paper.hpp"
#include "rbcstab/report/paper_checks.hpp"
#include "rbcstab/report/report.hpp"
#include "rbcstab/sweep/agreement.hpp"
#include "rbcstab/sweep/diagram.hpp"
#include "rbcstab/sweep/diagram_document.hpp"
#include "rbcstab/sweep/diagram_table.hpp"
#include "rbcstab/sweep/trace.hpp"
#include "rbcstab/verdict/certified_run.hpp"

namespace rbcstab::detail::paper {

namespace fs = std::filesystem;
using nlohmann::json;

// Numbers in the claims and captions: `digits` significant digits; a fraction as a percentage.
inline std::string num(double v, int digits = 4) {
  std::ostringstream ss;
  ss << std::setprecision(digits) << v;
  return ss.str();
}
inline std::string pct(double v) { return num(100 * v, 3) + "%"; }

// A run drawn as curves: integrated to T on the scene's output grid, its trajectory written as CSV.
struct Line {
  SceneFile file;
  SimulationResult run;
  std::string csv;  // relative to the output folder
  const std::vector<double>& t() const { return run.trajectory.t; }
  std::vector<double> Delta(int l) const {
    std::vector<double> v;
    for (const auto& d : run.trajectory.Delta_l) v.push_back(l - 2 < int(d.size()) ? d[std::size_t(l - 2)] : 0.0);
    return v;
  }
  std::vector<double> Delta_above2() const {  // sum of Delta_l, l >= 3
    std::vector<double> v;
    for (const auto& d : run.trajectory.Delta_l) {
      double s = 0;
      for (std::size_t k = 1; k < d.size(); ++k) s += d[k];
      v.push_back(s);
    }
    return v;
  }
};

struct Diagram {
  SceneFile file;
  DiagramSpec spec;
  std::vector<PointResult> points;
  std::vector<Agreement> agreements;
  std::string csv, overlay;  // relative
  std::size_t unstable(const std::function<bool(const PointResult&)>& where = {}) const {
    std::size_t n = 0;
    for (const auto& p : points) n += p.verdict == Verdict::unstable && (!where || where(p));
    return n;
  }
};

class Composer {
 public:
  Composer(const PaperOptions& o, fs::path dir, PaperResult& res) : o_(o), dir_(std::move(dir)), res_(res) {
    threads_ = o.threads > 0 ? o.threads : std::max(1, int(std::thread::hardware_concurrency()));
  }
  json figures = json::array();

  bool stopped() const { return o_.stop && o_.stop->load(); }

  void begin(const std::string& id, const std::string& title, const std::string& figure_label, int k, int n) {
    if (o_.on_step) o_.on_step(title, k, n);
    current_ = PaperFigure{id, title, {}, 0};
    label_ = figure_label;
    start_ = std::chrono::steady_clock::now();
    fs::create_directories(dir_ / id);
  }
  // Closes the current figure: its drawing spec (panels in a grid) and its caption text.
  void end(json panels, int nrows, int ncols, int width, int height, const std::string& caption) {
    current_.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    figures.push_back({{"id", current_.id},
                       {"title", current_.title},
                       {"png", current_.id + ".png"},
                       {"svg", current_.id + ".svg"},  // the page opens it on a click (scales without blur)
                       {"size_px", {width, height}},
                       {"nrows", nrows},
                       {"ncols", ncols},
                       {"panels", panels},
                       {"caption", caption},
                       {"data", current_.data},
                       {"label", label_},
                       {"seconds", current_.seconds}});
    res_.figures.push_back(current_);
  }

  // A claim and its check; `inconsistency` (the evidence) is kept only if the check fails.
  void claim(const std::string& text, const paper_check::Check& check, const std::string& how,
             const std::string& inconsistency = "") {
    res_.claims.push_back({label_, text, check.measured, check.expected, check.passed, how, check.name,
                           check.passed ? "" : inconsistency});
  }

  // A run made outside lines() and diagram(): counted in failed_runs unless it reached T.
  void count_run(bool reached_T) { res_.failed_runs += !reached_T; }

  std::string put(const std::string& name, const std::string& text) {
    const std::string rel = current_.id + "/" + name;
    write_file_atomic((dir_ / rel).string(), text);
    current_.data.push_back(rel);
    res_.files.push_back(rel);
    return rel;
  }

  SceneFile scene(const std::string& name) const {
    return load_scene((fs::path(scene_dir_) / (name + ".toml")).string());
  }
  void set_scene_dir(std::string d) { scene_dir_ = std::move(d); }

  // The named scenes (and, with companions, each one's reduced companion after them) run to T in parallel.
  std::vector<Line> lines(const std::vector<std::string>& names, bool companions = false) {
    std::vector<Line> out;
    // Built member by member: GCC 12 warns (maybe-uninitialized, a false positive) on {file, {}, {}}.
    for (const auto& n : names) {
      out.emplace_back().file = scene(n);
      if (companions) {
        SceneFile c = out.back().file;
        c.scene = reduced_scene(c.scene);
        out.emplace_back().file = std::move(c);
      }
    }
    parallel_for(out.size(), threads_, [&](std::size_t k) {
      SimulationOptions so = out[k].file.options;
      so.full_horizon = true;  // the whole trajectory is drawn
      so.record_trajectory = true;
      so.trajectory_text = true;
      out[k].run = simulate_scene(out[k].file, so);
    });
    for (auto& l : out) {
      res_.failed_runs += l.run.status != IntegrationStatus::success;
      l.csv = put(l.file.scene.name + ".csv", trajectory_csv(l.run));
    }
    return out;
  }

  // A phase-diagram scene run as its `rbcstab report` panel runs it (quick: a 12 x 12 grid), with the traced
  // boundary, the paper's analytic lines and every predictor's agreement (each plane traced once: the agreement
  // measures against the drawn boundary).
  Diagram diagram(const std::string& name, const std::string& step) {
    Diagram d{scene(name), {}, {}, {}, {}, {}};
    apply_truncation(d.file, truncation_use(PanelKind::diagram));
    d.spec = diagram_spec(d.file);
    if (o_.quick) d.spec.x.count = d.spec.y.count = 12;
    d.spec.validate();
    DiagramOptions dopt;
    dopt.threads = threads_;
    dopt.stop = o_.stop;
    if (o_.on_progress) dopt.on_progress = o_.on_progress;
    if (o_.on_step) o_.on_step(step + ": " + name + " (" + std::to_string(d.spec.size()) + " points)", -1, -1);
    DiagramRun run = run_diagram(d.file.scene, d.file.options, d.spec, dopt);
    d.points = std::move(run.points);
    if (!run.complete) return d;
    for (const auto& p : d.points) res_.failed_runs += p.verdict == Verdict::failed;
    std::vector<TraceCurve> boundary;
    AgreementOptions ao;
    try {
      ao.asymptotic_boundary =
          std::make_shared<const TraceResult>(trace_boundary(d.file.scene, d.spec, ao.trace_options));
      boundary = ao.asymptotic_boundary->curves;
    } catch (const InvalidArgument&) {  // not traceable on this plane: the simulations and lines are drawn
    }
    ao.threads = threads_;
    d.agreements = predictor_agreements(d.file.scene, d.spec, d.points, ao);
    d.csv = put(name + ".csv", diagram_csv(d.spec, d.points, DiagramOutputOptions{false}));
    d.overlay = put(name + "_overlay.json",
                    phase_overlay_json(d.spec, boundary, analytic_overlays(d.file.scene, d.spec, 200)).dump(1) + "\n");
    return d;
  }

  bool quick() const { return o_.quick; }
  int threads() const { return threads_; }

 private:
  const PaperOptions& o_;
  fs::path dir_;
  PaperResult& res_;
  std::string scene_dir_;
  int threads_ = 1;
  PaperFigure current_;
  std::string label_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace rbcstab::detail::paper
