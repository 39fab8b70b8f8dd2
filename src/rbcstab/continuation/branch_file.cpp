#include "rbcstab/continuation/branch_file.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <limits>
#include <set>
#include <utility>

#include "rbcstab/continuation/branch_io.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/io/files.hpp"
#include "rbcstab/io/json.hpp"
#include "rbcstab/io/scene_file.hpp"

namespace rbcstab {

namespace {

using json = nlohmann::json;
constexpr double kInf = std::numeric_limits<double>::infinity();

// ---- writing ----

json vector_json(const Eigen::VectorXd& x) {
  json a = json::array();
  for (Eigen::Index i = 0; i < x.size(); ++i) a.push_back(number_or_null(x[i]));
  return a;
}

// The file keys of a branch object (to_json(MeasuredBranch) already holds the rest).
void add_states(json& j, const MeasuredBranch& m) {
  j["spectrum"] = m.spectrum_kind == StabilityKind::eigenvalues ? "eigenvalues" : "multipliers";
  for (std::size_t k = 0; k < m.branch.points.size(); ++k) {
    const BranchPoint& pt = m.branch.points[k];
    json& o = j["branch"][k];
    o["x"] = vector_json(pt.x);
    o["p"] = number_or_null(pt.p);
    o["arclength"] = number_or_null(pt.arclength);
    o["newton_iterations"] = pt.newton_iterations;
  }
  for (std::size_t k = 0; k < m.branch.special_points.size(); ++k) {
    const SpecialPoint& sp = m.branch.special_points[k];
    json& o = j["special_points"][k];
    o["x"] = vector_json(sp.x);
    o["p"] = number_or_null(sp.p);
    o["after_index"] = sp.after_index;
    o["test_value"] = number_or_null(sp.test_value);
    o["eigenvalue"] = complex_json(sp.eigenvalue);
  }
}

// A continuation bound: infinite (null in JSON) means none.
void put_bound(json& j, const std::string& key, double v) {
  put_number(j, key, v, std::string("no bound (") + (v < 0 ? "-inf" : "inf") + "): the parameter is free on this side");
}

json engine_json(const ContinuationOptions& e) {
  json j{{"initial_step", e.initial_step},
         {"min_step", e.min_step},
         {"max_step", e.max_step},
         {"step_growth", e.step_growth},
         {"step_shrink", e.step_shrink},
         {"easy_iterations", e.easy_iterations},
         {"max_newton", e.max_newton},
         {"newton_tol", e.newton_tol},
         {"max_points", e.max_points},
         {"direction", to_string(e.direction)},
         {"detect_bifurcations", e.detect_bifurcations},
         {"compute_stability", e.compute_stability},
         {"location_tol", e.location_tol},
         {"max_location_iterations", e.max_location_iterations},
         {"stability_tol", e.stability_tol},
         {"certificate_refine_margin", e.certificate_refine_margin}};
  put_bound(j, "p_min", e.p_min);
  put_bound(j, "p_max", e.p_max);
  return j;
}

json special_point_json(const SpecialPoint& sp) {
  json out = {{"type", to_string(sp.type)},
              {"name", sp.name},
              {"x", vector_json(sp.x)},
              {"p", number_or_null(sp.p)},
              {"parameters", sp.parameters},
              {"bracket", {number_or_null(sp.p_lo), number_or_null(sp.p_hi)}},
              {"precision", number_or_null(sp.precision)},
              {"status", to_string(sp.status)},
              {"unstable_before", sp.unstable_before},
              {"unstable_after", sp.unstable_after},
              {"test_value", number_or_null(sp.test_value)},
              {"after_index", sp.after_index},
              {"eigenvalue", complex_json(sp.eigenvalue)},
              {"mode_l", sp.mode_l ? json(*sp.mode_l) : json(nullptr)},
              {"mode_m", sp.mode_m ? json(*sp.mode_m) : json(nullptr)}};
  // Only where computed: files written before normal forms existed read back to themselves.
  if (sp.normal_form) out["normal_form"] = to_json(*sp.normal_form);
  return out;
}

// ---- reading: every access names the key path and the file ----

class Reader {
 public:
  Reader(std::string name, std::string source) : name_(std::move(name)), source_(std::move(source)) {}

  [[noreturn]] void fail(const std::string& what) const {
    throw InvalidArgument(name_, name_ + " = '" + source_ + "' is not a valid branch file: " + what);
  }

  const json& at(const json& j, const std::string& key, const std::string& path) const {
    if (!j.is_object()) fail(path + " must be an object");
    const auto it = j.find(key);
    if (it == j.end()) fail("key '" + join(path, key) + "' is missing");
    return *it;
  }
  const json& array(const json& j, const std::string& key, const std::string& path) const {
    const json& a = at(j, key, path);
    if (!a.is_array()) fail(join(path, key) + " must be an array");
    return a;
  }
  // A number; null reads as NaN when allowed (values that were not finite), else it fails.
  double value(const json& v, const std::string& path, bool null_ok = false) const {
    if (v.is_null() && null_ok) return std::nan("");
    if (!v.is_number()) fail(path + " must be a finite number, got " + v.dump());
    const double d = v.get<double>();
    if (!std::isfinite(d)) fail(path + " must be a finite number, got " + v.dump());
    return d;
  }
  double number(const json& j, const std::string& key, const std::string& path, bool null_ok = false) const {
    return value(at(j, key, path), join(path, key), null_ok);
  }
  // A bound: null is unbounded (-inf for a lower bound, +inf for an upper one).
  double bound(const json& j, const std::string& key, const std::string& path, double unbounded) const {
    const json& v = at(j, key, path);
    return v.is_null() ? unbounded : value(v, join(path, key));
  }
  long long integer(const json& j, const std::string& key, const std::string& path) const {
    const json& v = at(j, key, path);
    if (!v.is_number_integer()) fail(join(path, key) + " must be an integer, got " + v.dump());
    return v.get<long long>();
  }
  int small_int(const json& j, const std::string& key, const std::string& path, long long lo = 0) const {
    const long long v = integer(j, key, path);
    if (v < lo || v > 1000000000) fail(join(path, key) + " = " + std::to_string(v) + " is out of range");
    return static_cast<int>(v);
  }
  std::size_t index(const json& j, const std::string& key, const std::string& path) const {
    return static_cast<std::size_t>(small_int(j, key, path));
  }
  bool boolean(const json& j, const std::string& key, const std::string& path) const {
    const json& v = at(j, key, path);
    if (!v.is_boolean()) fail(join(path, key) + " must be true or false, got " + v.dump());
    return v.get<bool>();
  }
  std::string string(const json& j, const std::string& key, const std::string& path) const {
    const json& v = at(j, key, path);
    if (!v.is_string()) fail(join(path, key) + " must be a string, got " + v.dump());
    return v.get<std::string>();
  }
  Eigen::VectorXd vector(const json& v, const std::string& path) const {
    if (!v.is_array()) fail(path + " must be an array of numbers");
    Eigen::VectorXd x(static_cast<Eigen::Index>(v.size()));
    for (std::size_t i = 0; i < v.size(); ++i)
      x[static_cast<Eigen::Index>(i)] = value(v[i], path + "[" + std::to_string(i) + "]");
    return x;
  }
  std::complex<double> complex(const json& v, const std::string& path) const {
    if (!v.is_array() || v.size() != 2) fail(path + " must be a pair [re, im]");
    return {value(v[0], path + "[0]", true), value(v[1], path + "[1]", true)};
  }
  // Calls f and turns a library InvalidArgument (a bad name or value in the file) into one naming the key.
  template <class F>
  auto checked(const std::string& path, F f) const -> decltype(f()) {
    try {
      return f();
    } catch (const InvalidArgument& e) {
      fail(path + ": " + e.what());
    }
  }

  static std::string join(const std::string& path, const std::string& key) {
    return path.empty() ? key : path + "." + key;
  }
  static std::string item(const std::string& path, std::size_t k) { return path + "[" + std::to_string(k) + "]"; }

 private:
  std::string name_, source_;
};

// A name back to its enum value, from the enum's name table.
template <TabledEnum E>
E enum_named(const Reader& rd, const std::string& name, const std::string& path) {
  if (const auto v = try_from_string<E>(name)) return *v;
  rd.fail(path + " = '" + name + "' is not a known value");
}

// A measure value of the JSON: an integer, a number (null: NaN) or a label.
MeasureValue measure_value(const Reader& rd, const json& v, const std::string& path) {
  if (v.is_number_integer()) {  // an int measure (a winding number): a wider integer is not one
    const bool fits = v.is_number_unsigned() ? v.get<std::uint64_t>() <= std::uint64_t(INT_MAX)
                                             : v.get<std::int64_t>() >= INT_MIN && v.get<std::int64_t>() <= INT_MAX;
    if (!fits)
      rd.fail(path + " = " + v.dump() + " is out of range: must be an integer in [" + std::to_string(INT_MIN) + ", " +
              std::to_string(INT_MAX) + "]");
    return v.get<int>();
  }
  if (v.is_number_float() || v.is_null()) return rd.value(v, path, true);
  if (v.is_string()) return v.get<std::string>();
  rd.fail(path + " must be a number or a string, got " + v.dump());
}

int label_of(const Reader& rd, const json& o, const std::string& path) {
  const json& v = rd.at(o, "label", path);
  if (v.is_null()) return 0;
  if (!v.is_number_integer() || v.get<long long>() < 1 || v.get<long long>() > 1000000000)
    rd.fail(Reader::join(path, "label") + " must be a positive integer or null, got " + v.dump());
  return v.get<int>();
}

std::vector<double> parameters_of(const Reader& rd, const json& o, const std::vector<std::string>& names,
                                  const std::string& path) {
  std::vector<double> p;
  for (const auto& n : names) p.push_back(rd.number(o, n, path));
  return p;
}

std::vector<MeasureValue> measures_of(const Reader& rd, const json& o, const std::vector<std::string>& names,
                                      const std::string& path) {
  std::vector<MeasureValue> v;
  for (const auto& n : names) v.push_back(measure_value(rd, rd.at(o, n, path), Reader::join(path, n)));
  return v;
}

// A special point; its parameters by name (a branch's special points) or, names null, as the array
// "parameters" (a curve's start).
SpecialPoint read_special_point(const Reader& rd, const json& o, const std::string& at,
                                const std::vector<std::string>* names = nullptr) {
  SpecialPoint sp;
  sp.type = enum_named<SpecialPointType>(rd, rd.string(o, "type", at), Reader::join(at, "type"));
  sp.name = rd.string(o, "name", at);
  sp.x = rd.vector(rd.at(o, "x", at), Reader::join(at, "x"));
  sp.p = rd.number(o, "p", at);
  if (names) {
    sp.parameters = parameters_of(rd, o, *names, at);
  } else {
    const json& params = rd.array(o, "parameters", at);
    for (std::size_t i = 0; i < params.size(); ++i)
      sp.parameters.push_back(rd.value(params[i], Reader::item(Reader::join(at, "parameters"), i)));
  }
  const json& bracket = rd.at(o, "bracket", at);
  if (!bracket.is_array() || bracket.size() != 2) rd.fail(Reader::join(at, "bracket") + " must be a pair");
  sp.p_lo = rd.value(bracket[0], Reader::join(at, "bracket[0]"), true);
  sp.p_hi = rd.value(bracket[1], Reader::join(at, "bracket[1]"), true);
  sp.precision = rd.number(o, "precision", at, true);
  sp.status = enum_named<LocationStatus>(rd, rd.string(o, "status", at), Reader::join(at, "status"));
  sp.unstable_before = rd.small_int(o, "unstable_before", at);
  sp.unstable_after = rd.small_int(o, "unstable_after", at);
  sp.test_value = rd.number(o, "test_value", at, true);
  sp.after_index = rd.index(o, "after_index", at);
  sp.eigenvalue = rd.complex(rd.at(o, "eigenvalue", at), Reader::join(at, "eigenvalue"));
  // A BP's mode (files before it was reported have none: the mode stays unknown).
  for (const auto& [key, mode] : {std::pair{"mode_l", &sp.mode_l}, std::pair{"mode_m", &sp.mode_m}})
    if (o.contains(key) && !o.at(key).is_null()) *mode = rd.small_int(o, key, at);
  // The normal form (files before it was computed have none).
  if (o.contains("normal_form") && !o.at("normal_form").is_null())
    sp.normal_form =
        rd.checked(Reader::join(at, "normal_form"), [&] { return normal_form_from_json(o.at("normal_form")); });
  return sp;
}

// The certified stability keys of a point or special point (branch_io's put_stability).
template <class Point>
void read_stability(const Reader& rd, const json& o, const std::string& at, Point& pt) {
  pt.stability = rd.checked(Reader::join(at, "stability"),
                            [&] { return from_string<Stability>(rd.string(o, "stability", at), "stability"); });
  pt.margin = rd.number(o, "margin", at, true);
  pt.margin_error = rd.number(o, "margin_error", at, true);
  // Files written before the key existed: an uncertain label's reason is unknown to them, and stays so (not
  // written back).
  pt.uncertain_because = CertificateTerm::none;
  if (pt.stability == Stability::uncertain)
    pt.uncertain_because = o.contains("uncertain_because")
                               ? rd.checked(Reader::join(at, "uncertain_because"),
                                            [&] {
                                              return from_string<CertificateTerm>(rd.string(o, "uncertain_because", at),
                                                                                  "uncertain_because");
                                            })
                               : CertificateTerm::unknown;
}

// A branch object back into a MeasuredBranch: parameter and measure names as the run's, states of
// `dimension` unknowns (0: any, the same for every point).
MeasuredBranch read_branch(const Reader& rd, const json& j, const std::string& path,
                           std::vector<std::string> parameter_names, std::vector<std::string> measure_names,
                           Eigen::Index dimension) {
  MeasuredBranch m;
  m.measure_names = std::move(measure_names);
  m.branch.parameter_names = std::move(parameter_names);
  const std::string spectrum = rd.string(j, "spectrum", path);
  if (spectrum != "eigenvalues" && spectrum != "multipliers")
    rd.fail(Reader::join(path, "spectrum") + " = '" + spectrum + "' must be eigenvalues or multipliers");
  m.spectrum_kind = spectrum == "eigenvalues" ? StabilityKind::eigenvalues : StabilityKind::multipliers;
  auto check_size = [&](const Eigen::VectorXd& x, const std::string& where) {
    if (dimension == 0) dimension = x.size();
    if (x.size() != dimension || dimension == 0)
      rd.fail(where + " has " + std::to_string(x.size()) + " entries: must be " + std::to_string(dimension) +
              " (the problem's unknowns)");
  };
  const json& pts = rd.array(j, "branch", path);
  for (std::size_t k = 0; k < pts.size(); ++k) {
    const std::string at = Reader::item(Reader::join(path, "branch"), k);
    const json& o = pts[k];
    BranchPoint pt;
    pt.x = rd.vector(rd.at(o, "x", at), Reader::join(at, "x"));
    check_size(pt.x, Reader::join(at, "x"));
    pt.p = rd.number(o, "p", at);
    pt.parameters = parameters_of(rd, o, m.branch.parameter_names, at);
    const json& spectrum_values = rd.array(o, spectrum, at);
    pt.spectrum.resize(static_cast<Eigen::Index>(spectrum_values.size()));
    for (std::size_t i = 0; i < spectrum_values.size(); ++i)
      pt.spectrum[static_cast<Eigen::Index>(i)] =
          rd.complex(spectrum_values[i], Reader::item(Reader::join(at, spectrum), i));
    pt.n_unstable = rd.small_int(o, "n_unstable", at);
    pt.stable = rd.boolean(o, "stable", at);
    read_stability(rd, o, at, pt);
    pt.arclength = rd.number(o, "arclength", at);
    pt.newton_iterations = rd.small_int(o, "newton_iterations", at);
    m.branch.points.push_back(std::move(pt));
    m.point_measures.push_back(measures_of(rd, o, m.measure_names, at));
    m.point_labels.push_back(label_of(rd, o, at));
  }
  for (std::size_t k = 0; k < pts.size(); ++k) {  // the ends are known once every point is read
    const std::string at = Reader::item(Reader::join(path, "branch"), k);
    const std::string type = rd.string(pts[k], "type", at);
    if (type != m.point_type(k))
      rd.fail(Reader::join(at, "type") + " = '" + type + "' must be '" + m.point_type(k) +
              "' ('EP' at the two ends of a branch, '' elsewhere)");
  }
  const json& sps = rd.array(j, "special_points", path);
  for (std::size_t k = 0; k < sps.size(); ++k) {
    const std::string at = Reader::item(Reader::join(path, "special_points"), k);
    const json& o = sps[k];
    SpecialPoint sp = read_special_point(rd, o, at, &m.branch.parameter_names);
    read_stability(rd, o, at, sp);
    check_size(sp.x, Reader::join(at, "x"));
    if (sp.after_index + 1 >= pts.size())
      rd.fail(Reader::join(at, "after_index") + " = " + std::to_string(sp.after_index) +
              " must be below the last "
              "point's index (a special point lies between two points of the branch)");
    m.branch.special_points.push_back(std::move(sp));
    m.special_measures.push_back(measures_of(rd, o, m.measure_names, at));
    m.special_labels.push_back(label_of(rd, o, at));
  }
  m.branch.status = enum_named<ContinuationStatus>(rd, rd.string(j, "status", path), Reader::join(path, "status"));
  m.branch.message = rd.string(j, "message", path);
  const json& c = rd.at(j, "counters", path);
  const std::string cp = Reader::join(path, "counters");
  ContinuationCounters& n = m.branch.counters;
  n.steps = rd.index(c, "steps", cp);
  n.rejected_steps = rd.index(c, "rejected_steps", cp);
  n.newton_iterations = rd.index(c, "newton_iterations", cp);
  n.residual_evaluations = rd.index(c, "residual_evaluations", cp);
  n.jacobian_evaluations = rd.index(c, "jacobian_evaluations", cp);
  n.location_iterations = rd.index(c, "location_iterations", cp);
  // Files written before the branch-jump guard have no such count.
  n.unconfirmed_steps = c.contains("unconfirmed_steps") ? rd.index(c, "unconfirmed_steps", cp) : 0;
  return m;
}

ContinuationOptions read_engine(const Reader& rd, const json& j, const std::string& path) {
  ContinuationOptions e;
  e.initial_step = rd.number(j, "initial_step", path);
  e.min_step = rd.number(j, "min_step", path);
  e.max_step = rd.number(j, "max_step", path);
  e.step_growth = rd.number(j, "step_growth", path);
  e.step_shrink = rd.number(j, "step_shrink", path);
  e.easy_iterations = rd.small_int(j, "easy_iterations", path);
  e.max_newton = rd.small_int(j, "max_newton", path);
  e.newton_tol = rd.number(j, "newton_tol", path);
  e.p_min = rd.bound(j, "p_min", path, -kInf);
  e.p_max = rd.bound(j, "p_max", path, kInf);
  e.max_points = rd.index(j, "max_points", path);
  e.direction = rd.checked(Reader::join(path, "direction"),
                           [&] { return direction_from_string(rd.string(j, "direction", path)); });
  e.detect_bifurcations = rd.boolean(j, "detect_bifurcations", path);
  e.compute_stability = rd.boolean(j, "compute_stability", path);
  e.location_tol = rd.number(j, "location_tol", path);
  e.max_location_iterations = rd.small_int(j, "max_location_iterations", path);
  e.stability_tol = rd.number(j, "stability_tol", path);
  e.certificate_refine_margin = rd.number(j, "certificate_refine_margin", path);
  rd.checked(path, [&] { e.validate(); });
  return e;
}

BranchSpec read_spec(const Reader& rd, const json& j) {
  const std::string path = "spec";
  BranchSpec s;
  const std::string toml = rd.string(j, "scene", path);
  s.scene = rd.checked("spec.scene", [&] { return parse_scene(toml, "spec.scene").scene; });
  s.kind = rd.checked("spec.kind", [&] { return problem_kind_from_string(rd.string(j, "kind", path)); });
  s.parameter =
      rd.checked("spec.parameter", [&] { return continuation_parameter_from_string(rd.string(j, "parameter", path)); });
  s.engine = read_engine(rd, rd.at(j, "engine", path), "spec.engine");
  s.relax_T = rd.number(j, "relax_T", path);
  s.relax_tol = rd.number(j, "relax_tol", path);
  s.relax_max_periods = rd.small_int(j, "relax_max_periods", path);
  s.allow_unstable_start = rd.boolean(j, "allow_unstable_start", path);
  const json& o = rd.at(j, "orbit", path);
  s.orbit.segments = rd.small_int(o, "segments", "spec.orbit");
  s.orbit.rtol = rd.number(o, "rtol", "spec.orbit");
  s.orbit.atol = rd.number(o, "atol", "spec.orbit");
  s.orbit.samples_per_segment = rd.small_int(o, "samples_per_segment", "spec.orbit");
  s.label_every = rd.small_int(j, "label_every", path);
  s.switch_at_bp = rd.boolean(j, "switch_at_bp", path);
  const json& start = rd.at(j, "start_state", path);
  if (!start.is_null()) s.start_state = rd.vector(start, "spec.start_state");
  if (j.contains("start_parameter")) s.start_parameter = rd.number(j, "start_parameter", path);
  for (const bool stop : {false, true}) {
    const std::string key = stop ? "stop_at" : "monitor", at = Reader::join(path, key);
    if (!j.contains(key)) continue;  // optional: a run without monitors
    for (const json& t : rd.array(j, key, path)) {
      if (!t.is_string()) rd.fail(at + " must be an array of \"NAME=V1,V2,...\" strings, got " + t.dump());
      s.monitors.push_back(rd.checked(at, [&] { return parse_monitor(t.get<std::string>(), stop, key); }));
    }
  }
  rd.checked(path, [&] { s.validate(); });
  return s;
}

StartPoint read_start(const Reader& rd, const json& j) {
  StartPoint s;
  s.method = enum_named<StartMethod>(rd, rd.string(j, "method", "start"), "start.method");
  s.p = rd.number(j, "p", "start", true);
  s.newton = rd.boolean(j, "newton", "start");
  s.converged = rd.boolean(j, "converged", "start");
  s.iterations = rd.small_int(j, "iterations", "start");
  s.residual_norm = rd.number(j, "residual_norm", "start", true);
  s.message = rd.string(j, "message", "start");
  s.stable = rd.boolean(j, "stable", "start");
  s.n_unstable = rd.small_int(j, "n_unstable", "start");
  s.refused = rd.boolean(j, "refused", "start");
  read_stability(rd, j, "start", s);
  if (j.contains("relaxation_periods")) {  // orbits
    s.relaxation_periods = rd.small_int(j, "relaxation_periods", "start");
    s.periodicity_defect = rd.number(j, "periodicity_defect", "start", true);
    s.periodicity_tol = rd.number(j, "periodicity_tol", "start", true);
    s.relaxed = rd.boolean(j, "relaxed", "start");
  }
  return s;
}

// The one-parameter part of a file: the run's branch (a curve's "one_parameter_branch") on the spec.
SceneBranch read_scene_branch(const Reader& rd, const json& j, const json& branch_object, const std::string& path) {
  SceneBranch r;
  r.spec = read_spec(rd, rd.at(j, "spec", ""));
  r.problem_scene = problem_scene_of(r.spec);
  r.start = read_start(rd, rd.at(j, "start", ""));
  const Eigen::Index n = rd.checked("spec", [&] { return problem_dimension(r); });
  const std::vector<std::string> names{to_string(r.spec.parameter)};
  const std::vector<std::string> measures = measure_names(r.spec.kind, r.problem_scene.L);
  r.branch = read_branch(rd, branch_object, path, names, measures, n);
  if (const auto sw = branch_object.find("switched_branch"); sw != branch_object.end()) {
    const std::string sp = Reader::join(path, "switched_branch");
    SwitchedBranch s;
    s.switched = rd.boolean(*sw, "switched", sp);
    s.message = rd.string(*sw, "message", sp);
    s.bp_number = rd.small_int(*sw, "bp_number", sp, 1);
    const json& bl = rd.at(*sw, "bp_label", sp);
    s.bp_label = bl.is_null() ? 0 : rd.small_int(*sw, "bp_label", sp, 1);
    s.branch = read_branch(rd, *sw, sp, names, measures, n);
    r.switched = std::move(s);
  }
  return r;
}

// Labels positive and unique over the run.
void check_labels(const Reader& rd, const ContinuationRun& run) {
  std::set<int> seen;
  for (const LabelledPoint& p : labelled_points(run))
    if (!seen.insert(p.label).second) rd.fail("label " + std::to_string(p.label) + " appears twice");
}

}  // namespace

json branch_spec_json(const BranchSpec& s) {
  SceneFile sf;
  sf.scene = s.scene;
  json j{{"scene", to_toml(sf)},
         {"kind", to_string(s.kind)},
         {"parameter", to_string(s.parameter)},
         {"engine", engine_json(s.engine)},
         {"relax_T", s.relax_T},
         {"relax_tol", s.relax_tol},
         {"relax_max_periods", s.relax_max_periods},
         {"allow_unstable_start", s.allow_unstable_start},
         {"orbit",
          {{"segments", s.orbit.segments},
           {"rtol", s.orbit.rtol},
           {"atol", s.orbit.atol},
           {"samples_per_segment", s.orbit.samples_per_segment}}},
         {"label_every", s.label_every},
         {"switch_at_bp", s.switch_at_bp},
         {"start_state", s.start_state ? vector_json(*s.start_state) : json(nullptr)}};
  if (!s.start_state) j["start_state_reason"] = "none: the start is computed from the scene";
  if (s.start_parameter) j["start_parameter"] = *s.start_parameter;
  for (const Monitor& m : s.monitors)  // a function (Python's) cannot be saved: a restart goes without it
    if (!m.function) j[m.stop ? "stop_at" : "monitor"].push_back(monitor_text(m));
  return j;
}

json branch_file_json(const ContinuationRun& run) {
  json j = to_json(run);
  if (const SceneBranch* r = std::get_if<SceneBranch>(&run)) {
    add_states(j, r->branch);
    if (r->switched) {
      add_states(j["switched_branch"], r->switched->branch);
      j["switched_branch"]["bp_number"] = r->switched->bp_number;
      j["switched_branch"]["message"] = r->switched->message;
    }
    j["spec"] = branch_spec_json(r->spec);
    j["start"] = to_json(r->start, is_orbit(r->spec.kind));
  } else {
    const SceneCurve& c = std::get<SceneCurve>(run);
    add_states(j, c.curve);
    add_states(j["one_parameter_branch"], c.one.branch);
    j["spec"] = branch_spec_json(c.one.spec);
    j["start"] = to_json(c.one.start, is_orbit(c.one.spec.kind));
    j["curve_spec"] = {{"type", to_string(c.spec.type)},
                       {"parameter2", to_string(*c.spec.parameter2)},
                       {"point", c.spec.point},
                       {"symmetric_tol", c.spec.symmetric_tol}};
    put_bound(j["curve_spec"], "p2_min", c.spec.p2_min);
    put_bound(j["curve_spec"], "p2_max", c.spec.p2_max);
    j["curve_start"] = special_point_json(c.start);
    j["start_p2"] = number_or_null(c.start_p2);
    j["started"] = c.started;
    j["curve_message"] = c.message;
  }
  j["format"] = kBranchFileFormat;
  j["version"] = kBranchFileVersion;
  const SceneBranch* branch = std::get_if<SceneBranch>(&run);
  explain_nulls(j, nonfinite_reason((branch ? branch->spec : std::get<SceneCurve>(run).one.spec).scene.parameters));
  return j;
}

void save_branch(const std::string& path, const ContinuationRun& run) {
  write_file_atomic(path, branch_file_json(run).dump(1) + "\n");
}

ContinuationRun parse_branch_file(const std::string& text, const std::string& source, const std::string& name) {
  const json j = json::parse(text, nullptr, false);
  if (j.is_discarded())
    Reader(name, source)
        .fail("it is not JSON (a truncated or corrupted file?): " + std::to_string(text.size()) + " bytes");
  return parse_branch_json(j, source, name);
}

ContinuationRun parse_branch_json(const nlohmann::json& j, const std::string& source, const std::string& name) {
  const Reader rd(name, source);
  if (!j.is_object() || !j.contains("format") || j.at("format") != kBranchFileFormat)
    rd.fail(std::string("it has no \"format\": \"") + kBranchFileFormat + "\" (written by rbcstab continue --save?)");
  const long long version = rd.integer(j, "version", "");
  if (version != kBranchFileVersion)
    rd.fail("version " + std::to_string(version) + ": this rbcstab reads version " +
            std::to_string(kBranchFileVersion));
  if (!j.contains("curve")) {
    ContinuationRun run = read_scene_branch(rd, j, j, "");
    check_labels(rd, run);
    return run;
  }
  SceneCurve c;
  c.one = read_scene_branch(rd, j, rd.at(j, "one_parameter_branch", ""), "one_parameter_branch");
  const json& cs = rd.at(j, "curve_spec", "");
  c.spec.type =
      rd.checked("curve_spec.type", [&] { return curve_kind_from_string(rd.string(cs, "type", "curve_spec")); });
  c.spec.parameter2 = rd.checked("curve_spec.parameter2", [&] {
    return continuation_parameter_from_string(rd.string(cs, "parameter2", "curve_spec"));
  });
  c.spec.p2_min = rd.bound(cs, "p2_min", "curve_spec", -kInf);
  c.spec.p2_max = rd.bound(cs, "p2_max", "curve_spec", kInf);
  c.spec.point = rd.small_int(cs, "point", "curve_spec", 1);
  c.spec.symmetric_tol = rd.number(cs, "symmetric_tol", "curve_spec");
  BranchSpec one_spec = c.one.spec;
  one_spec.switch_at_bp = false;
  rd.checked("curve_spec", [&] { c.spec.validate(one_spec); });
  c.started = rd.boolean(j, "started", "");
  c.message = rd.string(j, "curve_message", "");
  c.start = read_special_point(rd, rd.at(j, "curve_start", ""), "curve_start");
  c.start_p2 = rd.number(j, "start_p2", "", true);
  const json& curve = rd.at(j, "curve", "");
  c.system = enum_named<CurveSystem>(rd, rd.string(curve, "system", "curve"), "curve.system");
  const std::vector<std::string> names{to_string(c.one.spec.parameter), to_string(*c.spec.parameter2)};
  c.curve = read_branch(rd, j, "", names, curve_measure_names(c.one.spec.kind, c.system, c.one.problem_scene.L), 0);
  if (!c.curve.branch.points.empty())  // the curve's unknowns hold the state of the problem it augments
    rd.checked("branch[0].x", [&] { (void)curve_point_state(c, c.curve.branch.points[0].x); });
  ContinuationRun run = std::move(c);
  check_labels(rd, run);
  return run;
}

ContinuationRun load_branch(const std::string& path, const std::string& name) {
  std::string text;
  try {
    text = read_file(path);
  } catch (const InvalidArgument& e) {
    throw InvalidArgument(name, name + " = '" + path + "': " + e.what());
  }
  return parse_branch_file(text, path, name);
}

}  // namespace rbcstab
