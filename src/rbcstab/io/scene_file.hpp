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

// The check after a run at an automatically reduced L (simulate_truncated, analysis/truncation.hpp): the modes
// the run dropped, what the run's sigma(t) makes of them, and the verdict. JSON outputs carry it as
// "truncation_check" (put_truncation, io/json.hpp; docs/cli.md lists the keys).
struct TruncationCheck {
  struct DroppedMode {
    int l = 3;
    double delta = 0;      // its seeded area delta_l
    double Delta_max = 0;  // upper bound of max_t Delta_l(t) along the run's sigma(t)
    double t_max = 0;      // where that bound is reached
  };
  int L_scene = 10;                  // the scene's L: the seeded modes l = 3..L_scene
  int L_candidate = 10;              // the L the a priori rule proposed and that was run first
  int L_run = 10;                    // the L of the run the outputs come from (L_candidate if passed, else L_scene)
  std::vector<DroppedMode> dropped;  // l = L_candidate + 1..L_scene
  double threshold = 0;    // a dropped mode must stay below delta_l + threshold (tolerance * Delta) at every t
  double sigma_shift = 0;  // upper bound of |sigma_scene(t) - sigma_run(t)| from the dropped modes' area
  double t_sigma_shift = 0;
  double sigma_tolerance = 0;  // tolerance * max_t |sigma_run(t)|
  std::size_t samples = 0;     // accepted steps of the run the check read
  bool passed = false;
  std::string verdict;  // one line: what passed or what failed
};

struct SceneFile {
  Scene scene;
  SimulationOptions options;  // run.tail_window and the [integrator] table
  // The figure-panel tables as the file gives them; the modules that run them read their keys
  // (sweep/diagram_table.hpp: [diagram]; report/panels.hpp: [fig6e], [continuation], [physical_map]).
  std::optional<SceneTable> diagram{}, fig6e{}, continuation{}, physical_map{};
  // Where each value came from, by its key ("parameters.B", "run.L", "name", "diagram.axes"): a key the file
  // or a flag gave; absent keys hold their default.
  std::map<std::string, Origin> origins{};
  // Why scene.L: the truncation policy's reason (resolve_truncation, analysis/truncation.hpp), which every JSON
  // output carries beside "L" (put_truncation, io/json.hpp); empty until the policy is applied.
  std::string L_reason{};
  // Set when an automatic L below the scene's was run and checked (simulate_truncated).
  std::optional<TruncationCheck> truncation_check{};
  std::string source{};  // the file's name, "" without a file
  std::string text{};    // the file as read ("" without a file): a panel report keeps it verbatim

  Origin origin(const std::string& key) const;
};

// A scene value as a file or a flag gives it.
// name: one of SceneKey::names; quantity: a physical value, a number in SI units or a text with a unit ("3.9um")
enum class ValueKind { number, integer, name, text, modes, boolean, quantity };
using SceneValue = std::variant<double, long long, std::string, std::map<int, double>, bool>;

// Every key of a scene file outside the panel tables, one row each: the parameter table's stored rows
// (model/parameter_table.hpp), then the run and integrator options. The parser, to_toml, the provenance and the
// command-line flags are all made from these rows.
struct SceneKey {
  std::string table, key;  // "parameters", "B"; table "" for the root's "name"
  ValueKind kind = ValueKind::number;
  std::string flag;                // "--B", "--delta-l"; "" when only a file sets it (a boolean's flag sets it true)
  std::string help;                // one line for --help: meaning and range
  std::vector<std::string> names;  // ValueKind::name: the allowed values
  std::function<SceneValue(const SceneFile&)> get;
  // Unchecked but for what a narrowing needs (L and max_steps in range, a known name): the scene and options
  // are validated after every key is set. ValueKind::modes merges (a flag overrides single modes).
  std::function<void(SceneFile&, const SceneValue&)> set;
  // A flag that front ends add themselves, beside scene_flags(): the [physical] keys ("--shear-rate"), whose
  // values take units.
  std::string unit_flag{};
  std::string path() const { return table.empty() ? key : table + "." + key; }
  std::string any_flag() const { return flag.empty() ? unit_flag : flag; }
};
const std::vector<SceneKey>& scene_keys();
// The rows with a flag, in --help order.
std::vector<const SceneKey*> scene_flags();
// Sets one flag's value on the file's scene and records its origin as a flag. The caller validates the scene
// and options after the last flag (validate_scene_file).
void apply_flag(SceneFile& file, const SceneKey& key, const SceneValue& value);
// A [physical] key's text ("3.9um") as its unit flag gives it; a refusal names the flag ("--radius = ...").
void apply_unit_flag(SceneFile& file, const SceneKey& key, const std::string& text);
// "l=value" items of a repeatable mode flag (--delta-l 3=1e-3), each item also a comma list (3=1e-3,4=2e-3);
// the whole text must parse and each mode appear once, else InvalidArgument(flag, ...).
std::map<int, double> parse_modes(const std::vector<std::string>& items, const std::string& flag);
void validate_scene_file(const SceneFile& file);  // the scene and the simulation options
// validate_scene_file, then the proof of it (model/scene.hpp): a library entry that takes a scene file checks it
// once here, naming in its messages the flag or file each value came from.
ValidScene validated(const SceneFile& file);

// A physical scene ([physical] keys or their flags): derives the parameters its cell determines
// (physical_parameters, model/physical.hpp) after the last key or flag is set. A parameter given too (in the file
// or by a flag) is refused: InvalidArgument("<parameter>", "<--B or parameters.B> and <--shear-rate or
// physical.shear_rate> both given: ..."). Without physical keys it does nothing.
void resolve_physical(SceneFile& file);
// The [parameters] keys a physical scene derives (written only in [physical] by to_toml).
bool derived_from_physical(const SceneFile& file, const SceneKey& key);

// Parses TOML text; unknown keys, wrong types and out-of-range values throw InvalidArgument naming the key
// (as "table.key") and the allowed range. The panel tables are kept, not interpreted.
SceneFile parse_scene(const std::string& toml_text, const std::string& source_name = "scene");
SceneFile load_scene(const std::string& path);
// The scene and options as TOML (round-trips through parse_scene; panels and origins are not written).
std::string to_toml(const SceneFile& file);

}  // namespace rbcstab
