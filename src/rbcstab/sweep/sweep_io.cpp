#include "rbcstab/sweep/sweep_io.hpp"

#include <iomanip>
#include <sstream>

#include "rbcstab/analysis/analysis_io.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/core/progress.hpp"
#include "rbcstab/core/text.hpp"
#include "rbcstab/io/json.hpp"
#include "rbcstab/sweep/diagram_document.hpp"
#include "rbcstab/sweep/point_record.hpp"

namespace rbcstab {

nlohmann::json fig6e_json(const SceneFile& file, const std::vector<Fig6eRow>& rows) {
  nlohmann::json j;
  put_truncation(j, file);
  j["rows"] = nlohmann::json::array();
  for (const Fig6eRow& r : rows) {
    nlohmann::json e{{"lambda", r.lambda},
                     {"B", r.B},
                     {"C", r.C},
                     {"alpha", r.alpha},
                     {"ln_alpha", r.ln_alpha},
                     {"surviving_mode", r.surviving_mode},
                     {"l_Delta", r.l_Delta}};
    put(e, "Delta2_tilde", r.Delta2_tilde);
    put(e, "Delta2_tilde_integer_mode", r.Delta2_tilde_integer);
    put(e, "Delta2_simulated", r.Delta2_bar);
    put(e, "ratio", r.ratio);
    put(e, "ratio_integer_mode", r.ratio_integer);
    j["rows"].push_back(e);
  }
  return j;
}

std::string trace_csv(const DiagramSpec& plane, const TraceResult& t) {
  std::ostringstream csv;
  csv << "curve,l," << to_string(plane.x.axis) << ',' << to_string(plane.y.axis) << ",sigma_R,sigma_c,mu\n";
  for (std::size_t c = 0; c < t.curves.size(); ++c)
    for (const TracePoint& p : t.curves[c].points)
      csv << c << ',' << t.curves[c].l << ',' << csv_number(p.x) << ',' << csv_number(p.y) << ','
          << csv_number(p.sigma_R) << ',' << csv_number(p.sigma_c) << ',' << csv_number(p.mu) << '\n';
  return csv.str();
}

nlohmann::json trace_json(const SceneFile& file, const DiagramSpec& plane, const TraceOptions& to,
                          const TraceResult& t) {
  nlohmann::json curves = nlohmann::json::array();
  for (std::size_t c = 0; c < t.curves.size(); ++c) {
    const TraceCurve& tc = t.curves[c];
    nlohmann::json xs = nlohmann::json::array(), ys = nlohmann::json::array(), mus = nlohmann::json::array();
    for (const TracePoint& p : tc.points) {
      xs.push_back(p.x);
      ys.push_back(p.y);
      mus.push_back(p.mu);
    }
    curves.push_back({{"curve", c},
                      {"chain", tc.chain},
                      {"l", tc.l},
                      {"criterion", tc.criterion},
                      {"x", xs},
                      {"y", ys},
                      {"mu", mus}});
  }
  nlohmann::json corners = nlohmann::json::array();
  for (const auto& k : t.corners) corners.push_back({{"x", k.x}, {"y", k.y}, {"l_from", k.l_from}, {"l_to", k.l_to}});
  nlohmann::json overlays = nlohmann::json::array();
  for (const Overlay& ov : analytic_overlays(file.scene, plane, 200)) {
    nlohmann::json line{{"name", ov.name}, {"x", ov.x}, {"y", ov.y}};
    explain_nulls(line, "undefined there: the line's formula is outside its domain");
    overlays.push_back(line);
  }
  nlohmann::json doc{{"format", "rbcstab-trace"},
                     {"version", 1},
                     {"scene", to_json(file.scene)},
                     {"plane",
                      {{"x", to_string(plane.x.axis)},
                       {"x_range", {plane.x.min, plane.x.max}},
                       {"y", to_string(plane.y.axis)},
                       {"y_range", {plane.y.min, plane.y.max}},
                       {"alpha", plane.alpha}}},
                     {"criterion", to_string(to.criterion)},
                     {"options",
                      {{"criterion", to_string(to.criterion)},
                       {"T", to.T > 0 ? to.T : file.scene.T},
                       {"lines", to.lines},
                       {"samples", to.samples},
                       {"bisections", to.bisections},
                       {"max_step", to.max_step},
                       {"method", to_string(to.method)}}},
                     {"method", t.method},
                     {"curves", curves},
                     {"corners", corners},
                     {"analytic_lines", overlays},
                     {"evaluations", t.evaluations},
                     {"chains", t.chains},
                     {"starts", t.starts},
                     {"turning_points", t.turning_points},
                     {"continuation",
                      {{"steps", t.counters.steps},
                       {"rejected_steps", t.counters.rejected_steps},
                       {"newton_iterations", t.counters.newton_iterations},
                       {"location_iterations", t.counters.location_iterations}}},
                     {"notes", t.notes},
                     {"seconds", t.seconds}};
  put_truncation(doc, file);
  explain_nulls(doc, nonfinite_reason(file.scene.parameters));
  return doc;
}

nlohmann::json trace_agreement_json(const nlohmann::json& dj, const std::string& source, const DiagramSpec& plane,
                                    const TraceOptions& options, int threads) {
  auto not_a_diagram = [&](const nlohmann::json::exception& e) {
    return InvalidArgument("diagram", "'" + source + "' is not a diagram document: " + e.what());
  };
  DiagramSpec ds;
  try {
    ds = spec_from_json(dj);
  } catch (const nlohmann::json::exception& e) {
    throw not_a_diagram(e);
  }
  if (ds.x.axis != plane.x.axis || ds.y.axis != plane.y.axis || ds.alpha != plane.alpha)
    throw InvalidArgument("diagram", "the diagram's plane differs from the traced plane");
  SceneFile dsf;
  std::vector<PointResult> points;
  try {
    dsf = parse_scene(dj.at("scene_toml").get<std::string>(), source);
    points = points_from_json(dj, ds);
  } catch (const nlohmann::json::exception& e) {
    throw not_a_diagram(e);
  }
  AgreementOptions ao;
  ao.threads = threads;
  ao.trace_options = options;
  ao.trace_options.on_progress = nullptr;  // the agreement traces run on worker threads
  ao.trace_finite_horizon = true;
  ao.trace_in_plane = true;
  return agreement_json(dsf.scene, ds, points, ao);
}

nlohmann::json trace_brief_json(const nlohmann::json& doc, const std::string& prefix) {
  nlohmann::json j{{"csv", prefix + ".csv"},
                   {"json", prefix + ".json"},
                   {"pieces", doc.at("curves").size()},
                   {"corners", doc.at("corners")},
                   {"evaluations", doc.at("evaluations")},
                   {"method", doc.at("method")},
                   {"seconds", doc.at("seconds")},
                   {"analytic_lines", doc.at("analytic_lines").size()},
                   {"L", doc.at("L")},
                   {"L_reason", doc.at("L_reason")}};
  if (doc.contains("agreement")) j["agreement"] = doc["agreement"];
  return j;
}

VerdictCounts count_verdicts(const std::vector<PointResult>& points) {
  VerdictCounts c;
  for (const PointResult& p : points) {
    c.failed += p.verdict == Verdict::failed;
    c.unstable += p.verdict == Verdict::unstable;
    c.stable += p.verdict == Verdict::stable;
  }
  return c;
}

nlohmann::json diagram_document(const SceneFile& file, const DiagramSpec& spec, const std::vector<PointResult>& points,
                                const Shard& shard, const DiagramOutputOptions& output,
                                const std::optional<AgreementOptions>& agreement) {
  nlohmann::json header = diagram_header(file.scene, file.options, spec);
  put_truncation(header, file);
  nlohmann::json doc = diagram_json(header, spec, points, shard, output);
  if (shard.n == 1)
    doc["agreement"] = agreement ? agreement_json(file.scene, spec, points, *agreement) : nlohmann::json(nullptr);
  return doc;
}

nlohmann::json diagram_brief_json(const SceneFile& file, const DiagramRun& r, const std::string& prefix) {
  const VerdictCounts c = count_verdicts(r.points);
  nlohmann::json j{{"csv", prefix + ".csv"},       {"json", prefix + ".json"}, {"points", r.points.size()},
                   {"computed", r.computed},       {"resumed", r.resumed},     {"stable", c.stable},
                   {"unstable", c.unstable},       {"failed", c.failed},       {"complete", r.complete},
                   {"config_hash", r.config_hash}, {"seconds", r.seconds}};
  put_truncation(j, file);
  return j;
}

nlohmann::json merge_brief_json(const MergeResult& m, std::size_t inputs, const std::string& prefix) {
  return {{"csv", prefix + ".csv"},    {"json", prefix + ".json"},    {"inputs", inputs},
          {"points", m.points.size()}, {"missing", m.missing.size()}, {"complete", m.missing.empty()}};
}

std::string threshold_precision_csv(const ThresholdPrecision& t) {
  std::ostringstream csv;
  csv << std::setprecision(12)
      << "predictor,method,rtol,budget,ln_C,error,evaluations,rhs_evaluations,seconds,status\n";
  for (const auto& r : t.rows)
    csv << r.predictor << ',' << r.method << ',' << csv_number(r.rtol) << ',' << r.budget << ',' << csv_number(r.ln_C)
        << ',' << csv_number(r.error) << ',' << r.evaluations << ',' << r.rhs_evaluations << ','
        << csv_number(r.seconds) << ",\"" << r.status << "\"\n";
  return csv.str();
}

nlohmann::json threshold_precision_json(const SceneFile& file, const ThresholdPrecisionOptions& options,
                                        const ThresholdPrecision& t) {
  nlohmann::json rows = nlohmann::json::array(), refs = nlohmann::json::array();
  // A number is missing only with a status other than "ok", which says why.
  auto why = [&](const std::string& status) {
    return status == "ok" ? nonfinite_reason(file.scene.parameters) : status;
  };
  for (const auto& r : t.rows) {
    nlohmann::json row{{"predictor", r.predictor},
                       {"method", r.method},
                       {"rtol", r.rtol},
                       {"budget", r.budget},
                       {"evaluations", r.evaluations},
                       {"rhs_evaluations", r.rhs_evaluations},
                       {"seconds", r.seconds},
                       {"status", r.status}};
    put_number(row, "ln_C", r.ln_C, why(r.status));
    std::string error_why = why(r.status);
    for (const auto& ref : t.references)
      if (ref.predictor == r.predictor && ref.status != "ok") error_why = "no reference: " + ref.status;
    put_number(row, "error", r.error, error_why);
    rows.push_back(row);
  }
  for (const auto& r : t.references) {
    nlohmann::json ref{{"predictor", r.predictor},
                       {"status", r.status},
                       {"rtol", r.predictor == "asymptotic" ? 0.0 : options.reference_rtol}};
    put_number(ref, "ln_C", r.ln_C, why(r.status));
    put_number(ref, "bracket", r.bracket, why(r.status));
    refs.push_back(ref);
  }
  nlohmann::json j{{"scene", to_json(file.scene)},
                   {"B", t.B},
                   {"ln_C_range", std::vector<double>{options.ln_C_lo, options.ln_C_hi}},
                   {"references", refs},
                   {"rows", rows}};
  put_truncation(j, file);
  return j;
}

std::string threshold_precision_text(const SceneFile& file, const ThresholdPrecision& t) {
  TextStream s;
  s << std::setprecision(12) << "critical ln C at B = " << t.B << " (scene " << file.scene.name << ")\n";
  for (const auto& r : t.references)
    s << "  reference " << std::setw(15) << r.predictor << ": ln C = " << r.ln_C << " (bracket " << r.bracket << ")"
      << (r.status == "ok" ? "" : "  " + r.status) << "\n";
  s << std::setprecision(4) << std::setw(15) << "predictor" << std::setw(12) << "method" << std::setw(8) << "rtol"
    << std::setw(8) << "budget" << std::setw(12) << "error" << std::setw(8) << "evals" << std::setw(12) << "RHS"
    << std::setw(11) << "seconds\n";
  for (const auto& r : t.rows)
    s << std::setw(15) << r.predictor << std::setw(12) << r.method << std::setw(8) << r.rtol << std::setw(8) << r.budget
      << std::setw(12) << r.error << std::setw(8) << r.evaluations << std::setw(12) << r.rhs_evaluations
      << std::setw(11) << r.seconds << (r.status == "ok" ? "" : "  " + r.status) << "\n";
  return s.str();
}

std::string progress_text(const Progress& p, bool detail) {
  TextStream s;
  s << "diagram " << p.done << "/" << p.total;
  if (detail && p.resumed) s << " (" << p.resumed << " resumed)";
  s << ", " << std::fixed << std::setprecision(1) << p.rate << " points/s";
  if (detail) s << ", elapsed " << duration_text(p.elapsed);
  s << ", ETA " << (p.rate > 0 ? duration_text(p.eta) : std::string("?"));
  return s.str();
}

std::vector<std::string> trace_summary_lines(const TraceResult& t, const nlohmann::json& doc,
                                             const std::string& prefix) {
  TextStream s;
  s << "traced " << t.curves.size() << " curve pieces, " << t.corners.size() << " corners, " << t.evaluations
    << " criterion evaluations in " << t.seconds << " s; wrote " << prefix << ".csv and " << prefix << ".json";
  std::vector<std::string> lines{s.str()};
  for (const std::string& n : t.notes) lines.push_back("note: " + n);
  if (doc.contains("agreement") && doc["agreement"].contains("predictors"))
    for (const auto& a : doc["agreement"]["predictors"]) {
      TextStream l;
      l << "agreement of " << a["predictor"].get<std::string>() << ": verdict " << a["verdict_fraction"] << ", mode "
        << a["mode_fraction"] << " over " << a["points"] << " points, disagreements beyond one grid step "
        << a["beyond_one_grid_step"];
      lines.push_back(l.str());
    }
  return lines;
}

std::string diagram_run_text(const DiagramRun& r, const std::string& prefix) {
  TextStream s;
  if (!r.complete) {
    s << "interrupted after " << r.points.size() << " points (" << r.computed
      << " computed in this run); finished points are in the journal: rerun the same command to resume";
    return s.str();
  }
  const VerdictCounts counts = count_verdicts(r.points);
  s << "diagram done: " << r.points.size() << " points (" << r.computed << " computed, " << r.resumed << " resumed) in "
    << duration_text(r.seconds) << "; " << counts.unstable << " unstable, " << counts.failed << " failed; wrote "
    << prefix << ".csv and " << prefix << ".json";
  return s.str();
}

}  // namespace rbcstab
