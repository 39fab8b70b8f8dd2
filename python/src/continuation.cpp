// Continuation from Python, as `rbcstab continue`: the same library calls (scene_run / continue_run,
// restart, load_branch and save_branch), the same serialisers (branch_io: a run's JSON equals the CLI's --json;
// branch_file: the CLI's branch files) and the same plot rules (report/bifurcation_plot: the JSON of what was
// drawn). The GIL is released while a run computes; Ctrl-C ends it through the engine's stop callback (every
// point) and the orbit shootings' integrator poll.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <complex>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "bindings.hpp"
#include "rbcstab/continuation/bifurcation_diagram.hpp"
#include "rbcstab/continuation/branch_file.hpp"
#include "rbcstab/continuation/branch_io.hpp"
#include "rbcstab/continuation/branch_labels.hpp"
#include "rbcstab/continuation/branch_spec.hpp"
#include "rbcstab/continuation/scene_branch.hpp"
#include "rbcstab/continuation/scene_curve.hpp"
#include "rbcstab/continuation/scene_kinds.hpp"
#include "rbcstab/continuation/scene_measures.hpp"
#include "rbcstab/continuation/scene_restart.hpp"
#include "rbcstab/continuation/scene_run.hpp"
#include "rbcstab/continuation/tunable_options.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/core/progress.hpp"
#include "rbcstab/io/files.hpp"
#include "rbcstab/report/bifurcation_plot.hpp"
#include "rbcstab/report/report.hpp"

namespace rbcstab::python {

namespace {

// A run and why its L (the "L_reason" of its JSON).
struct Run {
  ContinuationRun run;
  std::string L_reason;
};

// ---- options given as a dict of typed values (the Python layer checks the types) ----

// Takes the given options out of a dict; what is left at the end was not expected.
class Given {
 public:
  // A copy: the caller's dict stays as it is.
  explicit Given(const py::dict& d) : d_(py::reinterpret_steal<py::dict>(PyDict_Copy(d.ptr()))) {}
  template <class T>
  std::optional<T> take(const char* key) {
    if (!d_.contains(key)) return std::nullopt;
    T v = d_[key].cast<T>();
    PyDict_DelItemString(d_.ptr(), key);
    return v;
  }
  bool has(const char* key) const { return d_.contains(key); }
  void finish(const char* what) const {
    for (const auto& [key, value] : d_)
      throw py::type_error(std::string(what) + ": unexpected option '" + py::str(key).cast<std::string>() + "'");
  }

 private:
  py::dict d_;
};

template <class T, class U>
void set_if(T& field, const std::optional<U>& v) {
  if (v) field = static_cast<T>(*v);
}

// A Python integer as the library's int or count; the library checks its range.
std::optional<int> as_int(const std::optional<long long>& n, const char* key) {
  if (n) require(std::abs(*n) <= std::numeric_limits<int>::max(), key, static_cast<double>(*n), "an integer");
  return n ? std::optional<int>(static_cast<int>(*n)) : std::nullopt;
}
std::optional<std::size_t> as_count(const std::optional<long long>& n, const char* key) {
  if (n) require(*n >= 0, key, static_cast<double>(*n), "an integer >= 0");
  return n ? std::optional<std::size_t>(static_cast<std::size_t>(*n)) : std::nullopt;
}

std::vector<Monitor> monitors_of(Given& g);

// What a restart, a switch or a curve from a label may change (RestartChanges), by keyword: monitors given
// (even none) replace the run's.
RestartChanges restart_changes(Given& g) {
  RestartChanges ch;
  if (const auto k = g.take<std::string>("kind")) ch.kind = problem_kind_from_string(*k);
  if (const auto q = g.take<std::string>("parameter")) ch.parameter = continuation_parameter_from_string(*q);
  ch.p_min = g.take<double>("min");
  ch.p_max = g.take<double>("max");
  for (const auto& [key, bound] : {std::pair{"min", ch.p_min}, std::pair{"max", ch.p_max}})
    if (bound) require(!std::isnan(*bound), key, *bound, "a number (-inf / inf: no bound)");
  if (const auto d = g.take<std::string>("direction")) ch.direction = direction_from_string(*d);
  for (const TunableOption& t : tunable_options())
    if (const auto v = g.take<double>(t.keyword().c_str())) ch.tuned[t.name] = *v;
  if (g.has("monitors")) ch.monitors = monitors_of(g);
  ch.max_points = as_count(g.take<long long>("max_points"), "max_points");
  ch.label_every = as_int(g.take<long long>("label_every"), "label_every");
  ch.switch_at_bp = g.take<bool>("switch_at_bp").value_or(false);
  return ch;
}

// The tunable options given, checked by their declaration (naming the keyword's option) and set.
void tune(Given& g, ContinuationOptions& engine, OrbitOptions& orbit) {
  for (const TunableOption& t : tunable_options())
    if (const auto v = g.take<double>(t.keyword().c_str())) {
      t.check(*v);
      t.set(engine, orbit, *v);
    }
}

// monitors: a list of (name, values, stop, function or None) from the Python layer. A function is called
// under the GIL with the point's parameters and measures (a dict); it is held borrowed: the caller keeps it
// alive for the run and detach() drops it from the result.
std::vector<Monitor> monitors_of(Given& g) {
  std::vector<Monitor> out;
  const auto list = g.take<py::list>("monitors");
  if (!list) return out;
  for (const py::handle item : *list) {
    const auto t = item.cast<py::tuple>();
    Monitor m;
    m.name = t[0].cast<std::string>();
    m.values = t[1].cast<std::vector<double>>();
    m.stop = t[2].cast<bool>();
    if (!t[3].is_none()) {
      PyObject* f = t[3].ptr();
      m.function = [f](const std::map<std::string, double>& point) {
        py::gil_scoped_acquire gil;
        return py::handle(f)(point).cast<double>();
      };
    }
    out.push_back(std::move(m));
  }
  return out;
}

// ---- Ctrl-C and progress while the GIL is released ----

// The engine's callbacks while the GIL is released: its stop runs Python's signal handlers (signal_poll: Ctrl-C
// raises out of the run); its on_progress counts every point stepped to (both directions, every part of the run)
// and hands the count to a PythonProgress (progress(done, 0, 0): a branch's end is not known in advance), whose
// finish() reports the last count. The caller keeps `progress` alive for the run; detach() drops the callbacks from
// the result.
struct Watch {
  std::function<void()> poll = signal_poll();
  PythonProgress progress;
  explicit Watch(const py::object& p) : progress(p) {}
  void attach(BranchSpec& spec) const {
    spec.engine.stop = [poll = poll](const Eigen::VectorXd&, double) {
      poll();
      return false;
    };
    if (ProgressCallback report = progress.callback())
      spec.engine.on_progress = [report, points = std::make_shared<std::size_t>(0)](double, double) {
        report(double(++*points), 0);
      };
    spec.orbit.poll = poll;
  }
  void finish() const { progress.finish(); }
};

BranchSpec& spec_of(ContinuationRun& run) {
  if (auto* b = std::get_if<SceneBranch>(&run)) return b->spec;
  return std::get<SceneCurve>(run).one.spec;
}

// The run as it is kept: without the callbacks of the call that made it (a function monitor too: its points stay
// labelled, but a restart, a branch file or a pickle goes without it).
Run detach(ContinuationRun&& run, std::string L_reason) {
  BranchSpec& spec = spec_of(run);
  spec.engine.stop = nullptr;
  spec.engine.on_progress = nullptr;
  spec.orbit.poll = nullptr;
  std::erase_if(spec.monitors, [](const Monitor& m) { return bool(m.function); });
  return {std::move(run), std::move(L_reason)};
}

// ---- runs ----

// The spec of a fresh run from the options: what continue_scene and bifurcation_diagram share.
BranchSpec branch_spec_of(Given& g, const std::string& kind, const std::string& parameter) {
  BranchSpec spec;
  spec.kind = problem_kind_from_string(kind);
  spec.parameter = continuation_parameter_from_string(parameter);
  spec.engine.p_min = g.take<double>("min").value_or(spec.engine.p_min);
  spec.engine.p_max = g.take<double>("max").value_or(spec.engine.p_max);
  if (const auto d = g.take<std::string>("direction")) spec.engine.direction = direction_from_string(*d);
  tune(g, spec.engine, spec.orbit);
  spec.monitors = monitors_of(g);
  set_if(spec.engine.max_points, as_count(g.take<long long>("max_points"), "max_points"));
  set_if(spec.relax_T, g.take<double>("relax_T"));
  set_if(spec.switch_at_bp, g.take<bool>("switch_at_bp"));
  set_if(spec.allow_unstable_start, g.take<bool>("allow_unstable_start"));
  set_if(spec.label_every, as_int(g.take<long long>("label_every"), "label_every"));
  return spec;
}

Run continue_from_scene(const py::handle& scene, const std::string& kind, const std::string& parameter,
                        const py::dict& options, const py::object& progress) {
  SceneFile file = scene_file(scene);
  Given g(options);
  BranchSpec spec = branch_spec_of(g, kind, parameter);
  std::optional<CurveSpec> curve;
  const auto type = g.take<std::string>("curve");
  const auto parameter2 = g.take<std::string>("parameter2");
  const double inf = std::numeric_limits<double>::infinity();
  const double p2_min = g.take<double>("min2").value_or(-inf), p2_max = g.take<double>("max2").value_or(inf);
  const int point = as_int(g.take<long long>("point"), "point").value_or(1);
  if (type) {
    curve = curve_spec(*type, parameter2.value_or(""), p2_min, p2_max, point);
  } else if (parameter2) {
    throw InvalidArgument("parameter2", "parameter2 needs curve = 'LP', 'BP', 'HB', 'LPC', 'PD', 'NS' or 'UZ'");
  }
  g.finish("continuation");
  const Watch watch(progress);
  Run out = [&] {
    py::gil_scoped_release release;
    SceneRun sr = scene_run(std::move(file), std::move(spec), std::move(curve));
    watch.attach(sr.spec);
    ContinuationRun r = continue_run(sr);
    return detach(std::move(r), sr.L_reason);
  }();
  watch.finish();
  return out;
}

// A restart (label), a switch (switch_at) or a curve (label with curve) from a run, as `continue --restart`.
Run restart_from(const Run& from, RestartRequest q, const py::dict& options, const py::object& progress,
                 const char* what) {
  Given g(options);
  q.changes = restart_changes(g);
  g.finish(what);
  q.validate();
  const Watch watch(progress);
  Run out = [&] {
    py::gil_scoped_release release;
    ContinuationRun run = from.run;  // the callbacks go on a copy of its spec, which the restart takes
    watch.attach(spec_of(run));
    ContinuationRun r = restart(run, q);
    return detach(std::move(r), saved_run_L_reason(from.run));
  }();
  watch.finish();
  return out;
}

Run restart_py(const Run& from, int label, const py::dict& options, const py::object& progress) {
  return restart_from(from, {label, 0, std::nullopt, {}}, options, progress, "restart");
}

Run switch_py(const Run& from, int label, const py::dict& options, const py::object& progress) {
  return restart_from(from, {0, label, std::nullopt, {}}, options, progress, "switch");
}

// The curve of the special point labelled `label`, of its type unless `type` is given.
Run curve_py(const Run& from, int label, const std::optional<std::string>& type, const std::string& parameter2,
             double p2_min, double p2_max, const py::dict& options, const py::object& progress) {
  const std::string t = type ? *type : find_label(from.run, label).type;
  if (!type && (t.empty() || t == "EP"))
    throw InvalidArgument("label", "label " + std::to_string(label) +
                                       " is not a special point: a curve starts from an LP, BP, HB, LPC, PD, NS or UZ");
  return restart_from(from, {label, 0, curve_spec(t, parameter2, p2_min, p2_max), {}}, options, progress, "curve");
}

// ---- diagrams ----

struct Diagram {
  BifurcationDiagram d;
  std::string L_reason;
};

// rbcstab continue --diagram DEPTH: the start branch from the options as continue_scene's, the diagram's own
// (amplitude, duplicate_tol, max_branches) by keyword. Ctrl-C raises out of any branch (the engine's stop).
Diagram diagram_py(const py::handle& scene, const std::string& kind, const std::string& parameter, int depth,
                   const py::dict& options, const py::object& progress) {
  SceneFile file = scene_file(scene);
  Given g(options);
  BranchSpec spec = branch_spec_of(g, kind, parameter);
  BifurcationDiagramSpec ds;
  ds.depth = depth;
  set_if(ds.amplitude, g.take<double>("amplitude"));
  set_if(ds.duplicate_tol, g.take<double>("duplicate_tol"));
  set_if(ds.max_branches, as_count(g.take<long long>("max_branches"), "max_branches"));
  set_if(ds.journal, g.take<std::string>("journal"));
  g.finish("bifurcation_diagram");
  const Watch watch(progress);
  Diagram out = [&] {
    py::gil_scoped_release release;
    SceneRun sr = scene_run(std::move(file), std::move(spec));
    watch.attach(sr.spec);
    ds.start = sr.spec;
    BifurcationDiagram d = bifurcation_diagram(ds);
    d.start = std::get<SceneBranch>(detach(ContinuationRun(std::move(d.start)), "").run);
    return Diagram{std::move(d), sr.L_reason};
  }();
  watch.finish();
  return out;
}

py::tuple diagram_state(const Diagram& d) {
  std::vector<std::string> files;
  for (std::size_t k = 0; k < d.d.branches.size(); ++k) files.push_back(diagram_branch_file(d.d, k).dump());
  return py::make_tuple(to_json(d.d).dump(), files, d.L_reason);
}

Run load_py(const std::string& path) {
  ContinuationRun run = load_branch(path, "path");
  std::string reason = saved_run_L_reason(run);
  return {std::move(run), std::move(reason)};
}

// ---- columns ----

// The part of a run: "branch" (a branch, or a curve), "switched" (a branch's switched branch), "one_parameter"
// (the branch a curve started from); nullptr when the run has no such part.
const MeasuredBranch* part_of(const ContinuationRun& run, const std::string& role) {
  if (const auto* b = std::get_if<SceneBranch>(&run)) {
    if (role == "branch") return &b->branch;
    if (role == "switched") return b->switched ? &b->switched->branch : nullptr;
  } else {
    const auto& c = std::get<SceneCurve>(run);
    if (role == "branch") return &c.curve;
    if (role == "one_parameter") return &c.one.branch;
  }
  return nullptr;
}

template <class F>
py::array_t<double> doubles(std::size_t n, F f) {
  std::vector<double> v(n);
  for (std::size_t k = 0; k < n; ++k) v[k] = f(k);
  return own(std::move(v));
}

template <class T, class F>
py::array_t<T> values(std::size_t n, F f) {
  py::array_t<T> a(static_cast<py::ssize_t>(n));
  auto w = a.template mutable_unchecked<1>();
  for (std::size_t k = 0; k < n; ++k) w(static_cast<py::ssize_t>(k)) = f(k);
  return a;
}

template <class F>
py::array strings(std::size_t n, F f) {
  py::list l;
  for (std::size_t k = 0; k < n; ++k) l.append(py::str(f(k)));
  return py::module_::import("numpy").attr("array")(l, py::arg("dtype") = "str");
}

// The points of a part as named numpy columns: its parameters and measures (the names of its JSON points and
// CSV columns), stable, n_unstable, stability, margin, margin_error, label (0: unlabelled), type, arclength,
// the CSV's most unstable spectral value and the spectrum (points x dimension, complex).
py::dict columns(const Run& r, const std::string& role) {
  const MeasuredBranch* m = part_of(r.run, role);
  if (!m) throw py::key_error("the run has no part '" + role + "'");
  const std::vector<BranchPoint>& pts = m->branch.points;
  const std::size_t n = pts.size();
  py::dict out;
  const auto& names = m->branch.parameter_names;
  for (std::size_t i = 0; i < names.size(); ++i)
    out[py::str(names[i])] = doubles(n, [&](std::size_t k) { return pts[k].parameters[i]; });
  for (std::size_t i = 0; i < m->measure_names.size(); ++i) {
    const py::str name(m->measure_names[i]);
    const MeasureValue first = n ? m->point_measures[0][i] : MeasureValue(0.0);
    if (std::holds_alternative<std::string>(first))
      out[name] = strings(n, [&](std::size_t k) { return std::get<std::string>(m->point_measures[k][i]); });
    else if (std::holds_alternative<int>(first))
      out[name] = values<long long>(n, [&](std::size_t k) { return std::get<int>(m->point_measures[k][i]); });
    else
      out[name] = doubles(n, [&](std::size_t k) { return m->number(k, m->measure_names[i]); });
  }
  out["stable"] = values<bool>(n, [&](std::size_t k) { return pts[k].stable; });
  out["n_unstable"] = values<long long>(n, [&](std::size_t k) { return pts[k].n_unstable; });
  out["stability"] = strings(n, [&](std::size_t k) { return to_string(pts[k].stability); });
  out["margin"] = doubles(n, [&](std::size_t k) { return pts[k].margin; });
  out["margin_error"] = doubles(n, [&](std::size_t k) { return pts[k].margin_error; });
  out["label"] = values<long long>(n, [&](std::size_t k) { return m->point_label(k); });
  out["type"] = strings(n, [&](std::size_t k) { return m->point_type(k); });
  out["arclength"] = doubles(n, [&](std::size_t k) { return pts[k].arclength; });
  out[py::str(most_unstable_key(m->spectrum_kind))] =
      doubles(n, [&](std::size_t k) { return most_unstable(pts[k].spectrum, m->spectrum_kind); });
  const Eigen::Index dim = n ? pts[0].spectrum.size() : 0;
  py::array_t<std::complex<double>> spectrum({static_cast<py::ssize_t>(n), static_cast<py::ssize_t>(dim)});
  auto w = spectrum.mutable_unchecked<2>();
  for (std::size_t k = 0; k < n; ++k)
    for (Eigen::Index i = 0; i < dim; ++i)
      w(static_cast<py::ssize_t>(k), i) =
          i < pts[k].spectrum.size() ? pts[k].spectrum[i] : std::complex<double>(NAN, NAN);
  out[py::str(spectrum_key(m->spectrum_kind))] = spectrum;
  return out;
}

// ---- plots ----

// The JSON of what `rbcstab plot` draws for these runs saved as branch files (report/bifurcation_plot:
// plot_spec; the file's states add norm_x to the measures), each run known by its source name (the legend tells
// overlaid runs of the same kind apart by it).
py::object plot_spec_py(const std::vector<const Run*>& runs, const std::vector<std::string>& sources,
                        const std::string& x, const std::string& y, const std::string& title, bool all_labels) {
  if (runs.size() != sources.size()) throw py::value_error("plot_spec: one source name per run");
  std::vector<PlotInput> inputs;
  for (std::size_t k = 0; k < runs.size(); ++k)
    inputs.push_back(plot_input(branch_file_json(runs[k]->run), sources[k]));
  PlotOptions o;
  o.x = x;
  o.y = y;
  o.title = title;
  o.all_labels = all_labels;
  return to_python(to_json(plot_spec(inputs, o)));
}

}  // namespace

void bind_continuation(py::module_& m) {
  py::class_<Run> run(m, "_Run", "A continuation run (rbcstab.Branch wraps it).");
  run.def(
      "json", [](const Run& r) { return to_python(to_json(r.run, r.L_reason)); },
      "The run as `rbcstab continue --json` prints it.");
  run.def("columns", &columns, py::arg("role") = "branch",
          "The points of a part ('branch', 'switched', 'one_parameter') as named numpy columns.");
  run.def("has_part", [](const Run& r, const std::string& role) { return part_of(r.run, role) != nullptr; });
  run.def(
      "csv", [](const Run& r) { return to_csv(r.run); }, "The run as `rbcstab continue --csv` writes it.");
  run.def(
      "save_csv", [](const Run& r, const std::string& path) { write_file_atomic(path, to_csv(r.run)); },
      py::arg("path"), "Writes csv() to path, atomically (`rbcstab continue --csv`).");
  run.def(
      "text",
      [](const Run& r, const std::vector<std::string>& measures) { return to_text(r.run, TableOptions{measures}); },
      py::arg("measures") = std::vector<std::string>{},
      "The CLI's text: the summary and the table of labelled points.");
  run.def(
      "save", [](const Run& r, const std::string& path) { save_branch(path, r.run); }, py::arg("path"),
      "Writes the CLI's branch file (`rbcstab continue --save`), atomically.");
  run.def("outcome", [](const Run& r) {
    const RunOutcome o = outcome(r.run);
    return py::make_tuple(o.has_output, python_words(o.note), python_words(o.failure));
  });
  run.def(
      "label_type", [](const Run& r, int label) { return find_label(r.run, label).type; }, py::arg("label"),
      "The type of a labelled point ('' or 'EP': a regular point); ValueError listing the labels if none.");
  run.def(py::pickle([](const Run& r) { return py::make_tuple(branch_file_json(r.run).dump(), r.L_reason); },
                     [](const py::tuple& t) {
                       return Run{parse_branch_file(t[0].cast<std::string>(), "pickle"), t[1].cast<std::string>()};
                     }));

  m.def("continue_scene", &continue_from_scene, py::arg("scene"), py::arg("kind"), py::arg("parameter"),
        py::arg("options"), py::arg("progress") = py::none(),
        "A fresh run (rbcstab continue): the options as CLI flags in snake_case, typed.");
  m.def("restart", &restart_py, py::arg("run"), py::arg("label"), py::arg("options"), py::arg("progress") = py::none(),
        "rbcstab continue --restart FILE --label N");
  m.def("switch", &switch_py, py::arg("run"), py::arg("label"), py::arg("options"), py::arg("progress") = py::none(),
        "rbcstab continue --restart FILE --switch-at N");
  m.def("curve", &curve_py, py::arg("run"), py::arg("label"), py::arg("type"), py::arg("parameter2"), py::arg("min2"),
        py::arg("max2"), py::arg("options"), py::arg("progress") = py::none(),
        "rbcstab continue --restart FILE --label N --curve TYPE --parameter2 P2");
  m.def(
      "tunable_options",
      [] {
        py::list l;
        for (const TunableOption& t : tunable_options())
          l.append(py::make_tuple(t.keyword(), t.integer, t.range(), t.default_value(), t.help));
        return l;
      },
      "The tunable options (keyword, integer, range, default, help), as --help lists them.");
  py::class_<Diagram> diagram(m, "_BifurcationDiagram", "A bifurcation diagram (rbcstab.BifurcationDiagram wraps it).");
  diagram.def(
      "json", [](const Diagram& d) { return to_python(to_json(d.d)); },
      "The tree as `rbcstab continue --diagram N --json` prints it.");
  diagram.def(
      "text", [](const Diagram& d) { return to_text(d.d); }, "The CLI's text summary.");
  diagram.def("size", [](const Diagram& d) { return d.d.branches.size(); });
  diagram.def("resumed", [](const Diagram& d) { return d.d.resumed; });
  diagram.def("rejected", [](const Diagram& d) { return d.d.rejected; });
  diagram.def(
      "branch",
      [](const Diagram& d, std::size_t k) {
        return Run{diagram_run(d.d, k), d.L_reason};
      },
      py::arg("k"), "Branch k (0-based) as a run: restart, switch, curve, save and plot as any.");
  diagram.def(
      "save", [](const Diagram& d, const std::string& path) { return save_diagram(path, d.d, "path"); },
      py::arg("path"), "Writes the tree and its branch files (`--diagram N --save path`), atomically.");
  diagram.def("outcome", [](const Diagram& d) {
    const RunOutcome o = outcome(d.d);
    return py::make_tuple(o.has_output, python_words(o.note), python_words(o.failure));
  });
  diagram.def(py::pickle(&diagram_state, [](const py::tuple& t) {
    return Diagram{parse_diagram(t[0].cast<std::string>(), t[1].cast<std::vector<std::string>>(), "pickle"),
                   t[2].cast<std::string>()};
  }));
  m.def("bifurcation_diagram", &diagram_py, py::arg("scene"), py::arg("kind"), py::arg("parameter"), py::arg("depth"),
        py::arg("options"), py::arg("progress") = py::none(),
        "rbcstab continue --diagram DEPTH: the options as continue_scene's, plus amplitude, duplicate_tol, "
        "max_branches, journal.");
  m.def(
      "load_diagram",
      [](const std::string& path) {
        BifurcationDiagram d = load_diagram(path, "path");
        std::string reason = saved_run_L_reason(ContinuationRun(d.start));
        return Diagram{std::move(d), std::move(reason)};
      },
      py::arg("path"), "Reads a saved diagram (its tree and branch files).");
  m.def("load_branch", &load_py, py::arg("path"), "Reads a branch file (rbcstab continue --save).");
  m.def("plot_spec", &plot_spec_py, py::arg("runs"), py::arg("sources"), py::arg("x") = "", py::arg("y") = "",
        py::arg("title") = "", py::arg("all_labels") = false,
        "The JSON of what `rbcstab plot` draws for these runs (format rbcstab-plot).");
}

}  // namespace rbcstab::python
