#include "rbcstab/continuation/branch_io.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

#include "rbcstab/continuation/scene_run.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/core/text.hpp"
#include "rbcstab/io/json.hpp"

namespace rbcstab {

namespace {

nlohmann::json value_json(const MeasureValue& v) {
  if (const double* d = std::get_if<double>(&v)) return number_or_null(*d);
  if (const int* i = std::get_if<int>(&v)) return *i;
  return std::get<std::string>(v);
}

void put_value(std::ostream& os, const MeasureValue& v) {
  std::visit([&](const auto& x) { os << x; }, v);
}

// A CSV field: numbers as csv_number (empty when not finite, never "nan").
void put_csv_value(std::ostream& os, const MeasureValue& v) {
  if (const double* d = std::get_if<double>(&v))
    os << csv_number(*d);
  else
    put_value(os, v);
}

// The certified stability keys of a point, special point or start.
template <class Point>
void put_stability(nlohmann::json& j, const Point& pt) {
  j["stability"] = to_string(pt.stability);
  j["margin"] = number_or_null(pt.margin);
  j["margin_error"] = number_or_null(pt.margin_error);
  // Only where the label is uncertain: which quantity made it so (CertificateTerm).
  if (pt.stability == Stability::uncertain && pt.uncertain_because != CertificateTerm::unknown)
    j["uncertain_because"] = to_string(pt.uncertain_because);
}

// The parameters by name and the measures by name of one point (its row k).
nlohmann::json point_json(const MeasuredBranch& m, const std::vector<double>& parameters,
                          const std::vector<MeasureValue>& measures) {
  nlohmann::json j;
  const auto& names = m.branch.parameter_names;
  for (std::size_t k = 0; k < names.size(); ++k) j[names[k]] = number_or_null(parameters[k]);
  for (std::size_t k = 0; k < m.measure_names.size(); ++k) j[m.measure_names[k]] = value_json(measures[k]);
  return j;
}

// The keys a scene's branch and a curve share: what was continued, from which scene.
void put_header(nlohmann::json& j, const BranchSpec& spec) {
  j["kind"] = to_string(spec.kind);
  j["level"] = to_string(model_level(spec.kind));
  j["free_parameter"] = to_string(spec.parameter);
  j["parameters"] = to_json(spec.scene.parameters);
  j["beta"] = spec.scene.beta;
  if (is_orbit(spec.kind)) j["segments"] = spec.orbit.segments;
}

// Visits the points and special points of a branch in order along it: point k, then the special points
// that lie between it and point k + 1. f(special, index).
template <class F>
void along(const MeasuredBranch& m, F f) {
  const auto& sps = m.branch.special_points;
  std::size_t j = 0;
  for (std::size_t k = 0; k < m.branch.points.size(); ++k) {
    f(false, k);
    for (; j < sps.size() && sps[j].after_index <= k; ++j) f(true, j);
  }
  for (; j < sps.size(); ++j) f(true, j);
}

// j[key] = the label, or null with its reason: only the ends, the special points and every label_every-th
// point carry one.
void put_label(nlohmann::json& j, const std::string& key, int label) {
  if (label > 0) {
    j[key] = label;
    return;
  }
  j[key] = nullptr;
  j[key + "_reason"] = "unlabelled: labels go to the ends, the special points and every label_every-th point";
}

// CSV rows of a branch: its parameters, the branch name (if any), the CSV measures, stability and
// (with_max) the most unstable spectral value, label and type; special points as rows in their place.
void csv_rows(std::ostream& os, const MeasuredBranch& m, const char* branch, bool with_max) {
  along(m, [&](bool special, std::size_t k) {
    const std::vector<double>& parameters =
        special ? m.branch.special_points[k].parameters : m.branch.points[k].parameters;
    const std::vector<MeasureValue>& values = special ? m.special_measures[k] : m.point_measures[k];
    for (std::size_t i = 0; i < parameters.size(); ++i) os << (i ? "," : "") << csv_number(parameters[i]);
    if (branch) os << ',' << branch;
    for (std::size_t i = 0; i < m.measure_names.size(); ++i)
      if (is_csv_measure(m.measure_names[i])) {
        os << ',';
        put_csv_value(os, values[i]);
      }
    if (special) {
      os << ",," << (with_max ? "," : "");
    } else {
      const BranchPoint& pt = m.branch.points[k];
      os << ',' << (pt.stable ? 1 : 0) << ',' << pt.n_unstable;
      if (with_max) os << ',' << csv_number(most_unstable(pt.spectrum, m.spectrum_kind));
    }
    const int label = special ? m.special_label(k) : m.point_label(k);
    os << ',';
    if (label > 0) os << label;
    os << ',' << (special ? to_string(m.branch.special_points[k].type) : m.point_type(k)) << '\n';
  });
}

void csv_header(std::ostream& os, const std::vector<std::string>& parameters, bool with_label, const MeasuredBranch& m,
                bool with_max) {
  for (std::size_t i = 0; i < parameters.size(); ++i) os << (i ? "," : "") << parameters[i];
  if (with_label) os << ",branch";
  for (const auto& n : m.measure_names)
    if (is_csv_measure(n)) os << ',' << n;
  os << ",stable,n_unstable";
  if (with_max) os << ',' << most_unstable_key(m.spectrum_kind);
  os << ",label,type\n";
}

// "N points in P from a to b, status s (message)".
void branch_line(std::ostream& os, const Branch& b, const std::string& parameter) {
  os << b.points.size() << " points in " << parameter;
  if (!b.points.empty()) os << " from " << b.points.front().p << " to " << b.points.back().p;
  os << ", status " << to_string(b.status) << " (" << b.message << ")\n";
}

// A BP's mode change in branch order: "unstable" when the unstable count rises across it, "stable" when
// it falls, "" when it does not change.
std::string mode_direction(const SpecialPoint& sp) {
  if (sp.unstable_after == sp.unstable_before) return "";
  return sp.unstable_after > sp.unstable_before ? "unstable" : "stable";
}

// ", mode l = 4 m = 0 becoming stable" for a BP whose mode is known, else "".
std::string mode_text(const SpecialPoint& sp) {
  if (!sp.mode_l) return "";
  std::string t = ", mode l = " + std::to_string(*sp.mode_l);
  if (sp.mode_m) t += " m = " + std::to_string(*sp.mode_m);
  const std::string d = mode_direction(sp);
  return d.empty() ? t : t + " becoming " + d;
}

void special_lines(std::ostream& os, const Branch& b, const std::string& parameter, const char* indent) {
  for (const auto& sp : b.special_points)
    os << indent << sp.name << " " << parameter << " = " << sp.p << " (" << to_string(sp.status) << ", precision "
       << sp.precision << ", unstable " << sp.unstable_before << " -> " << sp.unstable_after << mode_text(sp) << ")"
       << (sp.normal_form ? "; " + to_text(*sp.normal_form, parameter) : "") << "\n";
}

// The text table's measures: the chosen ones, or the default list those of the branch.
std::vector<std::string> table_measures(const MeasuredBranch& m, const TableOptions& table) {
  if (!table.measures.empty()) {
    table.validate(m.measure_names);
    return table.measures;
  }
  std::vector<std::string> out;
  for (const char* name : {"r", "Psi", "sigma", "Delta_2", "omega", "sigma_bar", "mode", "r_min", "r_max", "kind"})
    if (std::find(m.measure_names.begin(), m.measure_names.end(), name) != m.measure_names.end())
      out.emplace_back(name);
  return out;
}

// "stable" for no unstable eigenvalue (multiplier), else "unstable n".
std::string stability_word(int n_unstable) {
  return n_unstable == 0 ? "stable" : "unstable " + std::to_string(n_unstable);
}

// AUTO's b-file table: one row per labelled point of the branches (BR 1, 2, ...), in order along each.
void b_table(std::ostream& os, const std::vector<const MeasuredBranch*>& branches, const TableOptions& table) {
  const MeasuredBranch* first = nullptr;
  for (const MeasuredBranch* m : branches)
    if (!first && !m->branch.points.empty()) first = m;
  if (!first) return;
  const std::vector<std::string> measures = table_measures(*branches.back(), table);
  // The curve's parameters (two) head the table; a one-parameter branch of a curve run fills the first.
  const std::vector<std::string>& parameters = branches.back()->branch.parameter_names.empty()
                                                   ? first->branch.parameter_names
                                                   : branches.back()->branch.parameter_names;
  constexpr int w = 17;
  os << std::setw(3) << "BR" << std::setw(7) << "PT" << std::setw(4) << "TY" << std::setw(6) << "LAB";
  for (const auto& n : parameters) os << std::setw(w) << n;
  for (const auto& n : measures) os << std::setw(w) << n;
  os << "  stability\n";
  for (std::size_t b = 0; b < branches.size(); ++b) {
    const MeasuredBranch& m = *branches[b];
    std::vector<std::size_t> columns;  // this branch's index of each table measure, or npos
    for (const auto& n : measures) {
      const auto it = std::find(m.measure_names.begin(), m.measure_names.end(), n);
      columns.push_back(it == m.measure_names.end() ? std::string::npos
                                                    : static_cast<std::size_t>(it - m.measure_names.begin()));
    }
    along(m, [&](bool special, std::size_t k) {
      const int label = special ? m.special_label(k) : m.point_label(k);
      if (label <= 0) return;
      const std::vector<double>& values =
          special ? m.branch.special_points[k].parameters : m.branch.points[k].parameters;
      const std::vector<MeasureValue>& row = special ? m.special_measures[k] : m.point_measures[k];
      const std::size_t pt = special ? m.branch.special_points[k].after_index : k;
      os << std::setw(3) << b + 1 << std::setw(7) << (std::to_string(pt) + (special ? "+" : "")) << std::setw(4)
         << (special ? to_string(m.branch.special_points[k].type) : m.point_type(k)) << std::setw(6) << label;
      for (std::size_t i = 0; i < parameters.size(); ++i) {
        os << std::setw(w);
        if (i < values.size())
          os << values[i];
        else
          os << "";
      }
      for (std::size_t c : columns) {
        os << std::setw(w);
        if (c == std::string::npos)
          os << "";
        else
          put_value(os, row[c]);
      }
      if (special) {
        const SpecialPoint& sp = m.branch.special_points[k];
        os << "  ";
        if (sp.unstable_after == sp.unstable_before)
          os << stability_word(sp.unstable_before);
        else
          os << "unstable " << sp.unstable_before << " -> " << sp.unstable_after;
        if (sp.mode_l) os << " (l = " << *sp.mode_l << (sp.mode_m ? " m = " + std::to_string(*sp.mode_m) : "") << ')';
        os << '\n';
      } else {
        const BranchPoint& q = m.branch.points[k];
        // The certified label: a margin within its error reads "uncertain", whatever the count says.
        if (q.stability == Stability::uncertain)
          os << "  uncertain (" << stability_word(q.n_unstable) << "; " << to_string(q.uncertain_because) << ")\n";
        else
          os << "  " << (q.stable ? "stable" : stability_word(q.n_unstable)) << '\n';
      }
    });
  }
}

}  // namespace

std::string spectrum_key(StabilityKind kind) {
  return kind == StabilityKind::eigenvalues ? "eigenvalues" : "multipliers";
}

std::string most_unstable_key(StabilityKind kind) {
  return kind == StabilityKind::eigenvalues ? "max_Re_eig" : "max_abs_multiplier";
}

double most_unstable(const Eigen::VectorXcd& spectrum, StabilityKind kind) {
  double m = kind == StabilityKind::eigenvalues ? -std::numeric_limits<double>::infinity() : 0.0;
  for (Eigen::Index i = 0; i < spectrum.size(); ++i)
    m = std::max(m, kind == StabilityKind::eigenvalues ? spectrum[i].real() : std::abs(spectrum[i]));
  return m;
}

nlohmann::json to_json(const MeasuredBranch& m) {
  const Branch& b = m.branch;
  const std::string spectrum = spectrum_key(m.spectrum_kind);
  nlohmann::json pts = nlohmann::json::array();
  for (std::size_t k = 0; k < b.points.size(); ++k) {
    const BranchPoint& pt = b.points[k];
    nlohmann::json j = point_json(m, pt.parameters, m.point_measures[k]);
    put_label(j, "label", m.point_label(k));
    j["type"] = m.point_type(k);
    j["stable"] = pt.stable;
    j["n_unstable"] = pt.n_unstable;
    put_stability(j, pt);
    nlohmann::json ev = nlohmann::json::array();
    for (Eigen::Index i = 0; i < pt.spectrum.size(); ++i) ev.push_back(complex_json(pt.spectrum[i]));
    j[spectrum] = ev;
    pts.push_back(j);
  }
  nlohmann::json sps = nlohmann::json::array();
  for (std::size_t k = 0; k < b.special_points.size(); ++k) {
    const SpecialPoint& sp = b.special_points[k];
    nlohmann::json j = point_json(m, sp.parameters, m.special_measures[k]);
    j["type"] = to_string(sp.type);
    j["name"] = sp.name;
    put_label(j, "label", m.special_label(k));
    if (sp.type == SpecialPointType::PD || sp.type == SpecialPointType::NS || sp.type == SpecialPointType::HB)
      j["critical"] = complex_json(sp.eigenvalue);
    j["bracket"] = {number_or_null(sp.p_lo), number_or_null(sp.p_hi)};
    j["precision"] = number_or_null(sp.precision);
    j["status"] = to_string(sp.status);
    j["unstable_before"] = sp.unstable_before;
    j["unstable_after"] = sp.unstable_after;
    if (sp.type == SpecialPointType::BP || sp.type == SpecialPointType::HB) {
      j["mode_l"] = sp.mode_l ? nlohmann::json(*sp.mode_l) : nlohmann::json(nullptr);
      j["mode_m"] = sp.mode_m ? nlohmann::json(*sp.mode_m) : nlohmann::json(nullptr);
      const std::string d = mode_direction(sp);
      j["mode_direction"] = sp.mode_l && !d.empty() ? nlohmann::json(d) : nlohmann::json(nullptr);
    }
    if (sp.normal_form) j["normal_form"] = to_json(*sp.normal_form);
    put_stability(j, sp);
    sps.push_back(j);
  }
  const ContinuationCounters& c = b.counters;
  return {{"branch", pts},
          {"special_points", sps},
          {"status", to_string(b.status)},
          {"message", b.message},
          {"counters",
           {{"steps", c.steps},
            {"rejected_steps", c.rejected_steps},
            {"unconfirmed_steps", c.unconfirmed_steps},
            {"newton_iterations", c.newton_iterations},
            {"residual_evaluations", c.residual_evaluations},
            {"jacobian_evaluations", c.jacobian_evaluations},
            {"location_iterations", c.location_iterations}}}};
}

nlohmann::json to_json(const StartPoint& s, bool orbit) {
  nlohmann::json start{{"method", to_string(s.method)},
                       {"p", number_or_null(s.p)},
                       {"newton", s.newton},
                       {"converged", s.converged},
                       {"iterations", s.iterations},
                       {"residual_norm", number_or_null(s.residual_norm)},
                       {"stable", s.stable},
                       {"n_unstable", s.n_unstable},
                       {"refused", s.refused},
                       {"message", s.message}};
  put_stability(start, s);
  if (orbit) {
    start["relaxation_periods"] = s.relaxation_periods;
    start["periodicity_defect"] = number_or_null(s.periodicity_defect);
    start["periodicity_tol"] = number_or_null(s.periodicity_tol);
    start["relaxed"] = s.relaxed;
  }
  explain_nulls(start,
                s.converged ? "not finite at the start point" : "not computed: the start failed (" + s.message + ")");
  return start;
}

nlohmann::json to_json(const SceneBranch& r) {
  nlohmann::json j = to_json(r.branch);
  put_header(j, r.spec);
  j["start"] = to_json(r.start, is_orbit(r.spec.kind));
  if (r.switched) {
    nlohmann::json sw = to_json(r.switched->branch);
    sw["switched"] = r.switched->switched;
    put_label(sw, "bp_label", r.switched->bp_label);
    if (!r.switched->switched) sw["message"] = r.switched->message;
    j["switched_branch"] = sw;
  }
  explain_nulls(j, nonfinite_reason(r.spec.scene.parameters));
  return j;
}

nlohmann::json to_json(const SceneCurve& r) {
  nlohmann::json j = to_json(r.curve);
  put_header(j, r.one.spec);
  const std::string p1 = to_string(r.one.spec.parameter), p2 = to_string(*r.spec.parameter2);
  j["free_parameter"] = p2;
  nlohmann::json start{{"type", to_string(r.start.type)},
                       {"name", r.start.name},
                       {p1, number_or_null(r.start.p)},
                       {p2, number_or_null(r.start_p2)},
                       {"precision", number_or_null(r.start.precision)},
                       {"status", to_string(r.start.status)}};
  j["curve"] = {{"type", to_string(r.spec.type)},
                {"parameters", {p1, p2}},
                {"start", start},
                {"one_parameter_points", r.one.branch.branch.points.size()},
                {"system", to_string(r.system)}};
  j["one_parameter_branch"] = to_json(r.one.branch);
  explain_nulls(j, nonfinite_reason(r.one.spec.scene.parameters));
  return j;
}

nlohmann::json to_json(const ContinuationRun& run) {
  return std::visit([](const auto& r) { return to_json(r); }, run);
}

nlohmann::json to_json(const ContinuationRun& run, const std::string& L_reason) {
  nlohmann::json j = to_json(run);
  put_truncation(j, run_L(run), L_reason);
  return j;
}

std::string to_csv(const SceneBranch& r) {
  // Kinds that can switch label their rows, so a switched branch can follow in the same table.
  const bool labelled = !is_orbit(r.spec.kind);
  std::ostringstream ss;
  ss << std::setprecision(17);
  csv_header(ss, {to_string(r.spec.parameter)}, labelled, r.branch, true);
  csv_rows(ss, r.branch, labelled ? "primary" : nullptr, true);
  if (r.switched && r.switched->switched) csv_rows(ss, r.switched->branch, "switched", true);
  return ss.str();
}

std::string to_csv(const SceneCurve& r) {
  std::ostringstream ss;
  ss << std::setprecision(17);
  csv_header(ss, {to_string(r.one.spec.parameter), to_string(*r.spec.parameter2)}, false, r.curve, false);
  csv_rows(ss, r.curve, nullptr, false);
  return ss.str();
}

std::string to_csv(const ContinuationRun& run) {
  return std::visit([](const auto& r) { return to_csv(r); }, run);
}

TableOptions TableOptions::from_list(const std::string& comma_separated) {
  TableOptions t;
  if (comma_separated.empty()) return t;
  for (std::size_t start = 0;;) {
    const std::size_t comma = comma_separated.find(',', start);
    t.measures.push_back(comma_separated.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (t.measures.back().empty())
      throw InvalidArgument("measures", "measures = '" + comma_separated +
                                            "' has an empty name: give names separated "
                                            "by single commas, e.g. r,Psi,sigma");
    if (comma == std::string::npos) return t;
    start = comma + 1;
  }
}

void TableOptions::validate(const std::vector<std::string>& available) const {
  for (const std::string& name : measures)
    if (std::find(available.begin(), available.end(), name) == available.end()) {
      std::string list;
      for (const auto& n : available) list += (list.empty() ? "" : ", ") + n;
      throw InvalidArgument("measures",
                            "measures = '" + name + "' is not a measure of this branch: must be one of " + list);
    }
}

std::string to_text(const SceneBranch& r, const TableOptions& table) {
  const std::string p = to_string(r.spec.parameter);
  TextStream ss;
  ss << std::setprecision(10);
  branch_line(ss, r.branch.branch, p);
  special_lines(ss, r.branch.branch, p, "");
  std::vector<const MeasuredBranch*> branches{&r.branch};
  if (r.switched && r.switched->switched) {
    const SpecialPoint* bp = find_special_point(r.branch.branch, SpecialPointType::BP, r.switched->bp_number);
    ss << "switched at " << (r.spec.switch_at_bp ? "the first BP: " : "BP ") << "label " << r.switched->bp_label;
    if (bp) ss << " at " << p << " = " << bp->p;
    ss << (r.spec.switch_at_bp ? " (the first met from the start); " : "; ");
    branch_line(ss, r.switched->branch.branch, p);
    special_lines(ss, r.switched->branch.branch, p, "  ");
    branches.push_back(&r.switched->branch);
  }
  b_table(ss, branches, table);
  return ss.str();
}

std::string to_text(const SceneCurve& r, const TableOptions& table) {
  const std::string p1 = to_string(r.one.spec.parameter), p2 = to_string(*r.spec.parameter2);
  const Branch& c = r.curve.branch;
  TextStream ss;
  ss << std::setprecision(10) << to_string(r.spec.type) << " curve from " << r.start.name << " (" << p1 << " = "
     << r.start.p << "): " << c.points.size() << " points in (" << p1 << ", " << p2 << ")";
  if (!c.points.empty()) ss << ", " << p2 << " from " << c.points.front().p << " to " << c.points.back().p;
  ss << ", status " << to_string(c.status) << " (" << c.message << ")\n";
  for (const auto& sp : c.special_points)
    ss << sp.name << " " << p1 << " = " << sp.parameters[0] << ", " << p2 << " = " << sp.parameters[1] << " ("
       << to_string(sp.status) << ", precision " << sp.precision << ")\n";
  b_table(ss, {&r.one.branch, &r.curve}, table);
  return ss.str();
}

std::string to_text(const ContinuationRun& run, const TableOptions& table) {
  return std::visit([&](const auto& r) { return to_text(r, table); }, run);
}

}  // namespace rbcstab
