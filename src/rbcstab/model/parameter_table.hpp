#pragma once
// The scene's parameters, one row each: name, symbol, description, domain with its message, get/set on a
// Scene, where a scene file keeps it and how an axis spaces it. shear_rate (gamma, 1/s) is the one row valid
// only on a physical scene (Scene::physical): its get and set throw InvalidArgument("shear_rate", ...) elsewhere. Scene
// files and command-line flags (io), continuation parameters (continuation/continuation_parameter.hpp) and diagram axes
// (sweep/diagram.hpp) all take their names and checks from this table, so adding a parameter is one enumerator and one
// row.
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
template <>
struct EnumTable<AxisScale> {
  static constexpr EnumName<AxisScale> entries[] = {
      {AxisScale::linear, "linear"}, {AxisScale::log, "log"}, {AxisScale::geometric, "geometric"}};
};

// The values a parameter may take. An infinite end is a value only when closed (C = inf: the vesicle limit).
struct Domain {
  double lo = -INFINITY, hi = INFINITY;
  bool lo_closed = false, hi_closed = false;
  std::string lo_name, hi_name;  // shown instead of the number ("4 pi", "Delta"); empty: the number
  std::string where;             // the values the bounds depend on ("Delta = 1"), shown after "with"
  std::string note;              // shown in parentheses after the range
  bool contains(double value) const;
  // The domain without a bound that is not known (NaN: Delta0's upper end Delta where Delta is not given).
  Domain known() const;
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

// The model levels a row moves (bit set of 1u << ModelLevel): a level it leaves alone has the same right-hand
// side and initial state at every value (tests/model/parameter_table_test.cpp checks each bit against the
// systems). The reduced (l = 2) level takes Upsilon_2 itself as its multiplier, so B drops out of it.
inline constexpr unsigned level_bit(ModelLevel level) { return 1u << static_cast<unsigned>(level); }
inline constexpr unsigned kEveryLevel =
    level_bit(ModelLevel::reduced) | level_bit(ModelLevel::modal) | level_bit(ModelLevel::full);
inline constexpr unsigned kModesAboveTwo = level_bit(ModelLevel::modal) | level_bit(ModelLevel::full);

// How a dimensionless number is made from a cell in physical units (Sec. II), for `rbcstab units`, the
// [physical] table and docs/units.md. A row without one (formula nullptr) is not made from physical inputs.
struct PhysicalFormula {
  const char* formula = nullptr;                    // "eta_ex gamma R^3 / kappa"
  const char* reference = nullptr;                  // "Eq. (dimless_nums)"
  double (*value)(const CellNumbers& n) = nullptr;  // NaN where an input is missing
  // `rbcstab units --<name>`: the physical value a given number completes ("the shear rate"), and where the
  // query holds it; nullptr: not an input of the conversion.
  const char* completes = nullptr;
  double UnitsQuery::*input = nullptr;
};

struct ParameterRow {
  SceneParameter id;
  const char* name;         // the scene key, the flag --name, the continuation and axis name, the Python keyword
  const char* symbol;       // TeX, for figure labels
  const char* unicode;      // for text and HTML ("λ", "Δ₀")
  const char* unit = "";    // of a dimensional value, for labels ("1/s"); "" for the dimensionless numbers
  const char* description;  // one line for --help and docs/scenes.md
  const char* table;        // the scene file's table holding it ("parameters", "initial"); nullptr: derived
  AxisScale scale;          // log: the value is ln of `of`'s (lnB = ln B); get, set and domain follow from `of`
  SceneParameter of;        // log rows: the parameter taken the log of; otherwise the row itself
  SceneParameter moves;     // the stored parameter that set() changes (a composite moves one input: Lambda, Delta)
  // Bit set (1u << parameter) of the stored parameters the value depends on. shear_rate, stored in the scene's
  // physical cell, lists B and C too: they are proportional to it there, so it moves them with it.
  std::uint32_t inputs;
  unsigned levels;    // the model levels it moves (level_bit)
  bool continuation;  // usable as a continuation parameter
  bool axis;          // usable as a diagram axis
  // A derived row's definition from the stored ones ("B/C"); nullptr for a stored row.
  const char* definition = nullptr;
  PhysicalFormula physical = {};
  // Linear rows only (log rows take them from `of` and leave them null):
  // Where the scene is valid: the range every scene key, flag, continuation bound, diagram axis and units
  // input enforces (beta in [0, pi]: pi - beta is the mirror image of beta).
  Domain (*domain)(const Parameters& p) = nullptr;
  double (*get)(const Scene& s) = nullptr;
  // Sets the value without checking it; throws InvalidArgument only when the composite cannot be moved from
  // this scene (S from an infinite S).
  void (*set)(Scene& s, double value) = nullptr;
};

std::span<const ParameterRow> parameter_table();
const ParameterRow& parameter_row(SceneParameter q);
std::string to_string(SceneParameter q);        // the row's name
std::string parameter_label(SceneParameter q);  // plain-text symbol: the name, "ln B" for a log axis
// The stored parameter a row is set through (Lambda: Delta, S: C, lnB: B), and whether setting any of `free`
// moves `stored` (also shear_rate, which moves B and C with it): a branch in `free` holds the others fixed.
SceneParameter moved_parameter(SceneParameter q);
bool moves_stored(std::span<const SceneParameter> free, SceneParameter stored);
// The rows a scene file stores in `table` ("parameters", "initial"), in table order.
std::vector<SceneParameter> stored_parameters(std::string_view table);
// The composites: rows with a definition from the stored ones (Lambda, S, alpha), in table order.
std::vector<SceneParameter> composite_parameters();
bool usable_as(SceneParameter q, ParameterUse use);
// A function of the material Parameters alone (every input lives in [parameters]; beta and delta do not).
bool is_material(SceneParameter q);
std::vector<std::string> parameter_names(ParameterUse use);  // in table order
// Throws InvalidArgument("parameter" | "axis" | "key", "<what> = '<name>' is not a <use>: must be one of ...").
SceneParameter parameter_from_string(std::string_view name, ParameterUse use);

double get_parameter(const Scene& s, SceneParameter q);
// Unchecked (see ParameterRow::set): callers validate the scene afterwards, or use with_parameter
// (continuation/continuation_parameter.hpp), which checks the value first.
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

// Why a number computed from p is not finite, naming the inputs that caused it: those that are infinite, so
// large that a square overflows (|v| > 1e150) or so small that a square of the inverse does (0 < |v| < 1e-150);
// "C = inf" is the vesicle limit.
std::string nonfinite_reason(const Parameters& p);
// Why S is infinite (Delta0 = 0 or C = inf: the vesicle limit) or else not finite.
std::string S_reason(const Parameters& p);

}  // namespace rbcstab
