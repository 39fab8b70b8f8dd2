#pragma once
// JSON and text views of what the report module's builders return (a scene's report folder, a figure panel's, the
// paper, a bifurcation plot), shared by the command line and any other front end.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "rbcstab/io/scene_file.hpp"
#include "rbcstab/report/bifurcation_plot.hpp"
#include "rbcstab/report/panels.hpp"
#include "rbcstab/report/paper.hpp"
#include "rbcstab/report/report.hpp"

namespace rbcstab {

// A scene's report: output, files, summary (and reduced_summary), shape (rho range), seconds, the truncation, and
// for a physical scene physical and shear_rate_thresholds. The text: one line, the folder, its files, l_Delta and
// the run's status.
nlohmann::json report_json(const SceneFile& file, const ReportOptions& options, const ReportResult& r);
std::string report_text(const ReportOptions& options, const ReportResult& r);
// Each of the report's runs (the scene's, its reduced companion) that stopped before T, one line each: why the
// command exits 1 although the report was written.
std::vector<std::string> report_failures(const SceneFile& file, const ReportResult& r);
// A panel's report: output, panel, files, status, failed, facts, compute_seconds, seconds and the truncation.
nlohmann::json panel_report_json(const SceneFile& file, const ReportOptions& options, const PanelReportResult& r);
std::string panel_report_text(const ReportOptions& options, const PanelReportResult& r);
// The paper: output, counts of figures and claims, passed, failed, failed_runs, seconds and the failed claims. The
// text: one line, then each failed claim with its measured and expected value.
nlohmann::json paper_json(const PaperOptions& options, const PaperResult& r);
std::string paper_text(const PaperOptions& options, const PaperResult& r);
// A drawn plot: png, json, x, y, series (name, kind, role), points, measures, notes. The text: what was drawn and
// the measures --x and --y accept.
nlohmann::json plot_json(const PlotSpec& spec, const PlotFiles& files);
std::string plot_text(const PlotSpec& spec, const PlotFiles& files);

}  // namespace rbcstab
