#include "rbcstab/report/bifurcation_plot.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <limits>
#include <map>
#include <numbers>
#include <set>
#include <sstream>
#include <tuple>

#include "rbcstab/core/error.hpp"
#include "rbcstab/io/files.hpp"
#include "rbcstab/io/json.hpp"
#include "rbcstab/model/parameter_table.hpp"
#include "rbcstab/report/detail/staging.hpp"
#include "rbcstab/report/report.hpp"

namespace rbcstab {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
// Coinciding special points share one text when they are this close in both axes (fraction of the span):
// closer than about a character at the default size.
constexpr double kCoincident = 0.01;

bool is_curve(const json& j) { return j.contains("curve"); }

std::vector<std::string> free_parameters(const json& j) {
  if (is_curve(j)) {
    const json& p = j["curve"]["parameters"];
    return {p[0].get<std::string>(), p[1].get<std::string>()};
  }
  return {j["free_parameter"].get<std::string>()};
}

// The input's problem kind; a bare branch without "kind" is an orbit when its points carry multipliers.
std::string problem_of(const json& j) {
  if (j.contains("kind") && j["kind"].is_string()) return j["kind"].get<std::string>();
  const json& pts = j["branch"];
  return !pts.empty() && pts[0].contains("multipliers") ? "orbit" : "equilibrium";
}

bool orbit_problem(const std::string& problem) { return problem == "orbit" || problem == "modal-orbit"; }

std::string level_of(const json& j, const std::string& problem) {
  if (j.contains("level") && j["level"].is_string()) return j["level"].get<std::string>();
  return problem == "modal" || problem == "modal-orbit" ? "modal" : problem == "full" ? "full" : "reduced";
}

bool is_delta_l(const std::string& key) {
  return key.size() > 6 && key.rfind("Delta_", 0) == 0 &&
         std::all_of(key.begin() + 6, key.end(), [](unsigned char c) { return std::isdigit(c); });
}

double num(const json& v) { return v.is_number() ? v.get<double>() : kNaN; }

// The measures computed here from what a point carries (see the header).
double derived(const json& p, const std::string& name) {
  auto max_over = [&](const char* key, auto&& f) {
    const auto it = p.find(key);
    if (it == p.end() || !it->is_array() || it->empty()) return kNaN;
    double m = -kInf;
    for (const json& z : *it) {
      if (!z.is_array() || z.size() != 2) return kNaN;
      const double v = f(num(z[0]), num(z[1]));
      if (!std::isfinite(v)) return kNaN;
      m = std::max(m, v);
    }
    return m;
  };
  if (name == "period") return 2 * std::numbers::pi;
  if (name == "max_abs_multiplier") return max_over("multipliers", [](double re, double im) { return std::hypot(re, im); });
  if (name == "max_Re_eig") return max_over("eigenvalues", [](double re, double) { return re; });
  if (name == "norm_Delta" || name == "norm_x") {
    double s = 0;
    bool any = false;
    if (name == "norm_Delta") {
      for (const auto& [k, v] : p.items())
        if (is_delta_l(k)) s += num(v) * num(v), any = true;
    } else if (p.contains("x") && p["x"].is_array()) {
      for (const json& v : p["x"]) s += num(v) * num(v), any = true;
    }
    return any ? std::sqrt(s) : kNaN;
  }
  return kNaN;
}

// The scene's parameters that stay fixed along an input: the material parameters and beta, except the
// free ones and those a free composite moves (Lambda through Delta, S through C: parameters.hpp; Delta,
// lambda move Lambda and C, Delta0 move S, which are therefore never fixed). Null (C = inf) is infinite.
using Fixed = std::map<std::string, double>;
Fixed fixed_parameters(const json& j) {
  std::set<std::string> moved;
  for (const std::string& q : free_parameters(j)) {
    moved.insert(q);
    if (q == "Lambda") moved.insert("Delta");
    if (q == "S") moved.insert("C");
  }
  Fixed f;
  const json* ps = j.contains("parameters") && j["parameters"].is_object() ? &j["parameters"] : nullptr;
  for (const char* name : {"lambda", "Delta", "Delta0", "B", "C", "beta"}) {
    if (moved.count(name)) continue;
    const json* v = std::string(name) == "beta" ? (j.contains("beta") ? &j["beta"] : nullptr)
                    : ps && ps->contains(name)  ? &(*ps)[name]
                                                : nullptr;
    if (v && (v->is_number() || v->is_null())) f[name] = v->is_null() ? kInf : v->get<double>();
  }
  return f;
}

// The quantity `name` of a point: its own key (null: undefined), else a derived measure, else a
// parameter the input holds fixed.
double value(const json& p, const std::string& name, const Fixed* fixed = nullptr) {
  const auto it = p.find(name);
  if (it != p.end()) return num(*it);
  if (fixed)
    if (const auto f = fixed->find(name); f != fixed->end()) return f->second;
  return derived(p, name);
}

std::string stability_of(const json& p, const std::string& source, std::size_t k) {
  if (const auto it = p.find("stability"); it != p.end() && !it->is_null()) {
    const std::string s = it->is_string() ? it->get<std::string>() : it->dump();
    if (s != "stable" && s != "unstable" && s != "uncertain")
      throw InvalidArgument("file", source + ": point " + std::to_string(k) + " has stability = '" + s +
                                        "' (must be stable, unstable or uncertain)");
    return s;
  }
  if (const auto it = p.find("stable"); it != p.end() && it->is_boolean()) return it->get<bool>() ? "stable" : "unstable";
  return "uncertain";
}

std::string style_of(const std::string& stability) {
  return stability == "unstable" ? "dashed" : stability == "uncertain" ? "dotted" : "solid";
}

std::optional<int> label_of(const json& p) {
  const auto it = p.find("label");
  if (it == p.end() || !it->is_number_integer()) return std::nullopt;
  return it->get<int>();
}

std::string type_of(const json& p) {
  const auto it = p.find("type");
  return it != p.end() && it->is_string() ? it->get<std::string>() : "";
}

// A switched branch is drawn when switching succeeded ("switched"; without the key: when it has points).
bool switched(const json& sw) {
  const bool has_points = sw.contains("branch") && sw["branch"].is_array() && !sw["branch"].empty();
  return sw.value("switched", has_points);
}

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
  return s;
}

std::string stem_of(const std::string& source) { return fs::path(source).stem().string(); }

// Which input quantity goes where, and the legend names.
struct Axes {
  std::string x, y;
};

std::string default_y(const PlotInput& in, const std::vector<std::string>& available) {
  const json& j = in.branch;
  if (is_curve(j)) return free_parameters(j)[1];
  // The reduced system's tank-treading equilibria often have r = 1 along the whole branch: Psi shows them.
  const std::string problem = problem_of(j);
  const char* preferred = problem == "orbit" ? "r_max" : problem == "equilibrium" ? "Psi" : "r";
  if (std::find(available.begin(), available.end(), preferred) != available.end()) return preferred;
  for (const auto& a : available)
    if (a != free_parameters(j)[0]) return a;
  return free_parameters(j)[0];
}

void require_available(const PlotInput& in, const std::vector<std::string>& available, const char* axis,
                       const std::string& name) {
  if (std::find(available.begin(), available.end(), name) != available.end()) return;
  throw InvalidArgument(axis, std::string(axis) + " = '" + name + "' is not a parameter or measure of " + in.source +
                                  " (available: " + join(available) + ")");
}

// The scaled coordinates a special point is matched to its branch by: the free parameter(s) and every
// number the branch's points and the special point both carry that varies along the branch, each
// divided by its span. Quantities constant up to rounding (Delta_3 = 0 or 1e-17 on the ellipsoidal
// branch) are left out: divided by their span, rounding would decide the match.
struct Matcher {
  std::vector<std::string> names;
  std::vector<double> scale;
  std::vector<std::vector<double>> at;  // [k][c]
};

Matcher matcher(const json& pts, const std::vector<std::string>& parameters) {
  static const std::set<std::string> skip{"label", "n_unstable", "winding", "margin", "margin_error"};
  Matcher m;
  if (pts.empty()) return m;
  for (const auto& [k, v] : pts[0].items()) {
    if (!(v.is_number() || v.is_null()) || skip.count(k)) continue;
    double lo = kInf, hi = -kInf, big = 1;
    for (const json& p : pts) {
      const double x = value(p, k);
      if (std::isfinite(x)) lo = std::min(lo, x), hi = std::max(hi, x), big = std::max(big, std::abs(x));
    }
    const bool parameter = std::find(parameters.begin(), parameters.end(), k) != parameters.end();
    if (!(hi > lo) || (!parameter && !(hi - lo > 1e-8 * big))) continue;
    m.names.push_back(k);
    m.scale.push_back(hi - lo);
  }
  for (const json& p : pts) {
    std::vector<double> row;
    for (const auto& n : m.names) row.push_back(value(p, n));
    m.at.push_back(row);
  }
  return m;
}

// Where a special point lies on the branch: the segment [k, k + 1] and the fraction t along it closest
// to the point in the matcher's coordinates.
struct Place {
  std::size_t k = 0;
  double t = 0;
};

Place place(const Matcher& m, const json& sp, std::size_t n) {
  Place best;
  if (n < 2) return best;
  std::vector<double> s;
  for (const auto& name : m.names) s.push_back(value(sp, name));
  double best_d = kInf;
  for (std::size_t k = 0; k + 1 < n; ++k) {
    double dd = 0, dq = 0;  // t = <s - a, b - a> / |b - a|^2 over the coordinates both carry
    for (std::size_t c = 0; c < s.size(); ++c) {
      const double a = m.at[k][c], b = m.at[k + 1][c];
      if (!std::isfinite(s[c]) || !std::isfinite(a) || !std::isfinite(b)) continue;
      dd += (b - a) * (b - a) / (m.scale[c] * m.scale[c]);
      dq += (s[c] - a) * (b - a) / (m.scale[c] * m.scale[c]);
    }
    const double t = dd > 0 ? std::clamp(dq / dd, 0.0, 1.0) : 0.0;
    double d = 0;
    for (std::size_t c = 0; c < s.size(); ++c) {
      const double a = m.at[k][c], b = m.at[k + 1][c];
      if (!std::isfinite(s[c]) || !std::isfinite(a) || !std::isfinite(b)) continue;
      const double e = (a + t * (b - a) - s[c]) / m.scale[c];
      d += e * e;
    }
    if (d < best_d) best_d = d, best = {k, t};
  }
  return best;
}

struct Vertex {
  double x, y;
  bool special;           // a special point: belongs to the segments on both sides
  std::string stability;  // of a branch point
};

// The stability segments of a one-parameter branch: a new segment starts where the stability changes,
// at the special point located there (else at the midpoint of the two branch points).
std::vector<PlotSegment> stability_segments(const std::vector<Vertex>& vs) {
  std::vector<PlotSegment> segs;
  const Vertex* last_point = nullptr;
  bool special_since_point = false;
  for (const Vertex& v : vs) {
    if (v.special) {
      if (!segs.empty()) segs.back().x.push_back(v.x), segs.back().y.push_back(v.y);
      special_since_point = true;
      continue;
    }
    if (segs.empty() || v.stability != segs.back().stability) {
      PlotSegment next{v.stability, style_of(v.stability), {}, {}};
      if (!segs.empty() && last_point) {
        PlotSegment& cur = segs.back();
        if (!special_since_point) {
          cur.x.push_back((last_point->x + v.x) / 2);
          cur.y.push_back((last_point->y + v.y) / 2);
        }
        next.x.push_back(cur.x.back());
        next.y.push_back(cur.y.back());
      }
      segs.push_back(next);
    }
    segs.back().x.push_back(v.x);
    segs.back().y.push_back(v.y);
    last_point = &v;
    special_since_point = false;
  }
  return segs;
}

struct SeriesSource {
  const PlotInput* input;
  const json* part;  // the object holding "branch" and "special_points"
  std::string role;
};

PlotSeries make_series(const SeriesSource& src, const Axes& axes, std::size_t index, bool all_labels,
                       std::vector<PlotPoint>& points) {
  const json& j = src.input->branch;
  const json& pts = (*src.part)["branch"];
  const std::size_t n = pts.size();
  const Fixed fixed = fixed_parameters(j);
  PlotSeries s;
  s.problem = problem_of(j);
  s.level = level_of(j, s.problem);
  s.kind = is_curve(j) ? "curve" : orbit_problem(s.problem) ? "orbit" : "equilibrium";
  s.role = src.role;
  s.source = src.input->source;
  const std::string level_text = s.level + (s.level == "reduced" ? " system" : " model");
  s.name = (is_curve(j) ? j["curve"].value("type", std::string("special-point")) + " curve"
            : s.kind == "orbit" ? std::string("periodic orbits")
                                : std::string("equilibria")) +
           " (" + level_text + ")" + (src.role == "switched" ? ", switched branch" : "");
  for (std::size_t k = 0; k < n; ++k) {
    s.x.push_back(value(pts[k], axes.x, &fixed));
    s.y.push_back(value(pts[k], axes.y, &fixed));
    s.stability.push_back(stability_of(pts[k], s.source, k));
  }

  // The special points, placed on the branch (a value the point lacks, e.g. a derived measure, is
  // interpolated there), and the typed or labelled branch points.
  const Matcher m = matcher(pts, free_parameters(j));
  std::vector<std::vector<std::pair<double, Vertex>>> inserted(n);
  std::set<int> special_labels;
  auto add_point = [&](double x, double y, const json& p, const std::string& marker) {
    PlotPoint q;
    q.x = x;
    q.y = y;
    q.type = type_of(p);
    if (q.type.empty() && marker != "regular") q.type = p.value("name", std::string());
    q.label = label_of(p);
    if (const auto it = p.find("stability"); it != p.end() && it->is_string()) q.stability = it->get<std::string>();
    q.series = index;
    q.marker = marker;
    q.text = q.type.empty() ? (q.label ? std::to_string(*q.label) : "")
                            : q.type + (q.label ? " " + std::to_string(*q.label) : "");
    points.push_back(q);
  };
  auto mark = [&](const json& sp) {
    if (!sp.is_object() || n == 0) return;
    const Place pl = place(m, sp, n);
    const std::size_t k1 = std::min(pl.k + 1, n - 1);
    auto at = [&](const std::vector<double>& v, const std::string& name) {
      const double own = value(sp, name, &fixed);
      return std::isfinite(own) ? own : v[pl.k] + pl.t * (v[k1] - v[pl.k]);
    };
    const double x = at(s.x, axes.x), y = at(s.y, axes.y);
    inserted[pl.k].push_back({pl.t, Vertex{x, y, true, ""}});
    add_point(x, y, sp, type_of(sp) == "EP" ? "end" : "special");
    if (const auto l = label_of(sp)) special_labels.insert(*l);
  };
  if (const auto it = src.part->find("special_points"); it != src.part->end() && it->is_array())
    for (const json& sp : *it) mark(sp);
  // A curve starts at a special point of its one-parameter branch: marked as AUTO marks a curve's start.
  if (is_curve(j) && j["curve"].contains("start")) mark(j["curve"]["start"]);
  for (std::size_t k = 0; k < n; ++k) {
    const std::string type = type_of(pts[k]);
    const auto label = label_of(pts[k]);
    if (!type.empty() && !(label && special_labels.count(*label)))
      add_point(s.x[k], s.y[k], pts[k], type == "EP" ? "end" : "special");
    else if (type.empty() && label && all_labels)
      add_point(s.x[k], s.y[k], pts[k], "regular");
  }

  std::vector<Vertex> vs;
  for (std::size_t k = 0; k < n; ++k) {
    vs.push_back(Vertex{s.x[k], s.y[k], false, s.stability[k]});
    auto& ins = inserted[k];
    std::stable_sort(ins.begin(), ins.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    for (const auto& [t, v] : ins) vs.push_back(v);
  }
  if (s.kind == "curve") {
    PlotSegment all{"curve", "solid", {}, {}};
    for (const Vertex& v : vs) all.x.push_back(v.x), all.y.push_back(v.y);
    if (!vs.empty()) s.segments.push_back(all);
  } else {
    s.segments = stability_segments(vs);
  }
  return s;
}

// Whether the text list "a, b, c" holds t as one of its items.
bool lists(const std::string& list, const std::string& t) {
  for (std::size_t from = 0; from <= list.size();) {
    const std::size_t end = std::min(list.find(", ", from), list.size());
    if (list.compare(from, end - from, t) == 0) return true;
    from = end + 2;
  }
  return false;
}

// Points close together share one text at the first of them ("LP 2, BP 3").
void merge_texts(PlotSpec& spec) {
  double xlo = kInf, xhi = -kInf, ylo = kInf, yhi = -kInf;
  for (const PlotSeries& s : spec.series)
    for (std::size_t k = 0; k < s.x.size(); ++k)
      if (std::isfinite(s.x[k]) && std::isfinite(s.y[k]))
        xlo = std::min(xlo, s.x[k]), xhi = std::max(xhi, s.x[k]), ylo = std::min(ylo, s.y[k]), yhi = std::max(yhi, s.y[k]);
  const double dx = kCoincident * (xhi > xlo ? xhi - xlo : 1), dy = kCoincident * (yhi > ylo ? yhi - ylo : 1);
  for (std::size_t i = 0; i < spec.points.size(); ++i) {
    PlotPoint& p = spec.points[i];
    for (std::size_t k = 0; k < i && !p.text.empty(); ++k) {
      PlotPoint& q = spec.points[k];
      if (q.text.empty() || !(std::abs(p.x - q.x) <= dx && std::abs(p.y - q.y) <= dy)) continue;
      if (!lists(q.text, p.text)) q.text += ", " + p.text;
      p.text.clear();
    }
  }
}

std::string number_text(double v) {
  if (std::isinf(v)) return v > 0 ? "\\infty" : "-\\infty";
  std::ostringstream ss;
  ss << std::setprecision(4) << v;
  return ss.str();
}

// The parameters every input holds fixed at the same value (fixed_parameters), except the axes.
std::string default_title(const std::vector<PlotInput>& inputs, const Axes& axes) {
  std::vector<Fixed> fixed;
  for (const PlotInput& in : inputs) fixed.push_back(fixed_parameters(in.branch));
  std::vector<std::string> parts;
  for (const char* name : {"lambda", "Delta", "Delta0", "B", "C", "beta"}) {
    if (name == axes.x || name == axes.y || !fixed[0].count(name)) continue;
    const double v = fixed[0].at(name);
    if (std::all_of(fixed.begin(), fixed.end(), [&](const Fixed& f) { return f.count(name) && f.at(name) == v; })) {
      const std::string symbol = tex_symbol(name);  // "$...$"
      parts.push_back(symbol.substr(0, symbol.size() - 1) + " = " + number_text(v) + "$");
    }
  }
  return join(parts);
}

}  // namespace

PlotInput plot_input(json j, const std::string& source) {
  auto refuse = [&](const std::string& why) {
    return InvalidArgument("file", source + " is not a branch JSON (the output of `rbcstab continue --json` or a "
                                            "branch file of --save): " + why);
  };
  if (!j.is_object()) throw refuse("not a JSON object");
  if (j.contains("format") && j["format"] != "rbcstab-branch")
    throw refuse("format = " + j["format"].dump() + " (expected \"rbcstab-branch\")");
  if (!j.contains("branch") || !j["branch"].is_array()) throw refuse("no \"branch\" array of points");
  if (!j.contains("free_parameter") || !j["free_parameter"].is_string()) throw refuse("no \"free_parameter\"");
  if (is_curve(j)) {
    const json& c = j["curve"];
    if (!c.is_object() || !c.contains("parameters") || !c["parameters"].is_array() || c["parameters"].size() != 2 ||
        !c["parameters"][0].is_string() || !c["parameters"][1].is_string())
      throw refuse("\"curve\" needs \"parameters\": [p1, p2]");
  }
  const std::vector<std::string> params = free_parameters(j);
  auto check_part = [&](const json& part, const std::string& where) {
    for (std::size_t k = 0; k < part["branch"].size(); ++k) {
      const json& p = part["branch"][k];
      if (!p.is_object()) throw refuse(where + "point " + std::to_string(k) + " is not an object");
      for (const auto& q : params)
        if (!p.contains(q)) throw refuse(where + "point " + std::to_string(k) + " has no \"" + q + "\"");
    }
    if (part.contains("special_points") && !part["special_points"].is_array())
      throw refuse(where + "\"special_points\" is not an array");
  };
  check_part(j, "");
  if (j.contains("switched_branch")) {
    const json& sw = j["switched_branch"];
    if (!sw.is_object() || (switched(sw) && !(sw.contains("branch") && sw["branch"].is_array())))
      throw refuse("\"switched_branch\" has no \"branch\" array");
    if (switched(sw)) check_part(sw, "switched branch: ");
  }
  return {source, std::move(j)};
}

PlotInput read_plot_input(const std::string& path) {
  const std::string text = read_file(path);
  json j;
  try {
    j = json::parse(text);
  } catch (const json::parse_error& e) {
    throw InvalidArgument("file", path + " is not valid JSON (truncated or not a branch file?): " + e.what());
  }
  return plot_input(std::move(j), path);
}

std::vector<std::string> plot_measures(const PlotInput& in) {
  const json& j = in.branch;
  std::vector<std::string> out = free_parameters(j);
  const json& pts = j["branch"];
  if (pts.empty()) return out;
  const json& p = pts[0];
  for (const auto& [k, v] : p.items())
    if ((v.is_number() || v.is_null()) && k != "label" && std::find(out.begin(), out.end(), k) == out.end())
      out.push_back(k);
  auto add = [&](const std::string& name, bool applies) {
    if (applies && std::find(out.begin(), out.end(), name) == out.end()) out.push_back(name);
  };
  add("period", orbit_problem(problem_of(j)) && !is_curve(j));
  add("max_abs_multiplier", p.contains("multipliers"));
  add("max_Re_eig", p.contains("eigenvalues"));
  bool has_delta = false;
  for (const auto& [k, v] : p.items()) has_delta = has_delta || is_delta_l(k);
  add("norm_Delta", has_delta);
  add("norm_x", p.contains("x") && p["x"].is_array());
  for (const auto& [name, v] : fixed_parameters(j)) add(name, true);
  return out;
}

PlotSpec plot_spec(const std::vector<PlotInput>& inputs, const PlotOptions& o) {
  if (inputs.empty()) throw InvalidArgument("inputs", "inputs: at least one branch JSON is needed");
  PlotSpec spec;
  std::vector<std::vector<std::string>> available;
  for (const PlotInput& in : inputs) available.push_back(plot_measures(in));
  Axes axes{o.x.empty() ? free_parameters(inputs[0].branch)[0] : o.x,
            o.y.empty() ? default_y(inputs[0], available[0]) : o.y};
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    require_available(inputs[i], available[i], "x", axes.x);
    require_available(inputs[i], available[i], "y", axes.y);
  }
  spec.measures = available[0];
  std::erase_if(spec.measures, [&](const std::string& m) {
    return std::any_of(available.begin() + 1, available.end(),
                       [&](const auto& a) { return std::find(a.begin(), a.end(), m) == a.end(); });
  });
  spec.x = {axes.x, tex_symbol(axes.x)};
  spec.y = {axes.y, tex_symbol(axes.y)};
  spec.title = o.title.empty() ? default_title(inputs, axes) : o.title;

  std::vector<SeriesSource> sources;
  for (const PlotInput& in : inputs) {
    sources.push_back({&in, &in.branch, "primary"});
    if (in.branch.contains("switched_branch")) {
      const json& sw = in.branch["switched_branch"];
      if (switched(sw))
        sources.push_back({&in, &sw, "switched"});
      else
        spec.notes.push_back(in.source + ": the switched branch is not drawn: " +
                             sw.value("message", std::string("branch switching failed")));
    }
    if (in.branch["branch"].empty()) spec.notes.push_back(in.source + ": the branch has no points");
  }
  for (const SeriesSource& src : sources)
    spec.series.push_back(make_series(src, axes, spec.series.size(), o.all_labels, spec.points));
  // Several inputs of the same kind: their file names tell the series apart.
  std::map<std::string, int> count;
  for (const PlotSeries& s : spec.series) ++count[s.name];
  for (PlotSeries& s : spec.series)
    if (count[s.name] > 1) s.name += ": " + stem_of(s.source);
  merge_texts(spec);
  // matplotlib widens an axis by a margin and places ticks: beyond this magnitude that overflows to inf.
  constexpr double kDrawable = 1e300;
  for (const PlotSeries& ser : spec.series)
    for (const auto& [axis, name, values] : {std::tuple{"x", axes.x, &ser.x}, std::tuple{"y", axes.y, &ser.y}})
      for (double v : *values)
        if (std::isfinite(v) && std::abs(v) > kDrawable)
          throw InvalidArgument(axis, std::string(axis) + " = " + name + " reaches " + format_value(v) + " in " +
                                          ser.source + ": values beyond 1e300 in magnitude cannot be drawn");
  return spec;
}

std::string tex_symbol(const std::string& name) {
  // A scene parameter's symbol is its row's (model/parameter_table.hpp); the map holds the branch quantities.
  for (const ParameterRow& row : parameter_table())
    if (name == row.name) return std::string("$") + row.symbol + "$" + (*row.unit ? std::string(" [") + row.unit + "]" : "");
  static const std::map<std::string, std::string> symbols{
      {"r", R"($r$)"},
      {"Psi", R"($\Psi$)"},
      {"sigma", R"($\sigma$)"},
      {"sigma_bar", R"($\bar{\sigma}$)"},
      {"omega", R"($\omega$)"},
      {"r_min", R"($r_{\min}$)"},
      {"r_max", R"($r_{\max}$)"},
      {"Psi_min", R"($\Psi_{\min}$)"},
      {"Psi_max", R"($\Psi_{\max}$)"},
      {"period", R"(period $T$)"},
      {"max_abs_multiplier", R"($\max\,|\mu|$ (Floquet multipliers))"},
      {"max_Re_eig", R"($\max\,\mathrm{Re}\,\nu$ (eigenvalues))"},
      {"norm_Delta", R"($(\sum_l \Delta_l^2)^{1/2}$)"},
      {"norm_x", R"($\|x\|_2$)"},
      {"trivial_multiplier", R"(trivial multiplier $\mu_0$)"},
      {"n_unstable", "unstable eigenvalues / multipliers"},
      {"winding", "winding number"},
      {"margin", "stability margin"},
  };
  if (const auto it = symbols.find(name); it != symbols.end()) return it->second;
  if (is_delta_l(name)) return "$\\Delta_{" + name.substr(6) + "}$";
  return name;
}

json to_json(const PlotSpec& spec) {
  auto numbers = [](const std::vector<double>& v) {
    json a = json::array();
    for (double x : v) a.push_back(number_or_null(x));
    return a;
  };
  json series = json::array();
  std::set<std::string> used;
  for (const PlotSeries& s : spec.series) {
    json segs = json::array();
    for (const PlotSegment& g : s.segments) {
      segs.push_back({{"stability", g.stability}, {"style", g.style}, {"x", numbers(g.x)}, {"y", numbers(g.y)}});
      used.insert(g.stability);
    }
    series.push_back({{"name", s.name},
                      {"kind", s.kind},
                      {"problem", s.problem},
                      {"level", s.level},
                      {"role", s.role},
                      {"source", s.source},
                      {"x", numbers(s.x)},
                      {"y", numbers(s.y)},
                      {"stability", s.stability},
                      {"segments", segs}});
  }
  json points = json::array();
  for (const PlotPoint& p : spec.points)
    points.push_back({{"x", number_or_null(p.x)},
                      {"y", number_or_null(p.y)},
                      {"type", p.type},
                      {"label", p.label ? json(*p.label) : json(nullptr)},
                      {"stability", p.stability},
                      {"series", p.series},
                      {"marker", p.marker},
                      {"text", p.text}});
  // The legend's line-style key: the stabilities drawn, in a fixed order.
  json styles = json::array();
  for (const char* s : {"stable", "unstable", "uncertain"})
    if (used.count(s)) styles.push_back({{"stability", s}, {"style", style_of(s)}});
  return {{"format", "rbcstab-plot"},
          {"version", 1},
          {"x", {{"name", spec.x.name}, {"label", spec.x.label}}},
          {"y", {{"name", spec.y.name}, {"label", spec.y.label}}},
          {"title", spec.title},
          {"series", series},
          {"points", points},
          {"styles", styles},
          {"measures", spec.measures},
          {"notes", spec.notes}};
}

void PlotDrawOptions::validate() const {
  std::string ext = fs::path(output).extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (output.empty() || ext != ".png")
    throw InvalidArgument("output", "output = '" + output + "' must be a file name ending in .png");
  std::error_code ec;
  const fs::path parent = fs::absolute(output).lexically_normal().parent_path();
  if (!fs::is_directory(parent, ec))
    throw InvalidArgument("output", "output = '" + output + "': the folder " + parent.string() + " does not exist");
  if (fs::is_directory(output, ec)) throw InvalidArgument("output", "output = '" + output + "' is a folder");
  require(width >= 200 && width <= 4000, "width", width, "an integer in [200, 4000] (pixels)");
  require(height >= 200 && height <= 4000, "height", height, "an integer in [200, 4000] (pixels)");
  if (python.empty()) throw InvalidArgument("python", "python: an interpreter path is required");
}

std::string plot_json_path(const std::string& png) { return fs::path(png).replace_extension(".json").string(); }

PlotFiles draw_plot(const PlotSpec& spec, const PlotDrawOptions& o) {
  o.validate();
  const std::string script_dir = o.script_dir.empty() ? find_script_dir("") : o.script_dir;
  std::error_code ec;
  if (script_dir.empty() || !fs::is_regular_file(fs::path(script_dir) / kReportScript, ec))
    throw ReportError("script_dir: " + std::string(kReportScript) + " not found (looked in '" + script_dir +
                      "', $RBCSTAB_DATA_DIR, <prefix>/share/rbcstab/python); set RBCSTAB_DATA_DIR");
  const fs::path png = fs::absolute(o.output).lexically_normal();
  const fs::path json_path = plot_json_path(png.string());
  // `plot b.json --output b.png` would replace its own input by the JSON of what was drawn.
  for (const PlotSeries& s : spec.series)
    if (fs::equivalent(s.source, json_path, ec))
      throw InvalidArgument("output", "output = '" + o.output + "' would write " + json_path.string() +
                                          " over the input " + s.source + "; choose another name");
  check_python(o.python);
  // Drawn under hidden names beside the targets, renamed into place when both are complete.
  const fs::path dir = png.parent_path();
  const fs::path tmp_png = dir / (detail::hidden_sibling_name(png, ".tmp-") + ".png");
  const fs::path tmp_json = dir / (detail::hidden_sibling_name(json_path, ".tmp-") + ".json");
  const fs::path log = dir / (detail::hidden_sibling_name(png, ".log-") + ".txt");
  auto cleanup = [&] {
    for (const fs::path& p : {tmp_png, tmp_json, log}) fs::remove(p, ec);
  };
  try {
    write_file_atomic(tmp_json.string(), to_json(spec).dump(1) + "\n");
    const int rc = run_process({o.python, (fs::path(script_dir) / kReportScript).string(), "plot", tmp_json.string(),
                                tmp_png.string(), std::to_string(o.width), std::to_string(o.height)},
                               log.string());
    if (rc != 0 || !fs::is_regular_file(tmp_png, ec))
      throw ReportError("the plotting script failed (exit " + std::to_string(rc) + "): " + detail::log_tail(log.string(), 1500));
    fs::rename(tmp_png, png);
    fs::rename(tmp_json, json_path);
  } catch (const fs::filesystem_error& e) {
    cleanup();
    throw ReportError(std::string("output: ") + e.what());
  } catch (...) {
    cleanup();
    throw;
  }
  cleanup();
  return {png.string(), json_path.string()};
}

}  // namespace rbcstab
