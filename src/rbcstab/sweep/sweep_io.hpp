#pragma once
// JSON, CSV and text views of the sweep results (Fig. 6e table, traced boundaries, diagram runs and merges),
// shared by the command line, the report and any other front end.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "rbcstab/io/scene_file.hpp"
#include "rbcstab/sweep/agreement.hpp"
#include "rbcstab/sweep/diagram.hpp"
#include "rbcstab/sweep/diagram_document.hpp"
#include "rbcstab/sweep/fig6e.hpp"
#include "rbcstab/sweep/threshold_precision.hpp"
#include "rbcstab/sweep/trace.hpp"

namespace rbcstab {

// {"rows": [...], "L", "L_reason"}: a quantity outside its domain is null with "<key>_reason" beside it.
nlohmann::json fig6e_json(const SceneFile& file, const std::vector<Fig6eRow>& rows);

// One row per traced point: curve, l, x, y, sigma_R, sigma_c, mu (round-trip digits).
std::string trace_csv(const DiagramSpec& plane, const TraceResult& t);
// The trace document (format "rbcstab-trace"): scene, plane, the options as used (criterion resolved, T: the
// scene's when options.T is 0), curves, corners, the paper's analytic lines on the plane, counters.
nlohmann::json trace_json(const SceneFile& file, const DiagramSpec& plane, const TraceOptions& options,
                          const TraceResult& t);
// The agreement block of `rbcstab trace --diagram FILE`: every predictor against the simulated points of a
// diagram document (diagram_document) of the same plane, the boundaries traced with `options`; `source` names
// the document in messages. A document of another plane or not a diagram throws InvalidArgument("diagram", ...).
nlohmann::json trace_agreement_json(const nlohmann::json& diagram_doc, const std::string& source,
                                    const DiagramSpec& plane, const TraceOptions& options, int threads);
// What a trace says besides its files, one line each: the counts and seconds and the files written, its notes,
// and every predictor's agreement when the document holds one.
std::vector<std::string> trace_summary_lines(const TraceResult& t, const nlohmann::json& trace_doc,
                                             const std::string& prefix);
// What a trace wrote, from its document: files PREFIX.csv and PREFIX.json, pieces, corners, counts, agreement.
nlohmann::json trace_brief_json(const nlohmann::json& trace_doc, const std::string& prefix);

// The points of a diagram by verdict.
struct VerdictCounts {
  std::size_t stable = 0, unstable = 0, failed = 0;
};
VerdictCounts count_verdicts(const std::vector<PointResult>& points);
// The document `rbcstab diagram` writes to PREFIX.json: the header with the scene's truncation, the points and
// their summary (diagram_json) and, when the job holds the whole grid (shard.n == 1), every predictor's agreement
// with the points (agreement_json); without agreement options, "agreement" is null (a plane that cannot be
// traced: the caller says why).
nlohmann::json diagram_document(const SceneFile& file, const DiagramSpec& spec, const std::vector<PointResult>& points,
                                const Shard& shard, const DiagramOutputOptions& output = {},
                                const std::optional<AgreementOptions>& agreement = AgreementOptions{});
// What a diagram run wrote: files PREFIX.csv and PREFIX.json, point counts by verdict, hash, seconds, truncation.
nlohmann::json diagram_brief_json(const SceneFile& file, const DiagramRun& r, const std::string& prefix);
// The closing line of a diagram run: what it computed and wrote to PREFIX.csv and PREFIX.json, or when it was
// stopped how far it got and how to resume.
std::string diagram_run_text(const DiagramRun& r, const std::string& prefix);
// What a merge of `inputs` shard files wrote.
nlohmann::json merge_brief_json(const MergeResult& m, std::size_t inputs, const std::string& prefix);

// The threshold-precision study (sweep/threshold_precision.hpp): one CSV row per located boundary (predictor,
// method, rtol, budget, ln_C, error, evaluations, rhs_evaluations, seconds, status); the document {scene, B,
// ln_C_range, references, rows, L, L_reason}, a missing number null with its reason (the row's status); the text:
// the references, then one aligned line per row.
std::string threshold_precision_csv(const ThresholdPrecision& t);
nlohmann::json threshold_precision_json(const SceneFile& file, const ThresholdPrecisionOptions& options,
                                        const ThresholdPrecision& t);
std::string threshold_precision_text(const SceneFile& file, const ThresholdPrecision& t);

// A diagram's progress line (the command line's diagram, report and paper): "diagram 12/64, 3.2 points/s, ETA
// 15.0s"; with detail also the resumed points and the elapsed time ("diagram 12/64 (4 resumed), 3.2 points/s,
// elapsed 2.5s, ETA 15.0s").
std::string progress_text(const Progress& p, bool detail);

}  // namespace rbcstab
