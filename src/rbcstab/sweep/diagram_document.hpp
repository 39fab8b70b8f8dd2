#pragma once
// Diagram outputs: CSV (one row per point, index order) and JSON (configuration, per-point
// records, verdict counts and cost), plus merging of shard outputs. Both are pure functions of the
// configuration and the points, so a serial run, a threaded run, MPI ranks and merged shards give
// the same bytes (per-point wall-clock seconds aside, which include_seconds = false drops).
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "rbcstab/sweep/agreement.hpp"
#include "rbcstab/sweep/diagram.hpp"

namespace rbcstab {

struct DiagramOutputOptions {
  bool include_seconds = true;  // per-point wall-clock cost; false makes the output reproducible byte for byte
};

// Everything that defines the diagram: scene, integrator options, axes, classifier, config hash.
nlohmann::json diagram_header(const Scene& base, const SimulationOptions& options, const DiagramSpec& spec);

std::string diagram_csv(const DiagramSpec& spec, const std::vector<PointResult>& points,
                        const DiagramOutputOptions& o = {});
// header + "points" + "summary"; shard (if n > 1) and "complete" say which part of the grid it holds.
nlohmann::json diagram_json(const nlohmann::json& header, const DiagramSpec& spec,
                            const std::vector<PointResult>& points, const Shard& shard,
                            const DiagramOutputOptions& o = {});

// Every predictor's agreement with the points (agreement.hpp) as JSON: the asymptotic predictor's fields at the
// top level and one entry per predictor in "predictors".
nlohmann::json agreement_json(const Scene& base, const DiagramSpec& spec, const std::vector<PointResult>& points,
                              const AgreementOptions& options = {});

// The spec and points back from a diagram_json document (throws InvalidArgument("merge", ...) naming
// the point and field of any value that is not a verdict/status name, a number where one is due, an integer
// where one is due (never truncated), or that point_value_error refuses, e.g. l_Delta outside [2, L]; a
// document without a valid scene_toml is refused).
DiagramSpec spec_from_json(const nlohmann::json& doc);
std::vector<PointResult> points_from_json(const nlohmann::json& doc, const DiagramSpec& spec);

struct MergeResult {
  nlohmann::json header;
  DiagramSpec spec;
  std::vector<PointResult> points;   // index order
  std::vector<std::size_t> missing;  // grid indices no input held
  bool seconds_present = true;       // every input carried per-point seconds
};
// Merges shard outputs of one diagram: they must share the config hash, which must be the hash of the first
// input's scene_toml and diagram (an edited header is refused); a point held twice must agree (deterministic
// runs) or it throws InvalidArgument("merge", ...).
MergeResult merge_diagrams(const std::vector<nlohmann::json>& docs);
// The same from files' text: errors name the file and the line of the offending value ("cc.json:57: ...").
struct MergeInput {
  std::string name;  // the file name, for messages
  std::string text;  // its content
};
MergeResult merge_diagrams(const std::vector<MergeInput>& inputs);

}  // namespace rbcstab
