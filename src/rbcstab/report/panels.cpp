#include "rbcstab/report/panels.hpp"

#include "rbcstab/report/detail/parameter_labels.hpp"
#include "rbcstab/report/detail/staging.hpp"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <memory>
#include <optional>
#include <random>
#include <set>
#include <sstream>

#include "rbcstab/continuation/branch_io.hpp"
#include "rbcstab/continuation/scene_run.hpp"
#include "rbcstab/continuation/tunable_options.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/io/files.hpp"
#include "rbcstab/io/json.hpp"
#include "rbcstab/report/bifurcation_plot.hpp"
#include "rbcstab/sweep/diagram_document.hpp"
#include "rbcstab/sweep/diagram_table.hpp"
#include "rbcstab/sweep/sweep_io.hpp"
#include "rbcstab/verdict/verdict_io.hpp"

namespace rbcstab {

namespace fs = std::filesystem;

namespace {

// The table's numbers, each finite and > 0 (the grids of the Fig. 6e table).
std::vector<double> positive_list(const SceneTable& t, const char* key) {
  const std::vector<double> out = t.numbers(key, 0, "a non-empty array of numbers > 0");
  for (double x : out) require(std::isfinite(x) && x > 0, t.path(key), x, "finite numbers > 0");
  return out;
}

std::string csv_value(const Quantity& q) {
  if (!q.valid()) return "n/a";
  std::ostringstream ss;
  ss << std::setprecision(10) << q.value;
  return ss.str();
}

std::string fixed(double v, int digits = 1) {
  std::ostringstream ss;
  ss << std::fixed << std::setprecision(digits) << v;
  return ss.str();
}

// Staging folder for the panel's data (a hidden sibling of the report folder), removed at the end.
struct Staging {
  fs::path dir;
  explicit Staging(const std::string& output) {
    const fs::path out = fs::absolute(output).lexically_normal();
    const fs::path target = out.has_filename() ? out : out.parent_path();
    remove_stale_staging(target.parent_path().string(), target.filename().string(), ".panel-");
    std::random_device rd;
    std::ostringstream name;
    name << staging_prefix(target.filename().string(), ".panel-") << std::hex << rd() << rd();
    dir = target.parent_path() / name.str();
    std::error_code ec;
    fs::create_directory(dir, ec);
    if (ec) throw ReportError("output: cannot create " + dir.string() + ": " + ec.message());
  }
  ~Staging() {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
  Staging(const Staging&) = delete;
  Staging& operator=(const Staging&) = delete;
  std::string put(const std::string& name, const std::string& content) const {
    const std::string path = (dir / name).string();
    write_file_atomic(path, content);
    return path;
  }
};

std::string parameters_text(const Scene& s, bool with_lambda, bool with_BC) {
  using P = SceneParameter;
  std::string text;
  auto put = [&](P q) { text += (text.empty() ? "" : ", ") + detail::plain_value(q, get_parameter(s, q)); };
  if (with_lambda) put(P::lambda);
  put(P::Delta);
  put(P::Delta0);
  if (with_BC) {
    put(P::B);
    put(P::C);
  }
  put(P::beta);
  return text;
}

// Title parts in the paper's symbols (mathtext), for the figures; `varied` names what the panel varies.
std::string tex_parameters(const Scene& s, const std::set<std::string>& varied, bool with_BC, double alpha_fixed = 0) {
  std::string text;
  auto put = [&](SceneParameter q, double v) {
    if (!varied.count(to_string(q))) text += detail::tex_value(q, v) + ", ";
  };
  for (SceneParameter q : {SceneParameter::lambda, SceneParameter::Delta, SceneParameter::Delta0})
    put(q, get_parameter(s, q));
  if (with_BC)
    for (SceneParameter q : {SceneParameter::B, SceneParameter::C}) put(q, get_parameter(s, q));
  if (alpha_fixed > 0) put(SceneParameter::alpha, alpha_fixed);
  return text + (std::abs(std::cos(s.beta)) < 0.5 ? "in plane" : "out of plane");
}
}  // namespace

PanelKind panel_kind(const SceneFile& scene) {
  std::vector<PanelKind> found;
  for (auto [table, kind] : {std::pair{&scene.diagram, PanelKind::diagram}, std::pair{&scene.fig6e, PanelKind::fig6e},
                             std::pair{&scene.continuation, PanelKind::continuation},
                             std::pair{&scene.physical_map, PanelKind::physical_map}})
    if (table->has_value()) found.push_back(kind);
  if (found.size() > 1)
    throw InvalidArgument("scene", scene.source +
                                       " holds more than one panel table ([diagram], [fig6e], [continuation], "
                                       "[physical_map]): "
                                       "one figure panel per scene file");
  return found.empty() ? PanelKind::none : found[0];
}

TruncationUse truncation_use(PanelKind kind) {
  switch (kind) {
    case PanelKind::none:
      return TruncationUse::simulation;
    case PanelKind::diagram:
    case PanelKind::fig6e:
      return TruncationUse::grid;
    case PanelKind::continuation:
      return TruncationUse::reduced;
    case PanelKind::physical_map:  // the onset's asymptotic verdicts over l = 3..L, no simulation
      return TruncationUse::analysis;
  }
  return TruncationUse::simulation;
}

Fig6eOptions fig6e_options(const SceneFile& sf) {
  Fig6eOptions f;
  const Scene& s = sf.scene;
  f.Delta = s.parameters.Delta;
  f.Delta0 = s.parameters.Delta0;
  f.beta = s.beta;
  f.delta = s.delta;
  f.L = s.L;
  f.T = s.T;
  f.simulation = sf.options;
  f.simulation.record_trajectory = false;  // the table keeps tail means only
  if (const auto& t = sf.fig6e) {
    t->allow_only({"lambda", "B", "C"});
    if (t->has("lambda")) f.lambdas = positive_list(*t, "lambda");
    if (t->has("B")) f.B = positive_list(*t, "B");
    if (t->has("C")) f.C = positive_list(*t, "C");
  }
  f.validate();
  return f;
}

std::string fig6e_csv(const Fig6eOptions& f, const std::vector<Fig6eRow>& rows) {
  std::ostringstream ss;
  ss << "# Fig. 6e: Delta~2 (continuous l_*, integer l_s) vs simulated Delta-bar_2 (T = " << f.T << ", tail mean over "
     << f.simulation.tail_window << "); n/a: outside domain or stable\n";
  ss << "lambda,B,C,alpha,ln_alpha,l_s,l_Delta,Delta2_tilde,Delta2_tilde_integer,Delta2_bar,ratio,ratio_integer\n";
  for (const Fig6eRow& r : rows)
    ss << r.lambda << ',' << r.B << ',' << r.C << ',' << r.alpha << ',' << r.ln_alpha << ',' << r.surviving_mode << ','
       << r.l_Delta << ',' << csv_value(r.Delta2_tilde) << ',' << csv_value(r.Delta2_tilde_integer) << ','
       << csv_value(r.Delta2_bar) << ',' << csv_value(r.ratio) << ',' << csv_value(r.ratio_integer) << '\n';
  return ss.str();
}

ContinuationPanel continuation_panel(const SceneFile& sf) {
  ContinuationPanel c;
  if (!sf.continuation) return c;
  c.engine.direction = Direction::both;
  const SceneTable& t = *sf.continuation;
  std::set<std::string> keys{"parameter",  "min",     "max",     "direction", "measure",
                             "max_points", "relax_T", "monitor", "stop_at"};
  for (const TunableOption& o : tunable_options())
    if (!o.orbit) keys.insert(o.keyword());  // the panel's branch is of equilibria: no shooting options
  t.allow_only(keys);
  if (t.has("parameter")) {
    try {
      c.parameter = continuation_parameter_from_string(t.text("parameter"));
    } catch (const InvalidArgument& e) {
      if (e.parameter() == t.path("parameter")) throw;
      throw InvalidArgument(t.path("parameter"), t.path("parameter") + ": " + e.what());
    }
  }
  if (t.has("min")) c.engine.p_min = t.number("min");
  if (t.has("max")) c.engine.p_max = t.number("max");
  require(!(c.engine.p_min >= c.engine.p_max), "continuation.max", c.engine.p_max, "> continuation.min");
  if (t.has("direction")) {
    c.engine.direction = from_string<Direction>(t.text("direction"), "continuation.direction");
  }
  if (t.has("measure")) {
    c.measure = t.text("measure");
    if (c.measure != "r" && c.measure != "Psi")
      throw InvalidArgument("continuation.measure", "continuation.measure = '" + c.measure + "' must be r or Psi");
  }
  OrbitOptions unused;
  for (const TunableOption& o : tunable_options()) {
    if (o.orbit || !t.has(o.keyword())) continue;
    const double v = t.number(o.keyword());
    try {
      o.check(v);
    } catch (const InvalidArgument& e) {
      throw InvalidArgument(t.path(o.keyword()), t.path(o.keyword()) + ": " + e.what());
    }
    o.set(c.engine, unused, v);
  }
  const auto texts = [&t](const char* key) {
    return t.has(key) ? t.texts(key, 0, "a list of \"NAME=V1,V2,...\" strings") : std::vector<std::string>{};
  };
  try {
    c.monitors = parse_monitors(texts("monitor"), texts("stop_at"), t.path("monitor"), t.path("stop_at"));
  } catch (const InvalidArgument& e) {
    throw InvalidArgument(e.parameter(), e.parameter() + ": " + e.what());
  }
  if (t.has("max_points")) {
    const long long n = t.integer("max_points");
    require(n >= 2 && n <= 1'000'000, "continuation.max_points", double(n), "an integer in [2, 1000000]");
    c.engine.max_points = std::size_t(n);
  }
  if (t.has("relax_T")) c.relax_T = t.number("relax_T");
  require(std::isfinite(c.relax_T) && c.relax_T >= 0, "continuation.relax_T", c.relax_T, "finite and >= 0");
  try {
    c.engine.validate();
  } catch (const InvalidArgument& e) {
    throw InvalidArgument("continuation", std::string("continuation: ") + e.what());
  }
  return c;
}

BranchSpec branch_spec(const ContinuationPanel& panel, const Scene& scene) {
  BranchSpec spec;
  spec.scene = scene;
  spec.kind = ProblemKind::equilibrium;
  spec.parameter = panel.parameter;
  spec.engine = panel.engine;
  spec.monitors = panel.monitors;
  spec.relax_T = panel.relax_T;
  return spec;
}

nlohmann::json bifurcation_json(const SceneBranch& branch, const std::string& measure) {
  nlohmann::json j = to_json(branch);
  j["measure"] = measure;
  return j;
}

nlohmann::json phase_overlay_json(const DiagramSpec& spec, const std::vector<TraceCurve>& boundary,
                                  const std::vector<Overlay>& lines) {
  nlohmann::json curves = nlohmann::json::array();
  std::set<int> labelled;
  for (const TraceCurve& c : boundary) {
    std::vector<double> x, y;
    for (const TracePoint& p : c.points) x.push_back(p.x), y.push_back(p.y);
    nlohmann::json j{{"x", x}, {"y", y}, {"style", "solid"}, {"color", "black"}, {"width", 2.2}};
    // One legend entry for the whole traced boundary (its pieces differ only in the active mode).
    if (labelled.insert(0).second) j["label"] = "traced boundary (asymptotic criterion)";
    curves.push_back(j);
  }
  for (const Overlay& o : lines) {
    if (o.x.empty()) continue;
    nlohmann::json j{{"x", o.x}, {"y", o.y}};
    if (o.name.rfind("l_star=", 0) == 0) {
      // As the paper's Fig. 4: l_* = 2.5 solid, the transitions to the next l dashed.
      j["label"] = "$l_* = " + o.name.substr(7) + "$";
      j["style"] = o.name == "l_star=2.5" ? "solid" : "dashed";
      j["color"] = "0.25";
      j["width"] = o.name == "l_star=2.5" ? 1.4 : 1.0;
      j["label_on_line"] = true;  // many parallel lines: label them in place rather than in the legend
    } else if (o.name == "alpha_init") {
      j["label"] = "$\\alpha_*^{\\mathrm{init}}$";
      j["style"] = "dashdot";
      j["color"] = "tab:blue";  // the paper's blue line; dash-dotted for greyscale
    } else if (o.name == "C_star_minus") {
      j["label"] = "$\\mathcal{C}_*^-$";
      j["style"] = "dotted";
      j["color"] = "tab:red";
      j["width"] = 2.2;
    } else if (o.name == "C_star_plus") {
      j["label"] = "$\\mathcal{C}_*^+$";
      j["style"] = "dashed";
      j["color"] = "tab:red";
    } else if (o.name == "lambda_star_minus") {
      j["label"] = "$\\lambda_*^-$";
      j["style"] = "dashed";
      j["color"] = "tab:red";
    } else {
      j["label"] = o.name;
      j["style"] = "dotted";
    }
    curves.push_back(j);
  }
  nlohmann::json doc{{"axes", {{"x", tex_symbol(to_string(spec.x.axis))}, {"y", tex_symbol(to_string(spec.y.axis))}}},
                     {"curves", curves}};
  explain_nulls(doc, "undefined there: the line's formula is outside its domain (drawn as a gap)");
  return doc;
}

void PanelOptions::validate() const {
  require(threads >= 0 && threads <= 4096, "threads", threads, "an integer in [0, 4096] (0: all cores)");
  require(nx >= 0 && nx <= 1'000'000, "counts", nx, "integers in [1, 1000000] (0: the scene's)");
  require(ny >= 0 && ny <= 1'000'000, "counts", ny, "integers in [1, 1000000] (0: the scene's)");
  trace.validate();
}

PanelReportResult build_panel_report(const SceneFile& sf, const PanelOptions& panel, const ReportOptions& options) {
  // The hooks draw other commands' data into a scene's report; a panel draws what it computes, in their place.
  for (const std::string* hook :
       {&options.phase_diagram, &options.delta2_comparison, &options.bifurcation, &options.physical_map})
    if (!hook->empty())
      throw InvalidArgument("phase_diagram",
                            "--phase-diagram, --delta2-comparison and --bifurcation draw data from "
                            "other commands into a scene report; a panel scene computes its own");
  panel.validate();
  options.validate();
  sf.scene.validate();
  sf.options.validate();
  PanelReportResult res;
  res.kind = panel_kind(sf);
  if (res.kind == PanelKind::none)
    throw InvalidArgument("scene",
                          sf.source + " holds no panel table ([diagram], [fig6e], [continuation] or [physical_map])");
  // Refuse what build_report would refuse before computing anything (a grid can take hours).
  check_python(options.python);
  detail::output_target(options.output, options.overwrite);
  ReportOptions ro = options;
  ro.run_scene = false;
  ro.scene_toml = sf.text;
  const auto t0 = std::chrono::steady_clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };
  Staging staging(options.output);
  std::ostringstream summary;
  summary << std::setprecision(4);

  if (res.kind == PanelKind::diagram) {
    DiagramSpec spec = diagram_spec(sf);
    if (panel.nx > 0) spec.x.count = panel.nx;
    if (panel.ny > 0) spec.y.count = panel.ny;
    spec.validate();
    DiagramOptions dopt;
    dopt.threads = panel.threads;
    dopt.on_progress = panel.on_progress;
    dopt.stop = panel.stop;
    const DiagramRun run = run_diagram(sf.scene, sf.options, spec, dopt);
    if (!run.complete) {
      res.complete = false;
      res.status = "interrupted";
      return res;
    }
    for (const PointResult& p : run.points) res.failed += p.verdict == Verdict::failed;
    std::size_t unstable = 0;
    for (const PointResult& p : run.points) unstable += p.verdict == Verdict::unstable;
    const double diagram_seconds = run.seconds;
    // The traced boundary of the asymptotic criterion (sweep/trace.hpp): the exact equilibrium out of plane,
    // the period average over the attracting periodic orbit in plane (time average where there is none).
    // Where the library cannot trace (e.g. an unconverged average) the panel shows the simulations and the
    // analytic lines, and says why.
    std::vector<TraceCurve> boundary;
    std::shared_ptr<const TraceResult> traced;  // drawn, and the agreement's asymptotic boundary
    std::string trace_note;
    // With beta on an axis the plane crosses from out of plane to in plane (the criterion's source changes
    // along it): not traced. In plane a ln B plane is traced in closed form in B (App. E: ~0.4 s).
    const bool traceable = spec.x.axis != Axis::beta && spec.y.axis != Axis::beta;
    if (!traceable)
      trace_note =
          "not traced: beta on an axis (the plane mixes in- and out-of-plane criteria; "
          "try `rbcstab trace`)";
    else
      try {
        traced = std::make_shared<const TraceResult>(trace_boundary(sf.scene, spec, panel.trace));
        const TraceResult& tr = *traced;
        boundary = tr.curves;
        trace_note = std::to_string(tr.curves.size()) + " pieces, " + std::to_string(tr.corners.size()) +
                     " mode corners, " + std::to_string(tr.evaluations) + " criterion evaluations, " +
                     fixed(tr.seconds, 2) + " s";
      } catch (const InvalidArgument& e) {
        trace_note = std::string("not traced: ") + e.what();
      }
    const std::vector<Overlay> lines =
        analytic_overlays(sf.scene, spec, 200);  // 200 samples per line: smooth at 900 px
    // Without the per-point wall-clock seconds: the data behind the figure is the same on every run.
    ro.phase_diagram = staging.put("phase_diagram.csv", diagram_csv(spec, run.points, DiagramOutputOptions{false}));
    staging.put("phase_diagram.json", phase_overlay_json(spec, boundary, lines).dump(1) + "\n");
    AgreementOptions ao;
    ao.threads = panel.threads;
    ao.trace_options = panel.trace;
    if (panel.trace.criterion == TraceCriterion::asymptotic) ao.asymptotic_boundary = traced;
    ao.trace_in_plane = true;
    nlohmann::json doc = diagram_document(sf, spec, run.points, Shard{}, {},
                                          traceable ? std::optional<AgreementOptions>(ao) : std::nullopt);
    if (!traceable) doc["agreement_reason"] = trace_note;
    ro.attachments.push_back(staging.put("diagram.json", doc.dump(1) + "\n"));
    res.status = res.failed ? "failed runs" : "success";
    res.facts = {{"grid", std::to_string(spec.x.count) + " x " + std::to_string(spec.y.count) + " (" +
                              parameter_label(spec.x.axis) + " in [" + fixed(spec.x.min, 3) + ", " +
                              fixed(spec.x.max, 3) + "], " + parameter_label(spec.y.axis) + " in [" +
                              fixed(spec.y.min, 3) + ", " + fixed(spec.y.max, 3) + "])"},
                 {"classifier", to_string(spec.classifier)},
                 {"unstable points", std::to_string(unstable)},
                 {"failed points", std::to_string(res.failed)},
                 {"diagram wall time [s]", fixed(diagram_seconds)},
                 {"traced boundary", trace_note},
                 {"analytic lines", std::to_string(lines.size())}};
    if (doc["agreement"].is_object() && doc["agreement"].value("verdict_fraction", nlohmann::json()).is_number())
      res.facts.push_back({"asymptotic criterion agrees (verdict / mode)",
                           fixed(100 * doc["agreement"]["verdict_fraction"].get<double>()) + "% / " +
                               fixed(100 * doc["agreement"]["mode_fraction"].get<double>()) + "%"});
    summary << "Phase diagram by direct simulation (modal level, L = " << sf.scene.L << ", T = " << sf.scene.T
            << ") over " << parameter_label(spec.x.axis) << " and " << parameter_label(spec.y.axis)
            << ", coloured by l_Delta (" << to_string(spec.classifier)
            << " classifier), with the traced stability boundary and the paper's "
            << "analytic lines. Base scene: "
            << parameters_text(sf.scene, spec.x.axis != Axis::lambda && spec.y.axis != Axis::lambda, false) << ".";
    ro.figure_title = sf.scene.name + ": " +
                      tex_parameters(sf.scene, {to_string(spec.x.axis), to_string(spec.y.axis)}, false, spec.alpha);
  } else if (res.kind == PanelKind::fig6e) {
    const Fig6eOptions f = fig6e_options(sf);
    const std::vector<Fig6eRow> rows = fig6e_table(f);
    std::size_t compared = 0;
    for (const Fig6eRow& r : rows) {
      compared += r.ratio.valid();
      // A row whose run did not finish says so in its reason (a stable run is not a failure).
      res.failed += !r.Delta2_bar.valid() && r.l_Delta != 2;
    }
    ro.delta2_comparison = staging.put("fig6e.csv", fig6e_csv(f, rows));
    res.status = res.failed ? "failed runs" : "success";
    res.facts = {{"rows (lambda x B x C)", std::to_string(rows.size())},
                 {"rows compared (unstable, theory defined)", std::to_string(compared)},
                 {"rows without a simulated value (failed or stable)", std::to_string(rows.size() - compared)},
                 {"T, L", fixed(f.T, 0) + ", " + std::to_string(f.L)}};
    summary << "Fig. 6e: the post-instability excess area Delta~2 of Eq. ss (continuous l_*) against the simulated "
            << "long-time mean Delta-bar_2, over lambda, B and C (" << rows.size() << " runs, Delta = " << f.Delta
            << ", Delta0 = " << f.Delta0 << ", beta = " << f.beta << ").";
    ro.figure_title = sf.scene.name + ": " + tex_parameters(sf.scene, {"lambda"}, false);
  } else if (res.kind == PanelKind::physical_map) {
    const PhysicalMapPanel p = physical_map_panel(sf);
    PhysicalMapOptions o = p.options;
    o.threads = panel.threads;
    if (p.healthy_spreads) o.spreads = healthy_cell_spreads(sf.scene);
    const PhysicalMap map = physical_map(sf.scene, o);
    const std::string file = shipped_observations(executable_path());
    const std::vector<PublishedObservation> observed =
        file.empty() ? std::vector<PublishedObservation>{} : read_observations(file);
    ro.physical_map = staging.put("physical_map.json", to_json(map, observed, file).dump(1) + "\n");
    PhysicalMapPage page = physical_map_page(map, observed, file);
    res.facts = std::move(page.facts);
    ro.panel_tables = std::move(page.tables);
    res.status = "success";
    summary << "Physical phase diagram of the scene's cell: where it tumbles, swings and where the l >= 3 modes "
            << "grow, over outer viscosity and shear rate (" << map.columns.size() << " viscosities; bands: "
            << (o.spreads.empty() ? "none computed" : "the published ranges of the cell's properties")
            << "), with the published observations drawn over it and where the model's assumptions fail.";
    ro.figure_title = sf.scene.name + ": physical phase diagram" +
                      (o.spreads.empty() ? " (nominal cell; no bands computed)"
                                         : " (bands: published ranges of the cell's properties)");
  } else {
    const ContinuationPanel c = continuation_panel(sf);
    const SceneBranch r = continue_scene(branch_spec(c, sf.scene));  // throws InvalidArgument("beta") if forced
    const Branch& b = r.branch.branch;
    const std::string name = to_string(c.parameter);
    ro.bifurcation = staging.put("bifurcation.json", bifurcation_json(r, c.measure).dump(1) + "\n");
    ro.bifurcation_y = c.measure;  // drawn by plot_spec, as `rbcstab plot --y`
    res.status = to_string(b.status);
    res.failed = !ended_normally(b.status);
    std::string specials;
    for (const SpecialPoint& sp : b.special_points) {
      std::ostringstream ss;
      ss << std::setprecision(8) << to_string(sp.type) << " at " << name << " = " << sp.p;
      specials += (specials.empty() ? "" : "; ") + ss.str();
    }
    res.facts = {{"points", std::to_string(b.points.size())},
                 {"status", res.status + (b.message.empty() ? "" : " (" + b.message + ")")},
                 {"special points", specials.empty() ? "none" : specials},
                 {"Newton iterations", std::to_string(b.counters.newton_iterations)}};
    summary << "Bifurcation diagram: equilibria of the reduced system (out-of-plane rest shape) continued in " << name
            << " from " << r.start.p << ", " << c.measure << " against " << name
            << "; stable solid, unstable dashed, special points (AUTO-07p labels) marked. "
            << "Base scene: " << parameters_text(sf.scene, c.parameter != ContinuationParameter::lambda, true) << ".";
    // Lambda moves Delta, S moves C (parameters.hpp): those are varied too.
    std::set<std::string> varied{name};
    if (c.parameter == ContinuationParameter::Lambda) varied.insert("Delta");
    if (c.parameter == ContinuationParameter::S) varied.insert("C");
    ro.figure_title = sf.scene.name + ": " + tex_parameters(sf.scene, varied, true);
  }
  res.compute_seconds = elapsed();
  res.facts.push_back({"computation wall time [s]", fixed(res.compute_seconds)});
  ro.panel_summary = summary.str();
  ro.panel_facts = res.facts;
  res.report = build_report(sf, ro);
  return res;
}

}  // namespace rbcstab
