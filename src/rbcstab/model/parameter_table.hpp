#pragma once
// The scene's parameters, one row each: name, symbol, description, domain with its message, get/set on a
// Scene, where a scene file keeps it and how an axis spaces it. shear_rate (gamma, 1/s) is the one row valid
// only on a physical scene (Scene::physical): its get and set throw InvalidArgument("shear_rate", ...) elsewhere. Scene files and command-line flags (io),
// continuation parameters (continuation/parameters.hpp) and diagram axes (sweep/diagram.hpp) all take their
// names and checks from this table, so adding a parameter is one enumerator and one row.
#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "rbcstab/core/enum_table.hpp"
#include "rbcstab/model/parameters.hpp"
#include "rbcstab/model/scene.hpp"

namespace rbcstab {

// Table order: the five material numbers, the composites of the reduced system, the log axes, the scene's
// shape parameters, then the physical path parameter. Lists of names (messages, --help) follow it.
enum class SceneParameter { lambda, Delta, Delta0, B, C, Lambda, S, alpha, lnB, lnC, beta, delta, shear_rate };

// Where a scene value came from.
enum class Origin { default_value, file, flag };
template <>
struct EnumTable<Origin> {
  static constexpr EnumName<Origin> entries[] = {
      {Origin::default_value, "default"}, {Origin::file, "file"}, {Origin::flag, "flag"}};
};

// How a row is valued and how an axis spaces it. log: the value is ln of another row's (lnB), spaced evenly;
// geometric: the value itself, its grid spaced evenly in ln (a rate over decades: 10, 100, 1000 1/s).
enum class AxisScale { linear, log, geometric };

// The values a parameter may take. An infinite end is a value only when closed (C = inf: the vesicle limit).
struct Domain {
  double lo = -INFINITY, hi = INFINITY;
  bool lo_closed = false, hi_closed = false;
  std::string lo_name, hi_name;  // shown instead of the number ("4 pi", "Delta"); empty: the number
  std::string where;             // the values the bounds depend on ("Delta = 1"), shown after "with"
  std::string note;              // shown in parentheses after the range
  bool contains(double value) const;
  // "finite and >= 0", "in (0, 4 pi)", "in [0, Delta] with Delta = 1", "> 0 (inf allowed: the vesicle limit)";
  // without `where` for --help, where the bound's value is not known yet.
  std::string text(bool with_where = true) const;
};

// What a name may be used as.
enum class ParameterUse {
  scene_key,     // a key of a scene file and a command-line flag (the row has a table)
  continuation,  // a continuation parameter (rbcstab continue --parameter)
  axis,          // a diagram or trace axis (rbcstab diagram --axes)
};

struct ParameterRow {
  SceneParameter id;
  const char* name;         // the scene key, the flag --name, the continuation and axis name
  const char* symbol;       // TeX, for figure labels
  const char* unit;         // of a dimensional value, for labels ("1/s"); "" for the dimensionless numbers
  const char* description;  // one line for --help and docs/scenes.md
  const char* table;        // the scene file's table holding it ("parameters", "initial"); nullptr: derived
  AxisScale scale;          // log: the value is ln of `of`'s (lnB = ln B); get, set and domain follow from `of`
  SceneParameter of;        // log rows: the parameter taken the log of; otherwise the row itself
  SceneParameter moves;     // the stored parameter that set() changes (a composite moves one input)
  // Bit set (1u << parameter) of the stored parameters the value depends on. shear_rate, stored in the scene's
  // physical cell, lists B and C too: they are proportional to it there, so it moves them with it.
  std::uint32_t inputs;
  bool continuation;        // usable as a continuation parameter
  bool axis;                // usable as a diagram axis
  // Linear rows only (log rows take them from `of`):
  // Where the scene is valid: the range every scene key, flag, continuation bound and diagram axis enforces
  // (beta in [0, pi]: pi - beta is the mirror image of beta).
  Domain (*domain)(const Parameters& p);
  double (*get)(const Scene& s);
  // Sets the value without checking it; throws InvalidArgument only when the composite cannot be moved from
  // this scene (S from an infinite S).
  void (*set)(Scene& s, double value);
};

std::span<const ParameterRow> parameter_table();
const ParameterRow& parameter_row(SceneParameter q);
std::string to_string(SceneParameter q);      // the row's name
std::string parameter_label(SceneParameter q);  // plain-text symbol: the name, "ln B" for a log axis
bool usable_as(SceneParameter q, ParameterUse use);
// A function of the material Parameters alone (every input lives in [parameters]; beta and delta do not).
bool is_material(SceneParameter q);
std::vector<std::string> parameter_names(ParameterUse use);  // in table order
// Throws InvalidArgument("parameter" | "axis" | "key", "<what> = '<name>' is not a <use>: must be one of ...").
SceneParameter parameter_from_string(std::string_view name, ParameterUse use);

double get_parameter(const Scene& s, SceneParameter q);
// Unchecked (see ParameterRow::set): callers validate the scene afterwards, or use with_parameter
// (continuation/parameters.hpp), which checks the value first.
void set_parameter(Scene& s, SceneParameter q, double value);
Domain parameter_domain(SceneParameter q, const Parameters& p);
// The domain a continuation lands on at its closed edges: parameter_domain (one range for every use).
Domain continuation_domain(SceneParameter q, const Parameters& p);
// Throws InvalidArgument(name, "<name> = <value> is out of range: must be <domain text>") outside `domain`
// ("finite and <domain text>" for an infinite value when the text does not say so).
void require_in(SceneParameter q, const Domain& domain, double value);
// The stored parameters of one scene-file table, each against its domain, in table order.
void validate_table(const Scene& s, std::string_view table);
// False when setting one would move the other (equal, or sharing an input: Lambda with Delta or lambda). One
// exception: shear_rate scales B and C together, so it leaves alpha = B/C alone and is independent of it.
bool independent(SceneParameter a, SceneParameter b);
// The scene's physical cell, complete; else InvalidArgument(name, "<name> needs a physical scene: ...") naming
// the [physical] keys and flags that make one. Where a row valid only on a physical scene is first used
// (continuation start, diagram and trace axes) this gives the message before any work.
const PhysicalCell& physical_cell(const Scene& s, const std::string& name);
// Throws that message when q cannot be used on s (shear_rate without a physical cell); else nothing.
void require_usable(SceneParameter q, const Scene& s);

}  // namespace rbcstab
