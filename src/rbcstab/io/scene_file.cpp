#include "rbcstab/io/scene_file.hpp"

#include <toml++/toml.h>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <sstream>

#include "rbcstab/core/error.hpp"
#include "rbcstab/core/text.hpp"
#include "rbcstab/io/files.hpp"

namespace rbcstab {

namespace {
constexpr const char* kPanelTables[] = {"diagram", "fig6e", "continuation", "physical_map"};

double number_of(const SceneValue& v) { return std::get<double>(v); }
long long integer_of(const SceneValue& v) { return std::get<long long>(v); }
const std::string& text_of(const SceneValue& v) { return std::get<std::string>(v); }
bool boolean_of(const SceneValue& v) { return std::get<bool>(v); }

void merge_modes(std::map<int, double>& into, const SceneValue& v) {
  for (const auto& [l, d] : std::get<std::map<int, double>>(v)) into[l] = d;
}

// field: a generic lambda returning the number's reference in a (const or not) SceneFile.
template <class Field>
SceneKey number_key(const char* table, const char* key, const char* flag, const char* help, Field field) {
  return {table,
          key,
          ValueKind::number,
          flag,
          help,
          {},
          [field](const SceneFile& f) { return SceneValue{field(f)}; },
          [field](SceneFile& f, const SceneValue& v) { field(f) = number_of(v); }};
}

// The [physical] table: one key per PhysicalCell field, each a quantity with a unit. A key set on a scene
// without a cell creates it; NaN (Python's to_dict of an absent value) leaves the field unset. A key that is also
// a parameter-table row (shear_rate, a continuation parameter and axis) takes its description and range from the
// row, so the two cannot disagree.
void add_physical_keys(std::vector<SceneKey>& k) {
  struct Row {
    const char* key;
    const char* flag;
    double PhysicalCell::*field;
    const char* help;
  };
  const Row rows[] = {
      {"temperature", "--temperature", &PhysicalCell::temperature, "temperature [K] at which energies in kBT are read"},
      {parameter_row(SceneParameter::shear_rate).name, "--shear-rate", &PhysicalCell::shear_rate, nullptr},
      {"viscosity", "--viscosity", &PhysicalCell::viscosity, "external (plasma) viscosity eta_ex [Pa s]"},
      {"inner_viscosity", "--inner-viscosity", &PhysicalCell::inner_viscosity,
       "internal (cytoplasm) viscosity eta_in [Pa s]: lambda = eta_in/eta_ex (else --lambda)"},
      {"radius", "--radius", &PhysicalCell::radius, "radius R [m] (or --area with --volume)"},
      {"area", "--area", &PhysicalCell::area,
       "membrane area A [m^2], with --volume: R = (3V/4 pi)^(1/3), Delta = A/R^2 - 4 pi"},
      {"volume", "--volume", &PhysicalCell::volume, "cell volume V [m^3], with --area"},
      {"stress_free_volume", "--stress-free-volume", &PhysicalCell::stress_free_volume,
       "stress-free volume V0 [m^3], with --area: Delta0 = A/R0^2 - 4 pi, R0 = (3 V0/4 pi)^(1/3)"},
      {"bending_modulus", "--bending-modulus", &PhysicalCell::bending_modulus, "bending modulus kappa [J]"},
      {"shear_modulus", "--shear-modulus", &PhysicalCell::shear_modulus, "(2D) shear modulus mu [N/m]"},
  };
  for (const Row& r : rows) {
    double PhysicalCell::*const field = r.field;
    const PhysicalUnit unit = plausible_range(r.key).unit;
    const std::string key = r.key;
    const ParameterRow* parameter = nullptr;
    for (const ParameterRow& p : parameter_table())
      if (key == p.name) parameter = &p;
    const std::string help = parameter ? parameter->description : r.help;
    k.push_back(
        {"physical",
         r.key,
         ValueKind::quantity,
         "",
         help + "; a number in " + si_unit(unit) + " (bare: only in [" + format_value(plausible_range(r.key).min) +
             ", " + format_value(plausible_range(r.key).max) + "]) or with a unit (" + accepted_units(unit) + ")",
         {},
         [field](const SceneFile& f) { return SceneValue{f.scene.physical ? (*f.scene.physical).*field : kNotGiven}; },
         [field, unit, key, parameter](SceneFile& f, const SceneValue& v) {
           double x = kNotGiven;
           // A bare number (a TOML or Python number, or text without a unit) only within the plausible range.
           if (const auto* text = std::get_if<std::string>(&v)) {
             x = parse_quantity(*text, unit, key, f.scene.physical ? f.scene.physical->temperature : kNotGiven);
             if (!has_unit(*text)) require_plausible_bare(key, x);
           } else {
             x = number_of(v);
             require_plausible_bare(key, x);
           }
           if (std::isnan(x)) {
             if (f.scene.physical) (*f.scene.physical).*field = x;
             return;
           }
           if (parameter)
             require_in(parameter->id, parameter_domain(parameter->id, f.scene.parameters), x);
           else
             require(std::isfinite(x) && x > 0, key, x, "finite and > 0 (" + si_unit(unit) + ")");
           if (!f.scene.physical) f.scene.physical.emplace();
           (*f.scene.physical).*field = x;
         },
         r.flag});
  }
}

std::vector<SceneKey> make_scene_keys() {
  std::vector<SceneKey> k;
  k.push_back({"",
               "name",
               ValueKind::text,
               "--name",
               "label carried into outputs (JSON \"scene\", plot titles, report headings): one line of printable "
               "text",
               {},
               [](const SceneFile& f) { return SceneValue{f.scene.name}; },
               [](SceneFile& f, const SceneValue& v) { f.scene.name = text_of(v); }});
  for (const ParameterRow& r : parameter_table()) {
    if (!r.table) continue;
    const SceneParameter q = r.id;
    k.push_back({r.table,
                 r.name,
                 ValueKind::number,
                 std::string("--") + r.name,
                 std::string(r.description) + (*r.unit ? std::string(" [") + r.unit + "]" : " (dimensionless)") + ", " +
                     parameter_domain(q, Parameters{}).text(false),
                 {},
                 [q](const SceneFile& f) { return SceneValue{get_parameter(f.scene, q)}; },
                 [q](SceneFile& f, const SceneValue& v) { set_parameter(f.scene, q, number_of(v)); }});
  }
  k.push_back(
      {"initial",
       "delta_l",
       ValueKind::modes,
       "--delta-l",
       "per-mode perturbation override Delta_l(0) (dimensionless, in [0, Delta]; modes l in [3, L]), l=value or a "
       "comma list 3=1e-3,4=2e-3 (repeatable; each mode once)",
       {},
       [](const SceneFile& f) { return SceneValue{f.scene.delta_l}; },
       [](SceneFile& f, const SceneValue& v) { merge_modes(f.scene.delta_l, v); }});
  k.push_back(
      {"initial",
       "rest_delta_l",
       ValueKind::modes,
       "--rest-delta-l",
       "stress-free l >= 3 content Delta0_l (dimensionless, in [0, Delta0 + Delta]; modes l in [3, L]), l=value or a "
       "comma list (repeatable; each mode once; only the full level holds it)",
       {},
       [](const SceneFile& f) { return SceneValue{f.scene.rest_delta_l}; },
       [](SceneFile& f, const SceneValue& v) { merge_modes(f.scene.rest_delta_l, v); }});
  add_physical_keys(k);
  k.push_back({"run",
               "L",
               ValueKind::integer,
               "--L",
               "truncation: modes l = 2..L, an integer in [" + std::to_string(kMinL) + ", " + std::to_string(kMaxL) +
                   "]; without --L or run.L each command states its choice (simulate, summary, report, post, "
                   "shape: the smallest L whose dropped modes gain < 1e-4 Delta)",
               {},
               [](const SceneFile& f) { return SceneValue{static_cast<long long>(f.scene.L)}; },
               [](SceneFile& f, const SceneValue& v) {
                 require_L(integer_of(v));
                 f.scene.L = int(integer_of(v));
               }});
  k.push_back(number_key(
      "run", "T", "--T", "horizon T in the time unit 1/shear rate, in (0, 1e7]",
      [](auto& f) -> auto& { return f.scene.T; }));
  k.push_back(number_key(
      "run", "dt", "--dt", "output sampling interval in the time unit 1/shear rate, in (0, T] with T/dt <= 1e7",
      [](auto& f) -> auto& { return f.scene.dt; }));
  std::vector<std::string> levels;
  for (ModelLevel m : {ModelLevel::automatic, ModelLevel::full, ModelLevel::modal, ModelLevel::reduced})
    levels.push_back(to_string(m));
  k.push_back({"run", "model", ValueKind::name, "--model", "model level", levels,
               [](const SceneFile& f) { return SceneValue{to_string(f.scene.model)}; },
               [](SceneFile& f, const SceneValue& v) { f.scene.model = model_level_from_string(text_of(v)); }});
  k.push_back(number_key(
      "run", "tail_window", "",
      "Delta_l are averaged over [T - tail_window, T] (time unit 1/shear rate), finite and > 0",
      [](auto& f) -> auto& { return f.options.tail_window; }));
  k.push_back({"run",
               "full_horizon",
               ValueKind::boolean,
               "",
               "integrate every run to T: no certified early termination on an attracting orbit",
               {},
               [](const SceneFile& f) { return SceneValue{f.options.full_horizon}; },
               [](SceneFile& f, const SceneValue& v) { f.options.full_horizon = boolean_of(v); }});
  k.push_back(
      {"integrator", "stepper", ValueKind::name, "--stepper", "time stepper", stepper_names(),
       [](const SceneFile& f) { return SceneValue{to_string(f.options.integrator.stepper)}; },
       [](SceneFile& f, const SceneValue& v) { f.options.integrator.stepper = stepper_from_string(text_of(v)); }});
  k.push_back(number_key(
      "integrator", "rtol", "--rtol", "relative tolerance (dimensionless), in [1e-15, 0.1]",
      [](auto& f) -> auto& { return f.options.integrator.rtol; }));
  k.push_back(number_key(
      "integrator", "atol", "--atol", "absolute tolerance (in the state's dimensionless units), in [0, 1]",
      [](auto& f) -> auto& { return f.options.integrator.atol; }));
  k.push_back(number_key(
      "integrator", "h_init", "", "first trial step (time unit 1/shear rate), finite and > 0",
      [](auto& f) -> auto& { return f.options.integrator.h_init; }));
  k.push_back(number_key(
      "integrator", "h_min", "",
      "smallest step (time unit 1/shear rate), in (0, h_init]: a smaller one ends the run with status "
      "step_size_underflow",
      [](auto& f) -> auto& { return f.options.integrator.h_min; }));
  k.push_back({"integrator",
               "max_steps",
               ValueKind::integer,
               "",
               "most integrator steps of a run, an integer >= 1: a run never hangs, it ends with status step_limit",
               {},
               [](const SceneFile& f) { return SceneValue{static_cast<long long>(f.options.integrator.max_steps)}; },
               [](SceneFile& f, const SceneValue& v) {
                 require(integer_of(v) > 0, "max_steps", double(integer_of(v)), "> 0");
                 f.options.integrator.max_steps = std::size_t(integer_of(v));
               }});
  k.push_back(number_key(
      "integrator", "max_seconds", "", "wall-clock budget in seconds, finite and >= 0 (0 = none): status time_limit",
      [](auto& f) -> auto& { return f.options.integrator.max_seconds; }));
  return k;
}

// Library validation names the bare symbol ("B", "rtol", "delta_l.3"); a scene file names its key
// ("parameters.B"), so out-of-range messages point at the line to fix.
template <class F>
void with_scene_keys(F&& check) {
  try {
    check();
  } catch (const InvalidArgument& e) {
    const std::string bare = e.parameter().substr(0, e.parameter().find('.'));
    for (const SceneKey& k : scene_keys()) {
      if (k.key != bare || k.table.empty()) continue;
      const std::string key = k.table + "." + e.parameter();
      std::string message = e.what();
      message =
          message.rfind(e.parameter(), 0) == 0 ? key + message.substr(e.parameter().size()) : key + ": " + message;
      throw InvalidArgument(key, message);
    }
    throw;
  }
}

// The root table; a syntax error becomes InvalidArgument("scene", "<source>:<line>:<column>: ...").
toml::table parse_toml(const std::string& text, const std::string& source) {
  try {
    return toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    std::ostringstream msg;
    msg << source << ":" << e.source().begin.line << ":" << e.source().begin.column << ": " << e.description();
    throw InvalidArgument("scene", "cannot parse scene file " + msg.str());
  }
}

std::optional<SceneTable::Item> item_of(const toml::node& node) {
  if (auto v = node.value_exact<bool>()) return SceneTable::Item{*v};
  if (auto v = node.value_exact<int64_t>()) return SceneTable::Item{static_cast<long long>(*v)};
  if (auto v = node.value_exact<double>()) return SceneTable::Item{*v};
  if (auto v = node.value_exact<std::string>()) return SceneTable::Item{*v};
  return std::nullopt;
}

// One value of a table: a scalar, or an array or inline table of scalars (mode maps).
SceneTable::Value value_of(const toml::node& node, const std::string& path) {
  using Shape = SceneTable::Value::Shape;
  SceneTable::Value v;
  auto add = [&](const toml::node& n) {
    const auto item = item_of(n);
    if (!item) throw InvalidArgument(path, path + " must be a number, a string, or an array or table of them");
    v.items.push_back(*item);
  };
  if (const toml::array* a = node.as_array()) {
    v.shape = Shape::array;
    for (const toml::node& n : *a) add(n);
  } else if (const toml::table* t = node.as_table()) {
    v.shape = Shape::table;
    for (const auto& [k, n] : *t) {
      v.keys.emplace_back(k.str());
      add(n);
    }
  } else {
    add(node);
  }
  return v;
}

SceneTable table_of(const std::string& name, const toml::table& t) {
  SceneTable out(name);
  for (const auto& [k, node] : t) out.set(std::string(k.str()), value_of(node, out.path(std::string(k.str()))));
  return out;
}

SceneValue read(const SceneTable& t, const SceneKey& k) {
  switch (k.kind) {
    case ValueKind::number:
      return t.number(k.key);
    case ValueKind::integer:
      return t.integer(k.key);
    case ValueKind::name:
    case ValueKind::text:
      return t.text(k.key);
    case ValueKind::modes:
      return t.modes(k.key);
    case ValueKind::boolean:
      return t.boolean(k.key);
    case ValueKind::quantity:
      if (const auto& items = t.values().at(k.key).items;
          items.size() == 1 && std::holds_alternative<std::string>(items[0]))
        return t.text(k.key);
      return t.number(k.key);
  }
  return {};
}
}  // namespace

Origin SceneFile::origin(const std::string& key) const {
  const auto it = origins.find(key);
  return it == origins.end() ? Origin::default_value : it->second;
}

const std::vector<SceneKey>& scene_keys() {
  static const std::vector<SceneKey> keys = make_scene_keys();
  return keys;
}

std::vector<const SceneKey*> scene_flags() {
  std::vector<const SceneKey*> flags;
  for (const SceneKey& k : scene_keys())
    if (!k.flag.empty()) flags.push_back(&k);
  return flags;
}

void apply_flag(SceneFile& file, const SceneKey& key, const SceneValue& value) {
  key.set(file, value);
  file.origins[key.path()] = Origin::flag;
}

void apply_unit_flag(SceneFile& file, const SceneKey& key, const std::string& text) {
  try {
    apply_flag(file, key, text);
  } catch (const InvalidArgument& e) {
    const std::string m = e.what();
    const std::string& name = key.unit_flag;
    throw InvalidArgument(name, m.rfind(key.key, 0) == 0 ? name + m.substr(key.key.size()) : name + ": " + m);
  }
}

std::map<int, double> parse_modes(const std::vector<std::string>& items, const std::string& flag) {
  const std::string form =
      " must be l=value with an integer mode l >= 3 and a number, e.g. 3=1e-3 (several: 3=1e-3,4=2e-3)";
  std::map<int, double> out;
  for (const auto& item : items) {
    for (const std::string& pair : comma_items(item)) {  // several modes at once; an empty one ("3=1e-3,") is an error
      const auto eq = pair.find('=');
      std::size_t lpos = 0;
      int l = 0;
      std::optional<double> v;
      try {
        if (eq == std::string::npos || eq == 0) throw std::invalid_argument(pair);
        l = std::stoi(pair.substr(0, eq), &lpos);
        v = read_number(pair.substr(eq + 1));
      } catch (const std::exception&) {
        lpos = 0;
      }
      if (eq == std::string::npos || lpos != eq || !v) throw InvalidArgument(flag, flag + " = '" + item + "'" + form);
      if (!out.emplace(l, *v).second)
        throw InvalidArgument(
            flag, flag + " = '" + item + "' repeats mode l = " + std::to_string(l) + ": give each mode once");
    }
  }
  return out;
}

namespace {
bool names_word(const std::string& text, const std::string& word) {
  auto part = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  for (std::size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1))
    if ((at == 0 || !part(text[at - 1])) && (at + word.size() == text.size() || !part(text[at + word.size()])))
      return true;
  return false;
}

// A name as a message quotes it: JSON-escaped, so a control character stays visible and the message one line.
std::string quoted_name(const std::string& name) {
  return nlohmann::json(name).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

// Where each value a message names came from ("run.dt from the scene file s.toml; run.T from --T"): a range
// that depends on another value (dt <= T) is fixed in either place.
std::string origins_named(const SceneFile& file, const std::string& message) {
  std::string out;
  for (const SceneKey& k : scene_keys()) {
    if (k.table.empty() || !names_word(message, k.key)) continue;
    const Origin o = file.origin(k.path());
    const std::string from = o == Origin::flag   ? k.any_flag()
                             : o == Origin::file ? "the scene file " + file.source
                                                 : "the default";
    out += (out.empty() ? "" : "; ") + k.path() + " from " + from;
  }
  return out;
}
}  // namespace

void validate_scene_file(const SceneFile& file) {
  try {
    file.scene.validate();
    file.options.validate();
  } catch (const InvalidArgument& e) {
    if (e.parameter() == "name") {  // the word "name" is in many messages: matched by parameter, not by text
      const std::string from = file.origin("name") == Origin::flag   ? "--name"
                               : file.origin("name") == Origin::file ? "the scene file " + file.source
                                                                     : "the default";
      throw InvalidArgument("name",
                            std::string(e.what()) + " (name = " + quoted_name(file.scene.name) + " from " + from + ")");
    }
    const std::string from = origins_named(file, e.what());
    if (from.empty()) throw;
    throw InvalidArgument(e.parameter(), std::string(e.what()) + " (" + from + ")");
  }
}

ValidScene validated(const SceneFile& file) {
  validate_scene_file(file);
  return ValidScene(file.scene);
}

namespace {
// How a message names where a key's value came from: its flag when a flag gave it, else its path.
std::string given_as(const SceneFile& file, const SceneKey& k) {
  return file.origin(k.path()) == Origin::flag && !k.any_flag().empty() ? k.any_flag() : k.path();
}
const SceneKey& key_at(const std::string& table, const std::string& key) {
  for (const SceneKey& k : scene_keys())
    if (k.table == table && k.key == key) return k;
  throw std::logic_error("no scene key " + table + "." + key);
}
}  // namespace

bool derived_from_physical(const SceneFile& file, const SceneKey& key) {
  if (!file.scene.physical || key.table != "parameters") return false;
  for (const DerivedParameter& d : derived_parameters(*file.scene.physical))
    if (d.parameter == key.key) return true;
  return false;
}

void resolve_physical(SceneFile& file) {
  if (!file.scene.physical) return;
  const PhysicalCell& cell = *file.scene.physical;
  // The physical key named in a message: the first given one among a parameter's inputs.
  for (const DerivedParameter& d : derived_parameters(cell)) {
    const SceneKey& parameter = key_at("parameters", d.parameter);
    if (file.origin(parameter.path()) == Origin::default_value) continue;
    for (const std::string& input : d.physical) {
      const SceneKey& physical = key_at("physical", input);
      if (file.origin(physical.path()) == Origin::default_value) continue;
      throw InvalidArgument(parameter.path(), given_as(file, parameter) + " and " + given_as(file, physical) +
                                                  " both given: " + d.parameter +
                                                  " follows from the physical values; give one of them");
    }
  }
  try {
    cell.validate_complete();
  } catch (const InvalidArgument& e) {
    const SceneKey& k = key_at("physical", e.parameter());
    std::string message = e.what();
    if (message.rfind(e.parameter(), 0) == 0) message = given_as(file, k) + message.substr(e.parameter().size());
    throw InvalidArgument(k.path(), message);
  }
  file.scene.parameters = physical_parameters(cell, file.scene.parameters);
}

SceneFile parse_scene(const std::string& toml_text, const std::string& source_name) {
  const toml::table root = parse_toml(toml_text, source_name);
  SceneFile f;
  f.source = source_name;
  f.text = toml_text;
  std::set<std::string> allowed(std::begin(kPanelTables), std::end(kPanelTables)), tables;
  for (const SceneKey& k : scene_keys()) {
    allowed.insert(k.table.empty() ? k.key : k.table);
    if (!k.table.empty()) tables.insert(k.table);
  }
  SceneTable names, top;  // every root key (checked first), and the root's values
  std::map<std::string, SceneTable> sub;
  for (const auto& [k, node] : root) {
    const std::string key(k.str());
    names.set(key, {});
    if (const toml::table* t = node.as_table())
      sub.emplace(key, table_of(key, *t));
    else
      top.set(key, value_of(node, key));
  }
  names.allow_only(allowed);
  for (const auto& [key, v] : top.values())
    if (tables.count(key) || std::find(std::begin(kPanelTables), std::end(kPanelTables), key) != std::end(kPanelTables))
      throw InvalidArgument(key, "scene key '" + key + "' must be a table ([" + key + "])");
  for (auto& [name, t] : sub) {
    if (tables.count(name)) continue;
    for (const auto& [key, v] : t.values()) f.origins[t.path(key)] = Origin::file;
    (name == "diagram"        ? f.diagram
     : name == "fig6e"        ? f.fig6e
     : name == "continuation" ? f.continuation
                              : f.physical_map) = std::move(t);
  }
  for (const std::string& name : tables) {
    const auto it = sub.find(name);
    if (it == sub.end()) continue;
    std::set<std::string> keys;
    for (const SceneKey& k : scene_keys())
      if (k.table == name) keys.insert(k.key);
    it->second.allow_only(keys);
  }
  for (const SceneKey& k : scene_keys()) {
    const SceneTable* t = k.table.empty() ? &top : nullptr;
    if (!t) {
      const auto it = sub.find(k.table);
      t = it == sub.end() ? nullptr : &it->second;
    }
    if (!t || !t->has(k.key)) continue;
    const SceneValue v = read(*t, k);
    with_scene_keys([&] { k.set(f, v); });
    f.origins[k.path()] = Origin::file;
  }
  with_scene_keys([&] { resolve_physical(f); });
  with_scene_keys([&] { validate_scene_file(f); });
  return f;
}

SceneFile load_scene(const std::string& path) { return parse_scene(read_file(path, "scene", kMaxSceneBytes), path); }

std::string to_toml(const SceneFile& file) {
  toml::table root;
  for (const SceneKey& k : scene_keys()) {
    if (derived_from_physical(file, k)) continue;
    if (k.kind == ValueKind::quantity && std::isnan(number_of(k.get(file)))) continue;
    toml::table* t = &root;
    if (!k.table.empty()) {
      if (!root.contains(k.table)) root.insert(k.table, toml::table{});
      t = root[k.table].as_table();
    }
    const SceneValue v = k.get(file);
    switch (k.kind) {
      case ValueKind::number:
        t->insert(k.key, number_of(v));
        break;
      case ValueKind::quantity:  // with its unit where a bare number would be refused on reading
        if (needs_unit_text(k.key, number_of(v)))
          t->insert(k.key, with_si_unit(k.key, number_of(v)));
        else if (!std::isnan(number_of(v)))
          t->insert(k.key, number_of(v));
        break;
      case ValueKind::integer:
        t->insert(k.key, static_cast<int64_t>(integer_of(v)));
        break;
      case ValueKind::name:
      case ValueKind::text:
        t->insert(k.key, text_of(v));
        break;
      case ValueKind::boolean:
        t->insert(k.key, boolean_of(v));
        break;
      case ValueKind::modes: {
        toml::table m;
        for (const auto& [l, d] : std::get<std::map<int, double>>(v)) m.insert(std::to_string(l), d);
        t->insert(k.key, std::move(m));
        break;
      }
    }
  }
  std::ostringstream ss;
  ss << root << "\n";
  return ss.str();
}

}  // namespace rbcstab
