#pragma once
// Scene files (TOML). Keys are the paper's symbols; docs/scenes.md lists them with their ranges. A file is
// read once into a SceneFile: the scene, the run options, the figure-panel tables as plain values, and where
// every value came from; command-line flags are applied on top of it (scene_flags, apply_flag).
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "rbcstab/integrate/simulation.hpp"
#include "rbcstab/io/scene_table.hpp"
#include "rbcstab/model/parameter_table.hpp"
#include "rbcstab/model/scene.hpp"

namespace rbcstab {

struct SceneFile {
  Scene scene;
  SimulationOptions options;  // run.tail_window and the [integrator] table
  // The figure-panel tables as the file gives them; the modules that run them read their keys
  // (sweep/diagram_file.hpp: [diagram]; report/panels.hpp: [fig6e], [continuation]).
  std::optional<SceneTable> diagram{}, fig6e{}, continuation{};
  // Where each value came from, by its key ("parameters.B", "run.L", "name", "diagram.axes"): a key the file
  // or a flag gave; absent keys hold their default.
  std::map<std::string, Origin> origins{};
  // Why scene.L: the truncation policy's reason (resolve_truncation, analysis/truncation.hpp), which every JSON
  // output carries beside "L" (put_truncation, io/json.hpp); empty until the policy is applied.
  std::string L_reason{};
  std::string source{};  // the file's name, "" without a file
  std::string text{};    // the file as read ("" without a file): a panel report keeps it verbatim

  Origin origin(const std::string& key) const;
};

// A scene value as a file or a flag gives it.
enum class ValueKind { number, integer, name, text, modes, boolean };  // name: one of SceneKey::names
using SceneValue = std::variant<double, long long, std::string, std::map<int, double>, bool>;

// Every key of a scene file outside the panel tables, one row each: the parameter table's stored rows
// (model/parameter_table.hpp), then the run and integrator options. The parser, to_toml, the provenance and the
// command-line flags are all made from these rows.
struct SceneKey {
  std::string table, key;          // "parameters", "B"; table "" for the root's "name"
  ValueKind kind = ValueKind::number;
  std::string flag;                // "--B", "--delta-l"; "" when only a file sets it (a boolean's flag sets it true)
  std::string help;                // one line for --help: meaning and range
  std::vector<std::string> names;  // ValueKind::name: the allowed values
  std::function<SceneValue(const SceneFile&)> get;
  // Unchecked but for what a narrowing needs (L and max_steps in range, a known name): the scene and options
  // are validated after every key is set. ValueKind::modes merges (a flag overrides single modes).
  std::function<void(SceneFile&, const SceneValue&)> set;
  std::string path() const { return table.empty() ? key : table + "." + key; }
};
const std::vector<SceneKey>& scene_keys();
// The rows with a flag, in --help order.
std::vector<const SceneKey*> scene_flags();
// Sets one flag's value on the file's scene and records its origin as a flag. The caller validates the scene
// and options after the last flag (validate_scene_file).
void apply_flag(SceneFile& file, const SceneKey& key, const SceneValue& value);
// "l=value" items of a repeatable mode flag (--delta-l 3=1e-3), each item also a comma list (3=1e-3,4=2e-3);
// the whole text must parse and each mode appear once, else InvalidArgument(flag, ...).
std::map<int, double> parse_modes(const std::vector<std::string>& items, const std::string& flag);
void validate_scene_file(const SceneFile& file);  // the scene and the simulation options

// Parses TOML text; unknown keys, wrong types and out-of-range values throw InvalidArgument naming the key
// (as "table.key") and the allowed range. The panel tables are kept, not interpreted.
SceneFile parse_scene(const std::string& toml_text, const std::string& source_name = "scene");
SceneFile load_scene(const std::string& path);
// The scene and options as TOML (round-trips through parse_scene; panels and origins are not written).
std::string to_toml(const SceneFile& file);

}  // namespace rbcstab
