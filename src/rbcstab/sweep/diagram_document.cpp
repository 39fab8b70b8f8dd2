#include "rbcstab/sweep/diagram_document.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <iterator>
#include <limits>
#include <map>
#include <sstream>

#include "rbcstab/core/error.hpp"
#include "rbcstab/io/json.hpp"
#include "rbcstab/io/scene_file.hpp"
#include "rbcstab/sweep/agreement.hpp"
#include "rbcstab/sweep/point_record.hpp"

namespace rbcstab {

namespace {
nlohmann::json axis_json(const AxisRange& a) {
  return {{"axis", to_string(a.axis)}, {"min", a.min}, {"max", a.max}, {"count", a.count}};
}
// An integer of type Int as the JSON gives it: a fraction or a wider integer is refused, never truncated.
template <class Int>
Int integer_of(const nlohmann::json& v) {
  using Limits = std::numeric_limits<Int>;
  bool fits = false;
  if (v.is_number_unsigned()) {
    fits = v.get<std::uint64_t>() <= std::uint64_t(Limits::max());
  } else if (v.is_number_integer()) {
    const std::int64_t x = v.get<std::int64_t>();
    fits = Limits::is_signed ? x >= std::int64_t(Limits::min()) && x <= std::int64_t(Limits::max()) : x >= 0;
  }
  if (!fits)
    throw InvalidArgument("merge", v.dump() + " is not an integer in [" + std::to_string(Limits::min()) + ", " +
                                       std::to_string(Limits::max()) + "]");
  return v.get<Int>();
}

AxisRange axis_from_json(const nlohmann::json& j) {
  AxisRange a;
  a.axis = axis_from_string(j.at("axis").get<std::string>());
  a.min = j.at("min").get<double>();
  a.max = j.at("max").get<double>();
  a.count = integer_of<int>(j.at("count"));
  return a;
}
double number(const nlohmann::json& j) { return j.is_null() ? std::nan("") : j.get<double>(); }
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
  h["diagram"] = {{"x", axis_json(spec.x)},
                  {"y", axis_json(spec.y)},
                  {"classifier", to_string(spec.classifier)},
                  {"alpha", spec.alpha},
                  {"points", spec.size()}};
  return h;
}

std::string diagram_csv(const DiagramSpec& spec, const std::vector<PointResult>& points,
                        const DiagramOutputOptions& o) {
  std::ostringstream ss;
  ss << "index,i,j," << to_string(spec.x.axis) << ',' << to_string(spec.y.axis)
     << ",verdict,l_Delta,growth,oscillating,sigma_final,status,t_reached,steps,failed_steps,rhs_evaluations"
     << ",terminated_at,margin";
  if (o.include_seconds) ss << ",seconds";
  ss << '\n';
  for (const PointResult& p : points) {
    ss << p.index << ',' << p.i << ',' << p.j << ',' << exact(p.x) << ',' << exact(p.y) << ',' << to_string(p.verdict)
       << ',' << p.l_Delta << ',' << csv_number(p.growth) << ',' << int(p.oscillating) << ','
       << csv_number(p.sigma_final) << ',' << to_string(p.status) << ',' << csv_number(p.t_reached) << ',' << p.steps
       << ',' << p.failed_steps << ',' << p.rhs_evaluations << ',' << csv_number(p.terminated_at) << ','
       << csv_number(p.margin);
    if (o.include_seconds) ss << ',' << csv_number(p.seconds);
    ss << '\n';
  }
  return ss.str();
}

nlohmann::json diagram_json(const nlohmann::json& header, const DiagramSpec& spec,
                            const std::vector<PointResult>& points, const Shard& shard, const DiagramOutputOptions& o) {
  nlohmann::json doc = header;
  if (shard.n > 1) doc["shard"] = {{"k", shard.k}, {"n", shard.n}};
  std::size_t expected = 0;
  for (std::size_t idx = 0; idx < spec.size(); ++idx) expected += shard.contains(idx) ? 1 : 0;
  doc["complete"] = points.size() == expected;
  doc["seconds_included"] = o.include_seconds;
  nlohmann::json arr = nlohmann::json::array();
  std::map<std::string, std::size_t> verdicts, modes;
  std::size_t rhs = 0, steps = 0, terminated = 0;
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
                     {"rhs_evaluations", p.rhs_evaluations},
                     {"terminated_at", number_or_null(p.terminated_at)},
                     {"margin", number_or_null(p.margin)}};
    if (o.include_seconds) r["seconds"] = p.seconds;
    explain_nulls(r, p.status == IntegrationStatus::success ? "not finite at this point's parameters"
                                                            : "the run ended with " + to_string(p.status) + " at t = " +
                                                                  format_value(p.t_reached) + ": " + p.reason);
    arr.push_back(std::move(r));
    ++verdicts[to_string(p.verdict)];
    if (p.verdict != Verdict::failed) ++modes[std::to_string(p.l_Delta)];
    if (p.verdict == Verdict::failed) failed.push_back(p.index);
    rhs += p.rhs_evaluations;
    steps += p.steps;
    seconds += p.seconds;
    terminated += std::isfinite(p.terminated_at) ? 1 : 0;
  }
  nlohmann::json summary{{"points", points.size()},       {"verdicts", verdicts},   {"l_Delta", modes},
                         {"failed_indices", failed},      {"rhs_evaluations", rhs}, {"steps", steps},
                         {"terminated_early", terminated}};
  if (o.include_seconds) summary["seconds"] = seconds;
  doc["summary"] = summary;
  doc["points"] = std::move(arr);
  return doc;
}

namespace {
nlohmann::json agreement_entry(const Agreement& a) {
  nlohmann::json d = nlohmann::json::array();
  for (const auto& x : a.verdict_disagreements)
    d.push_back({{"index", x.index},
                 {"simulated", to_string(x.simulated)},
                 {"l_simulated", x.l_simulated},
                 {"predicted", x.predicted_unstable ? "unstable" : "stable"},
                 {"l_predicted", x.l_predicted},
                 {"distance_grid_steps", number_or_null(x.distance_steps)},
                 {"S", number_or_null(x.S)},
                 {"alpha_over_alpha_init", x.alpha_over_alpha_init}});
  const double n = a.points ? double(a.points) : 1.0;
  nlohmann::json j{{"predictor", a.predictor},
                   {"description", a.description},
                   {"boundary", a.boundary},
                   {"points", a.points},
                   {"not_classified", a.not_classified},
                   {"verdict_fraction", a.points ? nlohmann::json(double(a.verdict_matches) / n) : nlohmann::json()},
                   {"mode_fraction", a.points ? nlohmann::json(double(a.mode_matches) / n) : nlohmann::json()},
                   {"unstable_points", a.unstable_matches},
                   {"unstable_mode_fraction",
                    a.unstable_matches ? nlohmann::json(double(a.unstable_mode_matches) / double(a.unstable_matches))
                                       : nlohmann::json()},
                   {"verdict_disagreements", a.verdict_disagreements.size()},
                   {"within_one_grid_step", a.verdict_disagreements.size() - a.beyond_one_step},
                   {"beyond_one_grid_step", a.beyond_one_step},
                   {"small_S", a.small_S},
                   {"near_alpha_init", a.near_alpha_init},
                   {"boundary_pieces", a.boundary_pieces},
                   {"boundary_corners", a.boundary_corners},
                   {"disagreements", d}};
  if (!a.note.empty()) j["note"] = a.note;
  if (a.points && !a.unstable_matches)
    j["unstable_mode_fraction_reason"] = "no point that the simulation and the predictor both call unstable";
  explain_nulls(j, "no point to compare: every point failed or was not classified");
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

namespace {
// Where a point's field sits, for error messages: (point position k in "points", field name).
using Where = std::function<std::string(std::size_t k, const std::string& field)>;

// The document's scene and options: every diagram JSON carries them (diagram_header).
SceneFile scene_of(const nlohmann::json& doc) {
  if (!doc.contains("scene_toml")) throw InvalidArgument("merge", "the diagram JSON has no scene_toml");
  try {
    return parse_scene(doc.at("scene_toml").get<std::string>());
  } catch (const std::exception& e) {
    throw InvalidArgument("merge", std::string("the scene_toml of the diagram JSON is invalid: ") + e.what());
  }
}

// Every value is checked (names in the enum tables, point_value_error), never defaulted: a merge must
// not turn an unreadable value into a plausible one.
std::vector<PointResult> read_points(const nlohmann::json& doc, const DiagramSpec& spec, const Where& where) {
  const int L = scene_of(doc).scene.L;
  std::vector<PointResult> out;
  if (!doc.contains("points") || !doc.at("points").is_array())
    throw InvalidArgument("merge", "malformed diagram JSON: no \"points\" array");
  std::size_t k = 0;
  for (const auto& r : doc.at("points")) {
    auto field = [&](const std::string& key, auto&& read) {
      try {
        read(r.at(key));
      } catch (const nlohmann::json::exception& e) {
        const std::string value = r.is_object() && r.contains(key) ? r.at(key).dump() : "missing";
        throw InvalidArgument("merge", where(k, key) + ": " + key + " = " + value + " is not valid (" + e.what() + ")");
      } catch (const InvalidArgument& e) {
        throw InvalidArgument("merge", where(k, key) + ": " + e.what());
      }
    };
    PointResult p;
    field("index", [&](const nlohmann::json& v) { p.index = integer_of<std::size_t>(v); });
    field("verdict",
          [&](const nlohmann::json& v) { p.verdict = from_string<Verdict>(v.get<std::string>(), "verdict"); });
    field("status",
          [&](const nlohmann::json& v) { p.status = from_string<IntegrationStatus>(v.get<std::string>(), "status"); });
    field("l_Delta", [&](const nlohmann::json& v) { p.l_Delta = integer_of<int>(v); });
    field("growth", [&](const nlohmann::json& v) { p.growth = number(v); });
    field("oscillating", [&](const nlohmann::json& v) { p.oscillating = v.get<bool>(); });
    field("sigma_final", [&](const nlohmann::json& v) { p.sigma_final = number(v); });
    field("reason", [&](const nlohmann::json& v) { p.reason = v.get<std::string>(); });
    field("t_reached", [&](const nlohmann::json& v) { p.t_reached = number(v); });
    field("steps", [&](const nlohmann::json& v) { p.steps = integer_of<std::size_t>(v); });
    field("failed_steps", [&](const nlohmann::json& v) { p.failed_steps = integer_of<std::size_t>(v); });
    field("rhs_evaluations", [&](const nlohmann::json& v) { p.rhs_evaluations = integer_of<std::size_t>(v); });
    field("terminated_at", [&](const nlohmann::json& v) { p.terminated_at = number(v); });
    field("margin", [&](const nlohmann::json& v) { p.margin = number(v); });
    if (r.contains("seconds")) field("seconds", [&](const nlohmann::json& v) { p.seconds = v.get<double>(); });
    if (const FieldError e = point_value_error(p, spec, L); !e.empty())
      throw InvalidArgument("merge", where(k, e.field) + ": " + e.why);
    p.i = int(p.index % std::size_t(spec.x.count));
    p.j = int(p.index / std::size_t(spec.x.count));
    p.x = spec.x.value(p.i);
    p.y = spec.y.value(p.j);
    out.push_back(std::move(p));
    ++k;
  }
  return out;
}

// The line of field `key` of element k of the top-level "points" array in text (the line of the
// element when the key is missing; 0 when not found). nlohmann::json keeps no positions, so the
// text is parsed again with a SAX handler over an iterator that counts the characters read.
class PointLineFinder : public nlohmann::json_sax<nlohmann::json> {
 public:
  PointLineFinder(const std::string& text, const std::size_t& consumed, std::size_t k, std::string key)
      : text_(text), consumed_(consumed), k_(k), key_(std::move(key)) {}
  std::size_t line() const { return line_; }

  bool null() override { return value(); }
  bool boolean(bool) override { return value(); }
  bool number_integer(number_integer_t) override { return value(); }
  bool number_unsigned(number_unsigned_t) override { return value(); }
  bool number_float(number_float_t, const string_t&) override { return value(); }
  bool string(string_t&) override { return value(); }
  bool binary(binary_t&) override { return value(); }
  bool start_object(std::size_t) override {
    ++depth_;
    if (depth_ == 3 && in_points_ && element_++ == k_) line_ = here();
    return true;
  }
  bool key(string_t& name) override {
    if (depth_ == 1) in_points_ = name == "points";
    if (depth_ == 3) key_here_ = name;
    return true;
  }
  bool end_object() override {
    if (depth_ == 1) in_points_ = false;
    --depth_;
    return true;
  }
  bool start_array(std::size_t) override { return ++depth_, true; }
  bool end_array() override {
    if (depth_ == 2) in_points_ = false;
    return --depth_, true;
  }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override { return false; }

 private:
  const std::string& text_;
  const std::size_t& consumed_;
  std::size_t k_;
  std::string key_, key_here_;
  int depth_ = 0;
  bool in_points_ = false;
  std::size_t element_ = 0, line_ = 0;
  // The lexer reads one character past a number before it reports it: count lines before that one.
  std::size_t here() const {
    const std::size_t end = std::min(text_.size(), consumed_ > 0 ? consumed_ - 1 : 0);
    return 1 + std::size_t(std::count(text_.begin(), text_.begin() + std::ptrdiff_t(end), '\n'));
  }
  bool value() {
    if (depth_ == 3 && in_points_ && element_ == k_ + 1 && key_here_ == key_) line_ = here();
    return true;
  }
};

struct CountingIterator {
  using iterator_category = std::input_iterator_tag;
  using value_type = char;
  using difference_type = std::ptrdiff_t;
  using pointer = const char*;
  using reference = const char&;
  const char* p;
  std::size_t* consumed;
  reference operator*() const { return *p; }
  CountingIterator& operator++() {
    ++p;
    ++*consumed;
    return *this;
  }
  CountingIterator operator++(int) {
    CountingIterator old = *this;
    ++*this;
    return old;
  }
  bool operator==(const CountingIterator& o) const { return p == o.p; }
};

std::size_t point_line(const std::string& text, std::size_t k, const std::string& key) {
  std::size_t consumed = 0;
  PointLineFinder finder(text, consumed, k, key);
  nlohmann::json::sax_parse(CountingIterator{text.data(), &consumed},
                            CountingIterator{text.data() + text.size(), &consumed}, &finder);
  return finder.line();
}

// Input d's config_hash (a string) and seconds_included (a boolean; absent: false), refused when of another type.
std::string hash_of(const nlohmann::json& doc, std::size_t d) {
  const auto it = doc.find("config_hash");
  if (it == doc.end() || !it->is_string())
    throw InvalidArgument("merge", "input " + std::to_string(d + 1) + " has no config_hash string (" +
                                       (it == doc.end() ? std::string("missing") : it->dump()) + ")");
  return it->get<std::string>();
}
bool seconds_included(const nlohmann::json& doc, std::size_t d) {
  const auto it = doc.find("seconds_included");
  if (it == doc.end()) return false;
  if (!it->is_boolean())
    throw InvalidArgument("merge", "input " + std::to_string(d + 1) + " has seconds_included = " + it->dump() +
                                       ": must be true or false");
  return it->get<bool>();
}

// Every field of a point but the wall-clock seconds, as text (its journal record): equal for equal results.
std::string deterministic_text(PointResult p) {
  p.seconds = 0;
  return point_to_line(p, "");
}

MergeResult merge(const std::vector<nlohmann::json>& docs, const std::vector<Where>& where) {
  if (docs.empty()) throw InvalidArgument("merge", "nothing to merge: give at least one diagram JSON");
  MergeResult m;
  m.spec = spec_from_json(docs.front());
  m.header = docs.front();
  for (const char* k : {"shard", "complete", "seconds_included", "summary", "points", "agreement"}) m.header.erase(k);
  // The header must be that of its own configuration (scene_toml and diagram): an edited scene, grid or hash
  // would otherwise be written out as the configuration that computed the points.
  const std::string hash = hash_of(docs.front(), 0);
  const SceneFile scene = scene_of(docs.front());
  const nlohmann::json own = diagram_header(scene.scene, scene.options, m.spec);
  if (own.at("config_hash") != hash)
    throw InvalidArgument("merge", "input 1 has config_hash '" + hash + "', but its scene_toml and diagram hash to " +
                                       own.at("config_hash").dump() + ": the file was edited after the run");
  for (const auto& [key, value] : own.items()) {  // the views of the configuration (scene, integrator) agree with it
    const auto it = m.header.find(key);
    if (it == m.header.end() || *it != value)
      throw InvalidArgument("merge", "input 1 has " + key + " = " +
                                         (it == m.header.end() ? std::string("nothing") : it->dump().substr(0, 200)) +
                                         ", which is not the configuration of its scene_toml and diagram: the file was "
                                         "edited after the run");
  }
  std::map<std::size_t, PointResult> all;
  for (std::size_t d = 0; d < docs.size(); ++d) {
    if (hash_of(docs[d], d) != hash)
      throw InvalidArgument("merge", "input " + std::to_string(d + 1) + " has config_hash '" + hash_of(docs[d], d) +
                                         "', input 1 has '" + hash + "': they are not shards of one diagram");
    m.seconds_present = m.seconds_present && seconds_included(docs[d], d);
    for (PointResult& p : read_points(docs[d], m.spec, where[d])) {
      auto [it, inserted] = all.emplace(p.index, p);
      if (!inserted && deterministic_text(it->second) != deterministic_text(p))
        throw InvalidArgument("merge", "point " + std::to_string(p.index) + " appears twice with different results");
    }
  }
  for (std::size_t idx = 0; idx < m.spec.size(); ++idx)
    if (!all.count(idx)) m.missing.push_back(idx);
  for (auto& [idx, p] : all) m.points.push_back(std::move(p));
  return m;
}

Where position_in(const std::string& input) {
  return [input](std::size_t k, const std::string& field) {
    return input + " points[" + std::to_string(k) + "]." + field;
  };
}
}  // namespace

std::vector<PointResult> points_from_json(const nlohmann::json& doc, const DiagramSpec& spec) {
  return read_points(doc, spec, position_in("diagram JSON"));
}

MergeResult merge_diagrams(const std::vector<nlohmann::json>& docs) {
  std::vector<Where> where;
  for (std::size_t d = 0; d < docs.size(); ++d) where.push_back(position_in("input " + std::to_string(d + 1)));
  return merge(docs, where);
}

MergeResult merge_diagrams(const std::vector<MergeInput>& inputs) {
  std::vector<nlohmann::json> docs;
  std::vector<Where> where;
  for (const MergeInput& in : inputs) {
    docs.push_back(parse_json_text(in.text, in.name, "merge"));
    where.push_back([&in](std::size_t k, const std::string& field) {
      const std::size_t line = point_line(in.text, k, field);
      return in.name + ":" + (line ? std::to_string(line) : "?") + ": points[" + std::to_string(k) + "]." + field;
    });
  }
  return merge(docs, where);
}

}  // namespace rbcstab
