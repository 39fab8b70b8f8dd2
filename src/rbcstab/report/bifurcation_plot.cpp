// What a bifurcation diagram draws (plot_spec): the axes, each input's series and their stability segments, the
// special and labelled points placed on them, the legend names and the title; and the axis labels (tex_symbol).
#include "rbcstab/report/bifurcation_plot.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <map>
#include <set>
#include <sstream>
#include <tuple>

#include "rbcstab/core/error.hpp"
#include "rbcstab/io/json.hpp"
#include "rbcstab/model/parameter_table.hpp"
#include "rbcstab/report/detail/plot_branch.hpp"

namespace rbcstab {

namespace fs = std::filesystem;
using nlohmann::json;

namespace detail::plot {
namespace {

// Coinciding special points share one text when they are this close in both axes (fraction of the span):
// closer than about a character at the default size.
constexpr double kCoincident = 0.01;

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
  s.name = (is_curve(j)         ? j["curve"].value("type", std::string("special-point")) + " curve"
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
    // Sub/supercritical from the point's normal form (continuation/normal_form.hpp), marked in the text.
    if (const auto nf = p.find("normal_form"); nf != p.end() && nf->is_object() && nf->contains("criticality")) {
      const std::string c = nf->at("criticality").is_string() ? nf->at("criticality").get<std::string>() : "";
      if (c == "supercritical" || c == "subcritical") {
        q.criticality = c;
        q.text += c == "supercritical" ? " super" : " sub";
      }
    }
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
        xlo = std::min(xlo, s.x[k]), xhi = std::max(xhi, s.x[k]), ylo = std::min(ylo, s.y[k]),
        yhi = std::max(yhi, s.y[k]);
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
  for (const SceneParameter q : held_parameters()) {
    const std::string name = to_string(q);
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
}  // namespace detail::plot

PlotSpec plot_spec(const std::vector<PlotInput>& inputs, const PlotOptions& o) {
  using namespace detail::plot;  // the branch readers (detail/plot_branch.hpp)
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
  using namespace detail::plot;  // the branch readers (detail/plot_branch.hpp)
  // A scene parameter's symbol is its row's (model/parameter_table.hpp); the map holds the branch quantities.
  for (const ParameterRow& row : parameter_table())
    if (name == row.name)
      return std::string("$") + row.symbol + "$" + (*row.unit ? std::string(" [") + row.unit + "]" : "");
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

}  // namespace rbcstab
