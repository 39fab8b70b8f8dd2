// Parameter-plane sweeps, as the CLI's diagram, trace and post --fig6e: the same library calls (plane_spec,
// run_diagram, trace_boundary, fig6e_table) and the same serialisers (diagram_document, trace_json, fig6e_json),
// so a result's document equals the file or --json the CLI writes. The GIL is released while they compute;
// Ctrl-C stops them (KeyboardInterrupt) with a journal, if any, left valid and resumable.
#include <pybind11/stl.h>

#include <algorithm>
#include <atomic>
#include <climits>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "bindings.hpp"
#include "rbcstab/analysis/truncation.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/io/experiments.hpp"
#include "rbcstab/io/files.hpp"
#include "rbcstab/io/json.hpp"
#include "rbcstab/report/panels.hpp"
#include "rbcstab/report/report.hpp"
#include "rbcstab/sweep/diagram_document.hpp"
#include "rbcstab/sweep/diagram_table.hpp"
#include "rbcstab/sweep/sweep_io.hpp"
#include "rbcstab/verdict/verdict_io.hpp"

namespace rbcstab::python {

namespace {

// An integer keyword the library holds as int: a value beyond int is refused, not wrapped around.
int narrow(long long v, const char* name) {
  if (v < INT_MIN || v > INT_MAX)
    throw InvalidArgument(name, std::string(name) + " = " + std::to_string(v) + " is out of range");
  return int(v);
}

// The scene as the CLI's grid commands resolve it: every point runs at one truncation L.
SceneFile grid_scene(const py::handle& scene) {
  SceneFile f = scene_file(scene);
  apply_truncation(f, TruncationUse::grid);
  return f;
}

// A 2-D (ny, nx) array over the grid from the points (index = j nx + i); grid points this job does not hold
// (another shard's) keep `missing`.
template <class T, class F>
py::array_t<T> grid_array(const DiagramSpec& spec, const std::vector<PointResult>& points, T missing, F value) {
  py::array_t<T> out({py::ssize_t(spec.y.count), py::ssize_t(spec.x.count)});
  T* a = out.mutable_data();
  std::fill(a, a + spec.size(), missing);
  for (const PointResult& p : points) a[p.index] = value(p);
  return out;
}

template <class F>
py::object grid_names(const DiagramSpec& spec, const std::vector<PointResult>& points, F name) {
  std::vector<std::string> names(spec.size());
  for (const PointResult& p : points) names[p.index] = name(p);
  return py::module_::import("numpy").attr("array")(py::cast(names)).attr("reshape")(spec.y.count, spec.x.count);
}

std::vector<double> axis_values(const AxisRange& a) {
  std::vector<double> v(std::size_t(a.count));
  for (int i = 0; i < a.count; ++i) v[std::size_t(i)] = a.value(i);
  return v;
}

// PREFIX.csv and PREFIX.json, as the CLI's --out PREFIX writes them: both or neither.
void save_files(const std::string& prefix, const std::string& csv, const std::string& json) {
  if (prefix.empty()) throw InvalidArgument("prefix", "prefix '' is empty: must be a file name or prefix");
  write_files_atomic({{prefix + ".csv", csv, "prefix"}, {prefix + ".json", json, "prefix"}});
}

// Raised through the integrator's poll to abandon the points in flight once the run is stopped.
struct Stopped : std::exception {
  const char* what() const noexcept override { return "diagram stopped"; }
};

// A finished diagram: its configuration and points, the CLI's document (built once) and its drawing overlay.
struct DiagramData {
  SceneFile file;
  DiagramSpec spec;
  DiagramRun run;
  Shard shard;
  DiagramOutputOptions output;
  nlohmann::json document;
  nlohmann::json overlay;  // the report's phase-diagram overlay: the paper's analytic lines on this plane

  py::dict arrays() const {
    const auto& pts = run.points;
    py::dict a;
    a["x"] = own(axis_values(spec.x));
    a["y"] = own(axis_values(spec.y));
    a["l_Delta"] = grid_array<long long>(spec, pts, -1, [](const PointResult& p) { return p.l_Delta; });
    a["verdict"] = grid_names(spec, pts, [](const PointResult& p) { return to_string(p.verdict); });
    a["status"] = grid_names(spec, pts, [](const PointResult& p) { return to_string(p.status); });
    a["reason"] = grid_names(spec, pts, [](const PointResult& p) { return p.reason; });
    a["growth"] = grid_array<double>(spec, pts, std::nan(""), [](const PointResult& p) { return p.growth; });
    a["oscillating"] = grid_array<bool>(spec, pts, false, [](const PointResult& p) { return p.oscillating; });
    a["sigma_final"] = grid_array<double>(spec, pts, std::nan(""), [](const PointResult& p) { return p.sigma_final; });
    a["t_reached"] = grid_array<double>(spec, pts, std::nan(""), [](const PointResult& p) { return p.t_reached; });
    auto count = [](std::size_t n) { return static_cast<long long>(n); };
    a["steps"] = grid_array<long long>(spec, pts, -1, [&](const PointResult& p) { return count(p.steps); });
    a["failed_steps"] =
        grid_array<long long>(spec, pts, -1, [&](const PointResult& p) { return count(p.failed_steps); });
    a["rhs_evaluations"] =
        grid_array<long long>(spec, pts, -1, [&](const PointResult& p) { return count(p.rhs_evaluations); });
    if (output.include_seconds)
      a["seconds"] = grid_array<double>(spec, pts, std::nan(""), [](const PointResult& p) { return p.seconds; });
    return a;
  }
  std::string csv() const { return diagram_csv(spec, run.points, output); }
  std::string json_text() const { return document.dump(1) + "\n"; }
  void save(const std::string& prefix) const { save_files(prefix, csv(), json_text()); }
};

struct DiagramArgs {
  PlaneChoice plane;
  long long threads = 0;
  std::string schedule = "dynamic", shard = "0/1", journal;
  double sync_interval = 1.0;
  bool include_seconds = true, finite_horizon_agreement = true;
};

std::shared_ptr<DiagramData> run_diagram_scene(const py::handle& scene, const DiagramArgs& a, py::object progress) {
  if (a.schedule != "dynamic" && a.schedule != "static")
    throw InvalidArgument("schedule", "schedule = '" + a.schedule + "' is not allowed: must be one of dynamic, static");
  auto d = std::make_shared<DiagramData>();
  d->file = grid_scene(scene);
  d->spec = plane_spec(d->file, a.plane);
  d->output.include_seconds = a.include_seconds;

  std::atomic<bool> stop{false};
  std::optional<py::error_already_set> pending;  // KeyboardInterrupt, or what the progress callable raised
  DiagramOptions ro;
  ro.threads = narrow(a.threads, "threads");
  ro.dynamic_schedule = a.schedule == "dynamic";
  ro.shard = shard_from_string(a.shard);
  ro.journal = a.journal;
  ro.sync_interval = a.sync_interval;
  ro.progress_interval = 0.1;  // also the Ctrl-C latency: signals are checked here, on the calling thread
  ro.stop = &stop;
  ro.on_progress = [&](const Progress& p) {
    py::gil_scoped_acquire gil;
    if (pending) return;
    try {
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
      if (!progress.is_none()) progress(p.done, p.total, p.eta);
    } catch (py::error_already_set& e) {
      pending.emplace(std::move(e));
      stop.store(true);
    }
  };
  ro.validate();
  // Points in flight are abandoned at once (never journaled): the journal holds finished points only.
  SimulationOptions options = d->file.options;
  options.integrator.poll = [&stop] {
    if (stop.load()) throw Stopped();
  };
  AgreementOptions ao;
  ao.threads = ro.threads;
  ao.finite_horizon = a.finite_horizon_agreement;
  ao.trace_options.predictor.integrator.poll = signal_poll();  // the boundary is traced on this thread
  {
    py::gil_scoped_release release;
    try {
      d->run = run_diagram(d->file.scene, options, d->spec, ro);
    } catch (const Stopped&) {
    }
    if (!stop.load()) {
      d->shard = ro.shard;
      d->document = diagram_document(d->file, d->spec, d->run.points, d->shard, d->output, ao);
      d->overlay = phase_overlay_json(d->spec, {}, analytic_overlays(d->file.scene, d->spec, 200));
    }
  }
  if (pending) throw std::move(*pending);
  if (!d->run.complete) throw std::logic_error("diagram: the run ended incomplete without a stop");
  return d;
}

// A traced boundary and its document, as `rbcstab trace`: what the result shows, as plain values (its CSV made
// once), so that a pickle holds all of it.
struct TraceData {
  std::string x_axis, y_axis;
  double x_min = 0, x_max = 0, y_min = 0, y_max = 0;
  std::vector<TraceCurve> curves_;
  std::vector<TraceCorner> corners_;
  std::string csv_text;
  nlohmann::json document;
  nlohmann::json overlay;  // the report's overlay: the traced pieces and the paper's analytic lines

  const std::string& csv() const { return csv_text; }
  std::string json_text() const { return document.dump(1) + "\n"; }
  void save(const std::string& prefix) const { save_files(prefix, csv(), json_text()); }
  py::list curves() const {
    py::list out;
    for (const TraceCurve& c : curves_) {
      std::vector<double> x, y, mu, sigma_R, sigma_c;
      for (const TracePoint& p : c.points) {
        x.push_back(p.x), y.push_back(p.y), mu.push_back(p.mu);
        sigma_R.push_back(p.sigma_R), sigma_c.push_back(p.sigma_c);
      }
      py::dict d;
      d["l"] = c.l;
      d["chain"] = c.chain;
      d["criterion"] = c.criterion;
      d["x"] = own(std::move(x));
      d["y"] = own(std::move(y));
      d["mu"] = own(std::move(mu));
      d["sigma_R"] = own(std::move(sigma_R));
      d["sigma_c"] = own(std::move(sigma_c));
      out.append(d);
    }
    return out;
  }
  py::dict corners() const {
    std::vector<double> x, y;
    const py::ssize_t n = py::ssize_t(corners_.size());
    py::array_t<long long> l_from{n}, l_to{n};
    for (std::size_t k = 0; k < corners_.size(); ++k) {
      x.push_back(corners_[k].x), y.push_back(corners_[k].y);
      l_from.mutable_at(py::ssize_t(k)) = corners_[k].l_from;
      l_to.mutable_at(py::ssize_t(k)) = corners_[k].l_to;
    }
    py::dict d;
    d["x"] = own(std::move(x));
    d["y"] = own(std::move(y));
    d["l_from"] = l_from;
    d["l_to"] = l_to;
    return d;
  }

  // Pickling: every field as plain Python values (points and corners as tuples of numbers).
  py::tuple state() const {
    py::list cs, ks;
    for (const TraceCurve& c : curves_) {
      py::list pts;
      for (const TracePoint& p : c.points) pts.append(py::make_tuple(p.x, p.y, p.l, p.sigma_R, p.sigma_c, p.mu));
      cs.append(py::make_tuple(c.l, c.criterion, c.chain, pts));
    }
    for (const TraceCorner& k : corners_) ks.append(py::make_tuple(k.x, k.y, k.l_from, k.l_to));
    return py::make_tuple(py::make_tuple(x_axis, y_axis, x_min, x_max, y_min, y_max), cs, ks, csv_text, document.dump(),
                          overlay.dump());
  }
  static std::shared_ptr<TraceData> from_state(const py::tuple& t) {
    auto d = std::make_shared<TraceData>();
    const auto plane = t[0].cast<py::tuple>();
    d->x_axis = plane[0].cast<std::string>(), d->y_axis = plane[1].cast<std::string>();
    d->x_min = plane[2].cast<double>(), d->x_max = plane[3].cast<double>();
    d->y_min = plane[4].cast<double>(), d->y_max = plane[5].cast<double>();
    for (const py::handle c : t[1]) {
      const auto ct = c.cast<py::tuple>();
      TraceCurve curve{ct[0].cast<int>(), ct[1].cast<std::string>(), {}, ct[2].cast<std::size_t>()};
      for (const py::handle p : ct[3]) {
        const auto pt = p.cast<py::tuple>();
        curve.points.push_back({pt[0].cast<double>(), pt[1].cast<double>(), pt[2].cast<int>(), pt[3].cast<double>(),
                                pt[4].cast<double>(), pt[5].cast<double>()});
      }
      d->curves_.push_back(std::move(curve));
    }
    for (const py::handle k : t[2]) {
      const auto kt = k.cast<py::tuple>();
      d->corners_.push_back({kt[0].cast<double>(), kt[1].cast<double>(), kt[2].cast<int>(), kt[3].cast<int>()});
    }
    d->csv_text = t[3].cast<std::string>();
    d->document = nlohmann::json::parse(t[4].cast<std::string>());
    d->overlay = nlohmann::json::parse(t[5].cast<std::string>());
    return d;
  }
};

struct TraceArgs {
  PlaneChoice plane;
  std::string criterion = "asymptotic", method = "auto";
  double horizon = 0, max_step = 0.02;
  long long lines = 4, samples = 128, threads = 1;
  std::optional<std::string> diagram;  // a diagram document's JSON text: measure the agreement
  std::string diagram_source = "diagram";
};

std::shared_ptr<TraceData> trace_scene(const py::handle& scene, const TraceArgs& a, const py::object& progress) {
  const SceneFile f = grid_scene(scene);
  auto d = std::make_shared<TraceData>();
  const DiagramSpec plane = plane_spec(f, a.plane);
  d->x_axis = to_string(plane.x.axis), d->y_axis = to_string(plane.y.axis);
  d->x_min = plane.x.min, d->x_max = plane.x.max, d->y_min = plane.y.min, d->y_max = plane.y.max;
  TraceOptions to;
  to.criterion = trace_criterion_from_string(a.criterion);
  to.method = trace_method_from_string(a.method);
  to.T = a.horizon;
  to.lines = narrow(a.lines, "lines");
  to.samples = narrow(a.samples, "samples");
  to.max_step = a.max_step;
  const int threads = narrow(a.threads, "threads");
  require(threads >= 0 && threads <= 4096, "threads", threads, "an integer in [0, 4096] (0: all cores)");
  to.validate();
  nlohmann::json dj;
  if (a.diagram) dj = parse_json_text(*a.diagram, a.diagram_source, "diagram");
  TraceOptions polled = to;  // the criteria's reduced runs answer Ctrl-C (this thread runs them)
  polled.predictor.integrator.poll = signal_poll();
  const PythonProgress bar(progress);
  polled.on_progress = bar.callback();
  {
    py::gil_scoped_release release;
    const TraceResult result = trace_boundary(f.scene, plane, polled);
    d->document = trace_json(f, plane, to, result);
    if (a.diagram) d->document["agreement"] = trace_agreement_json(dj, a.diagram_source, plane, polled, threads);
    d->overlay = phase_overlay_json(plane, result.curves, analytic_overlays(f.scene, plane, 200));
    d->csv_text = trace_csv(plane, result);
    d->curves_ = result.curves;
    d->corners_ = result.corners;
  }
  bar.finish();
  return d;
}

// The Fig. 6e table as `rbcstab post --fig6e --json`, and its columns.
py::tuple fig6e_scene(const py::handle& scene, const std::optional<std::vector<double>>& lambdas,
                      const std::optional<std::vector<double>>& B, const std::optional<std::vector<double>>& C,
                      const py::object& progress) {
  const SceneFile f = grid_scene(scene);
  Fig6eOptions o = fig6e_options(f);
  if (lambdas) o.lambdas = *lambdas;
  if (B) o.B = *B;
  if (C) o.C = *C;
  o.validate();
  Fig6eOptions polled = o;
  polled.simulation.integrator.poll = signal_poll();
  const PythonProgress runs(progress);
  polled.on_progress = runs.callback();
  std::vector<Fig6eRow> rows;
  {
    py::gil_scoped_release release;
    rows = fig6e_table(polled);
  }
  runs.finish();
  const std::size_t n = rows.size();
  std::vector<double> lambda(n), Bs(n), Cs(n), alpha(n), ln_alpha(n), tilde(n), tilde_int(n), bar(n), ratio(n),
      ratio_int(n);
  py::array_t<long long> surviving{py::ssize_t(n)}, l_Delta{py::ssize_t(n)};
  auto value = [](const Quantity& q) { return q.valid() ? q.value : std::nan(""); };
  for (std::size_t k = 0; k < n; ++k) {
    const Fig6eRow& r = rows[k];
    lambda[k] = r.lambda, Bs[k] = r.B, Cs[k] = r.C, alpha[k] = r.alpha, ln_alpha[k] = r.ln_alpha;
    surviving.mutable_at(py::ssize_t(k)) = r.surviving_mode;
    l_Delta.mutable_at(py::ssize_t(k)) = r.l_Delta;
    tilde[k] = value(r.Delta2_tilde), tilde_int[k] = value(r.Delta2_tilde_integer), bar[k] = value(r.Delta2_bar);
    ratio[k] = value(r.ratio), ratio_int[k] = value(r.ratio_integer);
  }
  py::dict cols;  // the names of fig6e_json's rows
  cols["lambda"] = own(std::move(lambda));
  cols["B"] = own(std::move(Bs));
  cols["C"] = own(std::move(Cs));
  cols["alpha"] = own(std::move(alpha));
  cols["ln_alpha"] = own(std::move(ln_alpha));
  cols["surviving_mode"] = surviving;
  cols["l_Delta"] = l_Delta;
  cols["Delta2_tilde"] = own(std::move(tilde));
  cols["Delta2_tilde_integer_mode"] = own(std::move(tilde_int));
  cols["Delta2_simulated"] = own(std::move(bar));
  cols["ratio"] = own(std::move(ratio));
  cols["ratio_integer_mode"] = own(std::move(ratio_int));
  return py::make_tuple(to_python(fig6e_json(f, rows)), cols, fig6e_csv(o, rows));
}

// The physical phase diagram (verdict/physical_map.hpp) as its JSON, with the published observations beside it
// ("experiments": the shipped data/experiments.csv, or the file given).
py::object physical_map_scene(const py::handle& scene, double min_viscosity, double max_viscosity,
                              long long viscosities, double min_rate, double max_rate, long long samples_per_decade,
                              double rtol, bool onset, bool healthy_spreads,
                              const std::vector<std::tuple<std::string, double, double, std::string>>& spreads,
                              long long threads, const std::string& experiments, const py::object& progress) {
  const SceneFile& f = scene_file(scene);
  PhysicalMapOptions o;
  o.min_viscosity = min_viscosity;
  o.max_viscosity = max_viscosity;
  o.viscosities = narrow(viscosities, "viscosities");
  o.min_rate = min_rate;
  o.max_rate = max_rate;
  o.samples_per_decade = narrow(samples_per_decade, "samples_per_decade");
  o.rtol = rtol;
  o.onset = onset;
  o.threads = narrow(threads, "threads");
  if (healthy_spreads) o.spreads = healthy_cell_spreads(f.scene);
  for (const auto& [key, lo, hi, source] : spreads) o.spreads.push_back({key, lo, hi, source});
  const std::string path = experiments.empty() ? shipped_observations(executable_path()) : experiments;
  const std::vector<PublishedObservation> observed =
      path.empty() ? std::vector<PublishedObservation>{} : read_observations(path);
  o.validate();
  o.predictor.integrator.poll = signal_poll();
  const PythonProgress bar(progress);
  o.on_progress = bar.callback();
  nlohmann::json j;
  {
    py::gil_scoped_release release;
    j = to_json(physical_map(f.scene, o), observed, path);
  }
  bar.finish();
  return to_python(j);
}

PlaneChoice plane_choice(std::vector<std::string> axes, std::vector<double> x_range, std::vector<double> y_range,
                         std::vector<long long> counts, std::string classifier, std::optional<double> alpha_fixed) {
  return {std::move(axes),   std::move(x_range),    std::move(y_range),
          std::move(counts), std::move(classifier), alpha_fixed};
}

}  // namespace

void bind_sweep(py::module_& m) {
  py::class_<DiagramData, std::shared_ptr<DiagramData>>(m, "_Diagram")
      .def("document", [](const DiagramData& d) { return to_python(d.document); })
      .def("overlay", [](const DiagramData& d) { return to_python(d.overlay); })
      .def("arrays", &DiagramData::arrays)
      .def("csv", &DiagramData::csv)
      .def("json_text", &DiagramData::json_text)
      .def("save", &DiagramData::save, py::arg("prefix"))
      .def(
          "point_scene",
          [](const DiagramData& d, std::size_t index) {
            if (index >= d.spec.size()) throw py::index_error("point_scene: index outside the grid");
            SceneFile f = d.file;
            f.scene = point_scene(d.file.scene, d.spec, index);
            f.scene.validate();
            f.origins["run.L"] = Origin::flag;  // the grid's L: a run of this scene does not choose another
            return f;
          },
          py::arg("index"))
      .def_property_readonly(
          "axes",
          [](const DiagramData& d) { return py::make_tuple(to_string(d.spec.x.axis), to_string(d.spec.y.axis)); })
      .def_property_readonly("computed", [](const DiagramData& d) { return d.run.computed; })
      .def_property_readonly("resumed", [](const DiagramData& d) { return d.run.resumed; })
      .def_property_readonly("rejected", [](const DiagramData& d) { return d.run.rejected; })
      .def_property_readonly("seconds", [](const DiagramData& d) { return d.run.seconds; })
      .def_property_readonly("L", [](const DiagramData& d) { return d.file.scene.L; })
      // The document holds the spec and every point (spec_from_json, points_from_json: merge's readers); the
      // scene goes as a Scene (its pickle keeps what the document's scene_toml does not: which keys were given).
      .def(py::pickle(
          [](const DiagramData& d) {
            return py::make_tuple(py::cast(d.file), d.document.dump(), d.overlay.dump(), d.run.computed, d.run.resumed,
                                  d.run.rejected, d.run.seconds, d.output.include_seconds);
          },
          [](const py::tuple& t) {
            auto d = std::make_shared<DiagramData>();
            d->file = t[0].cast<SceneFile>();
            d->document = nlohmann::json::parse(t[1].cast<std::string>());
            d->overlay = nlohmann::json::parse(t[2].cast<std::string>());
            d->spec = spec_from_json(d->document);
            d->run.points = points_from_json(d->document, d->spec);
            d->run.computed = t[3].cast<std::size_t>();
            d->run.resumed = t[4].cast<std::size_t>();
            d->run.rejected = t[5].cast<std::vector<std::string>>();
            d->run.seconds = t[6].cast<double>();
            d->run.complete = true;
            d->run.config_hash = d->document.value("config_hash", "");
            d->output.include_seconds = t[7].cast<bool>();
            if (const auto s = d->document.find("shard"); s != d->document.end())
              d->shard = {s->at("k").get<int>(), s->at("n").get<int>()};
            return d;
          }));

  m.def(
      "diagram",
      [](const py::handle& scene, std::vector<std::string> axes, std::vector<double> x_range,
         std::vector<double> y_range, std::vector<long long> counts, std::string classifier,
         std::optional<double> alpha_fixed, long long threads, std::string schedule, std::string shard,
         std::string journal, double sync_interval, bool include_seconds, bool finite_horizon_agreement,
         py::object progress) {
        DiagramArgs a;
        a.plane = plane_choice(std::move(axes), std::move(x_range), std::move(y_range), std::move(counts),
                               std::move(classifier), alpha_fixed);
        a.threads = threads;
        a.schedule = std::move(schedule);
        a.shard = std::move(shard);
        a.journal = std::move(journal);
        a.sync_interval = sync_interval;
        a.include_seconds = include_seconds;
        a.finite_horizon_agreement = finite_horizon_agreement;
        return run_diagram_scene(scene, a, std::move(progress));
      },
      py::arg("scene"), py::arg("axes"), py::arg("x_range"), py::arg("y_range"), py::arg("counts"),
      py::arg("classifier"), py::arg("alpha_fixed"), py::arg("threads"), py::arg("schedule"), py::arg("shard"),
      py::arg("journal"), py::arg("sync_interval"), py::arg("include_seconds"), py::arg("finite_horizon_agreement"),
      py::arg("progress"),
      "rbcstab diagram: the run as a _Diagram (empty lists/strings: the scene's [diagram] table or the defaults).");

  py::class_<TraceData, std::shared_ptr<TraceData>>(m, "_Trace")
      .def("document", [](const TraceData& d) { return to_python(d.document); })
      .def("overlay", [](const TraceData& d) { return to_python(d.overlay); })
      .def("curves", &TraceData::curves)
      .def("corners", &TraceData::corners)
      .def("csv", &TraceData::csv)
      .def("json_text", &TraceData::json_text)
      .def("save", &TraceData::save, py::arg("prefix"))
      .def_property_readonly("axes", [](const TraceData& d) { return py::make_tuple(d.x_axis, d.y_axis); })
      .def_property_readonly("x_range", [](const TraceData& d) { return py::make_tuple(d.x_min, d.x_max); })
      .def_property_readonly("y_range", [](const TraceData& d) { return py::make_tuple(d.y_min, d.y_max); })
      .def(py::pickle([](const TraceData& d) { return d.state(); }, &TraceData::from_state));

  m.def(
      "trace",
      [](const py::handle& scene, std::vector<std::string> axes, std::vector<double> x_range,
         std::vector<double> y_range, std::optional<double> alpha_fixed, std::string criterion, std::string method,
         double horizon, long long lines, long long samples, double max_step, long long threads,
         std::optional<std::string> diagram, std::string diagram_source, const py::object& progress) {
        TraceArgs a;
        a.plane = plane_choice(std::move(axes), std::move(x_range), std::move(y_range), {}, {}, alpha_fixed);
        a.criterion = std::move(criterion);
        a.method = std::move(method);
        a.horizon = horizon;
        a.lines = lines;
        a.samples = samples;
        a.max_step = max_step;
        a.threads = threads;
        a.diagram = std::move(diagram);
        a.diagram_source = std::move(diagram_source);
        return trace_scene(scene, a, progress);
      },
      py::arg("scene"), py::arg("axes"), py::arg("x_range"), py::arg("y_range"), py::arg("alpha_fixed"),
      py::arg("criterion"), py::arg("method"), py::arg("horizon"), py::arg("lines"), py::arg("samples"),
      py::arg("max_step"), py::arg("threads"), py::arg("diagram"), py::arg("diagram_source"),
      py::arg("progress") = py::none(),
      "rbcstab trace: the traced boundary as a _Trace (diagram: a diagram document's JSON text, for the agreement).");

  m.def("physical_map", &physical_map_scene, py::arg("scene"), py::arg("min_viscosity"), py::arg("max_viscosity"),
        py::arg("viscosities"), py::arg("min_rate"), py::arg("max_rate"), py::arg("samples_per_decade"),
        py::arg("rtol"), py::arg("onset"), py::arg("healthy_spreads"), py::arg("spreads"), py::arg("threads"),
        py::arg("experiments"), py::arg("progress") = py::none(),
        "The physical phase diagram's JSON (verdict/physical_map.hpp) with the observations beside it.");

  m.def("fig6e", &fig6e_scene, py::arg("scene"), py::arg("lambdas"), py::arg("B"), py::arg("C"),
        py::arg("progress") = py::none(),
        "(json dict, columns dict, csv text): rbcstab post --fig6e --json, its columns, and the CSV of post --fig6e.");
}

}  // namespace rbcstab::python
