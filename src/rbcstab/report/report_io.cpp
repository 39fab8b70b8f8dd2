#include "rbcstab/report/report_io.hpp"

#include <utility>
#include <vector>

#include "rbcstab/core/progress.hpp"
#include "rbcstab/core/text.hpp"
#include "rbcstab/io/json.hpp"
#include "rbcstab/verdict/verdict_io.hpp"

namespace rbcstab {

nlohmann::json report_json(const SceneFile& file, const ReportOptions& options, const ReportResult& r) {
  nlohmann::json j;
  j["output"] = options.output;
  j["files"] = r.files;
  j["summary"] = to_json(r.run, file.scene.parameters);
  if (r.has_reduced) j["reduced_summary"] = to_json(r.reduced, file.scene.parameters);
  j["shape"] = {{"rho_min", r.shape.rho_min}, {"rho_max", r.shape.rho_max}};
  j["seconds"] = r.seconds;
  put_truncation(j, file);
  put_physical(j, file.scene);
  if (file.scene.physical) j["shear_rate_thresholds"] = to_json(r.shear_rate_thresholds);
  j["convergence"] = convergence_json(r.convergence, options.convergence);
  return j;
}

std::string report_text(const ReportOptions& options, const ReportResult& r) {
  TextStream s;
  s << "report written to " << options.output << " (" << r.files.size()
    << " files, open index.html); l_Delta = " << r.run.l_Delta << ", status " << to_string(r.run.status);
  if (const auto& c = r.convergence; c.run) {
    const std::size_t rows = c.run->rows.size() + (c.reduced ? c.reduced->rows.size() : 0);
    const std::size_t runs = c.run->runs.size() + (c.reduced ? c.reduced->runs.size() : 0);
    const double seconds = c.run->seconds + (c.reduced ? c.reduced->seconds : 0);
    s << "; convergence: " << c.flagged() << " of " << rows << " numbers flagged (" << runs << " refined runs, "
      << duration_text(seconds) << ")";
  }
  s << "\n";
  return s.str();
}

std::vector<std::string> report_failures(const SceneFile& file, const ReportResult& r) {
  std::vector<std::string> out;
  for (const auto& [what, run] : {std::pair{"the run", &r.run}, std::pair{"the reduced companion run", &r.reduced}}) {
    if ((run == &r.reduced && !r.has_reduced) || run->status == IntegrationStatus::success) continue;
    TextStream s;
    s << what << " stopped at t = " << run->t_reached << ": " << run_reason(*run, file.scene.parameters)
      << "; the report shows it up to that time";
    out.push_back(s.str());
  }
  return out;
}

nlohmann::json panel_report_json(const SceneFile& file, const ReportOptions& options, const PanelReportResult& r) {
  nlohmann::json j;
  j["output"] = options.output;
  j["panel"] = to_string(r.kind);
  j["files"] = r.report.files;
  j["status"] = r.status;
  j["failed"] = r.failed;
  nlohmann::json facts = nlohmann::json::object();
  for (const auto& [k, v] : r.facts) facts[k] = v;
  j["facts"] = facts;
  j["compute_seconds"] = r.compute_seconds;
  j["seconds"] = r.report.seconds + r.compute_seconds;
  put_truncation(j, file);
  return j;
}

std::string panel_report_text(const ReportOptions& options, const PanelReportResult& r) {
  TextStream s;
  s << "report written to " << options.output << " (" << to_string(r.kind) << " panel, " << r.report.files.size()
    << " files, open index.html); status " << r.status << "\n";
  return s.str();
}

nlohmann::json paper_json(const PaperOptions& options, const PaperResult& r) {
  nlohmann::json j;
  j["output"] = options.output;
  j["figures"] = r.figures.size();
  j["claims"] = r.claims.size();
  j["passed"] = r.passed;
  j["failed"] = r.failed;
  j["inconsistent"] = r.inconsistent;
  j["failed_runs"] = r.failed_runs;
  j["seconds"] = r.seconds;
  nlohmann::json failed = nlohmann::json::array();
  for (const auto& c : r.claims)
    if (!c.passed)
      failed.push_back({{"figure", c.figure},
                        {"claim", c.claim},
                        {"measured", c.measured},
                        {"expected", c.expected},
                        {"inconsistency", c.inconsistency}});
  j["failed_claims"] = failed;
  return j;
}

std::string paper_text(const PaperOptions& options, const PaperResult& r) {
  TextStream s;
  s << "paper written to " << options.output << " (" << r.figures.size() << " figures, open index.html) in "
    << duration_text(r.seconds) << "; claims: " << r.passed << " passed, " << r.failed << " failed (" << r.inconsistent
    << " of them paper/model inconsistencies)\n";
  for (const auto& c : r.claims)
    if (!c.passed)
      s << "  FAILED " << c.figure << ": " << c.claim << "\n    measured " << c.measured << "; expected " << c.expected
        << "\n"
        << (c.inconsistency.empty() ? "" : "    paper/model inconsistency: " + c.inconsistency + "\n");
  return s.str();
}

nlohmann::json plot_json(const PlotSpec& spec, const PlotFiles& files) {
  nlohmann::json series = nlohmann::json::array();
  for (const PlotSeries& s : spec.series) series.push_back({{"name", s.name}, {"kind", s.kind}, {"role", s.role}});
  return {{"png", files.png}, {"json", files.json},           {"x", spec.x.name},          {"y", spec.y.name},
          {"series", series}, {"points", spec.points.size()}, {"measures", spec.measures}, {"notes", spec.notes}};
}

std::string plot_text(const PlotSpec& spec, const PlotFiles& files) {
  std::size_t marked = 0;
  for (const PlotPoint& p : spec.points) marked += !p.text.empty();
  TextStream s;
  s << "plot written to " << files.png << " (what was drawn: " << files.json << "): " << spec.y.name << " against "
    << spec.x.name << ", " << spec.series.size() << " series, " << spec.points.size() << " marked points (" << marked
    << " texts)\n";
  s << "--x/--y accept:";
  for (const auto& m : spec.measures) s << ' ' << m;
  s << "\n";
  return s.str();
}

}  // namespace rbcstab
