// Drawing a bifurcation diagram: the JSON of what is drawn (to_json), and draw_plot, which has
// rbcstab_report.py render it into a PNG and writes both files whole or not at all.
#include <cctype>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <system_error>
#include <vector>

#include "rbcstab/core/error.hpp"
#include "rbcstab/io/files.hpp"
#include "rbcstab/io/json.hpp"
#include "rbcstab/report/bifurcation_plot.hpp"
#include "rbcstab/report/detail/plot_branch.hpp"
#include "rbcstab/report/detail/staging.hpp"
#include "rbcstab/report/report.hpp"

namespace rbcstab {

namespace fs = std::filesystem;
using nlohmann::json;

json to_json(const PlotSpec& spec) {
  using namespace detail::plot;  // the branch readers (detail/plot_branch.hpp)
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
                      {"text", p.text},
                      {"criticality", p.criticality}});
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

namespace {
bool is_plot_document(const fs::path& path) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) return false;
  const json doc = json::parse(read_file(path.string(), "output"), nullptr, /*allow_exceptions=*/false);
  return doc.is_object() && doc.value("format", std::string()) == "rbcstab-plot";
}
}  // namespace

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
  // The JSON of what was drawn may replace an earlier one, never another file that happens to share the stem
  // (`continue --diagram --save d.json` then `plot d.b*.json --output d.png`).
  if (fs::exists(json_path, ec) && !is_plot_document(json_path))
    throw InvalidArgument("output", "output = '" + o.output + "' would write the JSON of what was drawn over " +
                                        json_path.string() + ", which is not a plot's JSON (format rbcstab-plot); " +
                                        "choose another name");
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
      throw ReportError("the plotting script failed (exit " + std::to_string(rc) +
                        "): " + detail::log_tail(log.string(), 1500));
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
