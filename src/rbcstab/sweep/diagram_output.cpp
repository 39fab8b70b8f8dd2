#include "rbcstab/sweep/diagram_output.hpp"

#include <cmath>
#include <map>
#include <sstream>

#include "rbcstab/core/error.hpp"
#include "rbcstab/io/json.hpp"
#include "rbcstab/io/scene_file.hpp"
#include "rbcstab/sweep/point_io.hpp"
#include "rbcstab/sweep/agreement.hpp"

namespace rbcstab {

namespace {
nlohmann::json axis_json(const AxisRange& a) {
  return {{"axis", to_string(a.axis)}, {"min", a.min}, {"max", a.max}, {"count", a.count}};
}
AxisRange axis_from_json(const nlohmann::json& j) {
  AxisRange a;
  a.axis = axis_from_string(j.at("axis").get<std::string>());
  a.min = j.at("min").get<double>();
  a.max = j.at("max").get<double>();
  a.count = j.at("count").get<int>();
  return a;
}
double number(const nlohmann::json& j) { return j.is_null() ? std::nan("") : j.get<double>(); }
// A failed point's non-finite value is an empty field (its status column says why), never "nan".
std::string csv_number(double v) { return std::isfinite(v) ? exact(v) : ""; }
}  // namespace

nlohmann::json diagram_header(const Scene& base, const SimulationOptions& options, const DiagramSpec& spec) {
  nlohmann::json h;
  h["format"] = "rbcstab-diagram";
  h["version"] = 1;
  h["config_hash"] = config_hash(base, options, spec);
  h["scene"] = to_json(base);
  h["scene_toml"] = to_toml(SceneFile{base, options});
  h["integrator"] = {{"stepper", to_string(options.integrator.stepper)},
                     {"rtol", options.integrator.rtol},
                     {"atol", options.integrator.atol},
                     {"tail_window", options.tail_window}};
  h["diagram"] = {{"x", axis_json(spec.x)}, {"y", axis_json(spec.y)}, {"classifier", to_string(spec.classifier)},
                  {"alpha", spec.alpha}, {"points", spec.size()}};
  return h;
}

std::string diagram_csv(const DiagramSpec& spec, const std::vector<PointResult>& points, const DiagramOutputOptions& o) {
  std::ostringstream ss;
  ss << "index,i,j," << to_string(spec.x.axis) << ',' << to_string(spec.y.axis)
     << ",verdict,l_Delta,growth,oscillating,sigma_final,status,t_reached,steps,failed_steps,rhs_evaluations";
  if (o.include_seconds) ss << ",seconds";
  ss << '\n';
  for (const PointResult& p : points) {
    ss << p.index << ',' << p.i << ',' << p.j << ',' << exact(p.x) << ',' << exact(p.y) << ',' << to_string(p.verdict)
       << ',' << p.l_Delta << ',' << csv_number(p.growth) << ',' << int(p.oscillating) << ','
       << csv_number(p.sigma_final) << ',' << to_string(p.status) << ',' << csv_number(p.t_reached) << ',' << p.steps << ',' << p.failed_steps << ','
       << p.rhs_evaluations;
    if (o.include_seconds) ss << ',' << csv_number(p.seconds);
    ss << '\n';
  }
  return ss.str();
}

nlohmann::json diagram_json(const nlohmann::json& header, const DiagramSpec& spec, const std::vector<PointResult>& points,
                            const Shard& shard, const DiagramOutputOptions& o) {
  nlohmann::json doc = header;
  if (shard.n > 1) doc["shard"] = {{"k", shard.k}, {"n", shard.n}};
  std::size_t expected = 0;
  for (std::size_t idx = 0; idx < spec.size(); ++idx) expected += shard.contains(idx) ? 1 : 0;
  doc["complete"] = points.size() == expected;
  doc["seconds_included"] = o.include_seconds;
  nlohmann::json arr = nlohmann::json::array();
  std::map<std::string, std::size_t> verdicts, modes;
  std::size_t rhs = 0, steps = 0;
  double seconds = 0;
  nlohmann::json failed = nlohmann::json::array();
  for (const PointResult& p : points) {
    nlohmann::json r{{"index", p.index},
                     {"i", p.i},
                     {"j", p.j},
                     {"x", p.x},
                     {"y", p.y},
                     {"verdict", to_string(p.verdict)},
                     {"l_Delta", p.l_Delta},
                     {"growth", number_or_null(p.growth)},
                     {"oscillating", p.oscillating},
                     {"sigma_final", number_or_null(p.sigma_final)},
                     {"status", to_string(p.status)},
                     {"reason", p.reason},
                     {"t_reached", number_or_null(p.t_reached)},
                     {"steps", p.steps},
                     {"failed_steps", p.failed_steps},
                     {"rhs_evaluations", p.rhs_evaluations}};
    if (o.include_seconds) r["seconds"] = p.seconds;
    arr.push_back(std::move(r));
    ++verdicts[to_string(p.verdict)];
    if (p.verdict != Verdict::failed) ++modes[std::to_string(p.l_Delta)];
    if (p.verdict == Verdict::failed) failed.push_back(p.index);
    rhs += p.rhs_evaluations;
    steps += p.steps;
    seconds += p.seconds;
  }
  nlohmann::json summary{{"points", points.size()}, {"verdicts", verdicts}, {"l_Delta", modes},
                         {"failed_indices", failed}, {"rhs_evaluations", rhs}, {"steps", steps}};
  if (o.include_seconds) summary["seconds"] = seconds;
  doc["summary"] = summary;
  doc["points"] = std::move(arr);
  return doc;
}

namespace {
nlohmann::json agreement_entry(const Agreement& a) {
  nlohmann::json d = nlohmann::json::array();
  for (const auto& x : a.verdict_disagreements)
    d.push_back({{"index", x.index}, {"simulated", to_string(x.simulated)}, {"l_simulated", x.l_simulated},
                 {"predicted", x.predicted_unstable ? "unstable" : "stable"}, {"l_predicted", x.l_predicted},
                 {"distance_grid_steps", number_or_null(x.distance_steps)}, {"S", number_or_null(x.S)},
                 {"alpha_over_alpha_init", x.alpha_over_alpha_init}});
  const double n = a.points ? double(a.points) : 1.0;
  nlohmann::json j{{"predictor", a.predictor},
                   {"description", a.description},
                   {"boundary", a.boundary},
                   {"points", a.points},
                   {"not_classified", a.not_classified},
                   {"verdict_fraction", a.points ? nlohmann::json(double(a.verdict_matches) / n) : nlohmann::json()},
                   {"mode_fraction", a.points ? nlohmann::json(double(a.mode_matches) / n) : nlohmann::json()},
                   {"verdict_disagreements", a.verdict_disagreements.size()},
                   {"within_one_grid_step", a.verdict_disagreements.size() - a.beyond_one_step},
                   {"beyond_one_grid_step", a.beyond_one_step},
                   {"small_S", a.small_S},
                   {"near_alpha_init", a.near_alpha_init},
                   {"boundary_pieces", a.boundary_pieces},
                   {"boundary_corners", a.boundary_corners},
                   {"disagreements", d}};
  if (!a.note.empty()) j["note"] = a.note;
  return j;
}
}  // namespace

nlohmann::json agreement_json(const Scene& base, const DiagramSpec& spec, const std::vector<PointResult>& points,
                              const AgreementOptions& options) {
  std::vector<Agreement> all;
  try {
    all = predictor_agreements(base, spec, points, options);
  } catch (const InvalidArgument& e) {
    return {{"predictor", "asymptotic"}, {"error", e.what()}};
  }
  // The asymptotic entry's fields at the top level (the block's original shape), every predictor in "predictors".
  nlohmann::json doc = agreement_entry(all.front());
  nlohmann::json list = nlohmann::json::array();
  for (const Agreement& a : all) list.push_back(agreement_entry(a));
  doc["predictors"] = list;
  return doc;
}

DiagramSpec spec_from_json(const nlohmann::json& doc) {
  try {
    if (doc.at("format").get<std::string>() != "rbcstab-diagram")
      throw InvalidArgument("merge", "not an rbcstab diagram JSON (format is not 'rbcstab-diagram')");
    DiagramSpec s;
    const auto& d = doc.at("diagram");
    s.x = axis_from_json(d.at("x"));
    s.y = axis_from_json(d.at("y"));
    s.classifier = classifier_from_string(d.at("classifier").get<std::string>());
    s.alpha = d.value("alpha", 0.0);
    s.validate();
    return s;
  } catch (const nlohmann::json::exception& e) {
    throw InvalidArgument("merge", std::string("not an rbcstab diagram JSON: ") + e.what());
  }
}

std::vector<PointResult> points_from_json(const nlohmann::json& doc, const DiagramSpec& spec) {
  std::vector<PointResult> out;
  try {
    for (const auto& r : doc.at("points")) {
      PointResult p;
      p.index = r.at("index").get<std::size_t>();
      if (p.index >= spec.size()) throw InvalidArgument("merge", "point index " + std::to_string(p.index) + " is outside the grid");
      p.i = int(p.index % std::size_t(spec.x.count));
      p.j = int(p.index / std::size_t(spec.x.count));
      p.x = spec.x.value(p.i);
      p.y = spec.y.value(p.j);
      p.verdict = try_from_string<Verdict>(r.at("verdict").get<std::string>()).value_or(Verdict::failed);
      p.l_Delta = r.at("l_Delta").get<int>();
      p.growth = number(r.at("growth"));
      p.oscillating = r.at("oscillating").get<bool>();
      p.sigma_final = number(r.at("sigma_final"));
      if (const auto st = try_from_string<IntegrationStatus>(r.at("status").get<std::string>())) p.status = *st;
      p.reason = r.at("reason").get<std::string>();
      p.t_reached = number(r.at("t_reached"));
      p.steps = r.at("steps").get<std::size_t>();
      p.failed_steps = r.at("failed_steps").get<std::size_t>();
      p.rhs_evaluations = r.at("rhs_evaluations").get<std::size_t>();
      p.seconds = r.contains("seconds") ? r.at("seconds").get<double>() : 0.0;
      out.push_back(std::move(p));
    }
  } catch (const nlohmann::json::exception& e) {
    throw InvalidArgument("merge", std::string("malformed diagram points: ") + e.what());
  }
  return out;
}

MergeResult merge_diagrams(const std::vector<nlohmann::json>& docs) {
  if (docs.empty()) throw InvalidArgument("merge", "nothing to merge: give at least one diagram JSON");
  MergeResult m;
  m.spec = spec_from_json(docs.front());
  m.header = docs.front();
  for (const char* k : {"shard", "complete", "seconds_included", "summary", "points", "agreement"}) m.header.erase(k);
  const std::string hash = docs.front().value("config_hash", "");
  std::map<std::size_t, PointResult> all;
  for (std::size_t d = 0; d < docs.size(); ++d) {
    if (docs[d].value("config_hash", "") != hash)
      throw InvalidArgument("merge", "input " + std::to_string(d + 1) + " has config_hash '" +
                                         docs[d].value("config_hash", "") + "', input 1 has '" + hash +
                                         "': they are not shards of one diagram");
    m.seconds_present = m.seconds_present && docs[d].value("seconds_included", false);
    for (PointResult& p : points_from_json(docs[d], m.spec)) {
      auto [it, inserted] = all.emplace(p.index, p);
      if (!inserted && (it->second.l_Delta != p.l_Delta || it->second.verdict != p.verdict ||
                        it->second.rhs_evaluations != p.rhs_evaluations))
        throw InvalidArgument("merge", "point " + std::to_string(p.index) + " appears twice with different results");
    }
  }
  for (std::size_t idx = 0; idx < m.spec.size(); ++idx)
    if (!all.count(idx)) m.missing.push_back(idx);
  for (auto& [idx, p] : all) m.points.push_back(std::move(p));
  return m;
}

}  // namespace rbcstab
