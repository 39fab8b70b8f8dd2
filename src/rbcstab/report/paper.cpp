// The paper's entry points: its options, where its scene files are, and build_paper, which composes the figures
// (paper_fig*.cpp, paper_app*.cpp) in a staging folder, writes paper.json and claims.json, has
// python/paper_draw.py draw them, writes the page (paper_page.cpp) and publishes the folder whole.
#include "rbcstab/report/paper.hpp"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <system_error>
#include <vector>

#include "rbcstab/core/error.hpp"
#include "rbcstab/io/files.hpp"
#include "rbcstab/report/detail/paper_composer.hpp"
#include "rbcstab/report/detail/paper_figures.hpp"
#include "rbcstab/report/detail/paper_page.hpp"
#include "rbcstab/report/detail/provenance.hpp"
#include "rbcstab/report/detail/staging.hpp"
#include "rbcstab/report/report.hpp"

#ifndef RBCSTAB_PAPER_SOURCE_SCENE_DIR
#define RBCSTAB_PAPER_SOURCE_SCENE_DIR ""
#endif

namespace rbcstab {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {
struct Stopped {};  // options.stop was set: the staging folder is dropped

bool has_file(const fs::path& dir, const char* name) {
  std::error_code ec;
  return !dir.empty() && fs::is_regular_file(dir / name, ec);
}
}  // namespace

void PaperOptions::validate() const {
  if (output.empty()) throw InvalidArgument("output", "output: a folder path is required");
  require(threads >= 0 && threads <= 4096, "threads", threads, "an integer in [0, 4096] (0: all cores)");
  if (python.empty()) throw InvalidArgument("python", "python: an interpreter path is required");
}

namespace {
// The stamp of the paper's pages: its scenes are every scene file of the folder, hashed in name order.
detail::Provenance paper_provenance(const std::string& scene_dir) {
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(scene_dir))
    if (e.path().extension() == ".toml") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  std::vector<std::string> texts;
  for (const fs::path& f : files) texts.push_back(read_file(f.string()));
  return detail::make_provenance(texts, "the " + std::to_string(files.size()) + " scene files of " + scene_dir);
}
}  // namespace

std::string find_scene_dir(const std::string& executable_path) {
  constexpr const char* probe = "fig3_b_op.toml";
  if (const char* env = std::getenv("RBCSTAB_DATA_DIR"); env && *env)
    if (has_file(fs::path(env) / "scenes", probe)) return (fs::path(env) / "scenes").string();
  if (!executable_path.empty()) {
    const fs::path d = fs::path(executable_path).parent_path() / ".." / "share" / "rbcstab" / "scenes";
    if (has_file(d, probe)) return fs::weakly_canonical(d).string();
  }
  if (has_file(RBCSTAB_PAPER_SOURCE_SCENE_DIR, probe)) return RBCSTAB_PAPER_SOURCE_SCENE_DIR;
  return "";
}

PaperResult build_paper(const PaperOptions& options) {
  using namespace detail::paper;  // the Composer, the figures and the page
  const auto start = std::chrono::steady_clock::now();
  options.validate();
  PaperOptions o = options;
  if (o.script_dir.empty()) o.script_dir = find_script_dir("");
  if (!has_file(o.script_dir, "paper_draw.py"))
    throw ReportError("script_dir: paper_draw.py not found (looked in '" + o.script_dir +
                      "', $RBCSTAB_DATA_DIR, <prefix>/share/rbcstab/python); set RBCSTAB_DATA_DIR");
  if (o.scene_dir.empty()) o.scene_dir = find_scene_dir("");
  if (!has_file(o.scene_dir, "fig3_b_op.toml"))
    throw InvalidArgument("scene_dir", "scene_dir = '" + o.scene_dir + "' holds no paper scenes (fig3_b_op.toml, ...)");
  check_python(o.python);
  const fs::path target = detail::output_target(o.output, o.overwrite);

  PaperResult res;
  try {
    detail::in_staging_folder(target, [&](const fs::path& tmp) {
      Composer c(o, tmp, res);
      c.set_scene_dir(o.scene_dir);
      const int n = 10;
      int k = 0;
      const std::vector<std::function<void()>> steps = {
          [&] { fig2(c, ++k, n); },
          [&] { fig3(c, ++k, n); },
          [&] { fig4(c, ++k, n); },
          [&] { fig5(c, ++k, n); },
          [&] { fig6(c, ++k, n); },
          [&] { app_vesicle(c, false, ++k, n); },
          [&] { app_vesicle(c, true, ++k, n); },
          [&] { app_in_plane_diagrams(c, ++k, n); },
          [&] { app_suppressed(c, ++k, n); },
      };
      for (const auto& step : steps) {
        step();
        if (c.stopped()) {
          res.complete = false;
          throw Stopped{};  // removes the staging folder; caught below
        }
      }
      for (const auto& cl : res.claims) {
        (cl.passed ? res.passed : res.failed) += 1;
        res.inconsistent += !cl.passed && !cl.inconsistency.empty();
      }
      json spec{{"format", "rbcstab-paper"}, {"version", 1}, {"quick", o.quick}, {"figures", c.figures}};
      spec["provenance"] = detail::provenance_json(paper_provenance(o.scene_dir));
      json claims = json::array();
      for (const auto& cl : res.claims)
        claims.push_back({{"figure", cl.figure},
                          {"claim", cl.claim},
                          {"measured", cl.measured},
                          {"expected", cl.expected},
                          {"passed", cl.passed},
                          {"how", cl.how},
                          {"check", cl.check},
                          {"inconsistency", cl.inconsistency}});
      write_file_atomic((tmp / "paper.json").string(), spec.dump(1) + "\n");
      write_file_atomic((tmp / "claims.json").string(), claims.dump(1) + "\n");
      res.files.insert(res.files.end(), {"paper.json", "claims.json"});
      if (o.on_step) o.on_step("drawing the figures with " + o.python, n, n);
      const std::string log = (tmp / "plot.log").string();
      const int rc = run_process({o.python, (fs::path(o.script_dir) / "paper_draw.py").string(), tmp.string()}, log);
      if (rc != 0)
        throw ReportError("the plotting script failed (exit " + std::to_string(rc) +
                          "): " + detail::log_tail(log, 1500));
      for (const auto& f : c.figures) {
        res.files.push_back(f["png"].get<std::string>());
        if (f.contains("svg")) res.files.push_back(f["svg"].get<std::string>());
      }
      res.files.push_back("plot.log");
      write_file_atomic((tmp / "index.html").string(), paper_html(spec, res, o));
      res.files.push_back("index.html");
      detail::publish_folder(tmp, target);
    });
  } catch (const Stopped&) {
    res.complete = false;
  }
  res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return res;
}

}  // namespace rbcstab
