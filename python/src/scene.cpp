// rbcstab.Scene: a scene file's content (io/scene_file.hpp) built from keywords, one per scene key. The keys,
// their kinds, defaults and ranges come from io's scene_keys(), so the CLI's flags, the TOML keys and these
// keywords cannot drift apart. Everything a computation reads from a scene (the keys, whether a key whose
// default is a choice was given, the panel tables, the file it came from) is in to_dict(), repr(), == and hash,
// so a copy, a pickle or Scene.from_dict(s.to_dict()) behaves as the scene does.
#include <pybind11/stl.h>

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <functional>
#include <optional>
#include <set>

#include "bindings.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/io/scene_defaults.hpp"
#include "rbcstab/model/parameter_table.hpp"
#include "rbcstab/report/bifurcation_plot.hpp"

namespace rbcstab::python {

std::string keyword_of(const std::string& key) { return key == "lambda" ? "lambda_" : key; }

namespace {

using python::keyword_of;  // beside the overload below, not hidden by it
std::string keyword_of(const SceneKey& k) { return keyword_of(k.key); }

// The type a keyword takes, as a Python annotation: a name's allowed values as a Literal (editors complete them),
// a quantity a number in SI units or text with a unit.
std::string python_type(const SceneKey& k) {
  switch (k.kind) {
    case ValueKind::number:
      return "float";
    case ValueKind::integer:
      return "int";
    case ValueKind::name: {
      std::string names;
      for (const std::string& n : k.names) names += (names.empty() ? "" : ", ") + ("\"" + n + "\"");
      return names.empty() ? "str" : "Literal[" + names + "]";
    }
    case ValueKind::text:
      return "str";
    case ValueKind::modes:
      return "Mapping[int, float]";
    case ValueKind::boolean:
      return "bool";
    case ValueKind::quantity:
      return "float | str";
  }
  return "object";
}

// The keywords beside the scene keys: the panel tables ([diagram], [fig6e], [continuation], [physical_map]) as
// dicts, and the file the scene came from (messages name it).
constexpr const char* kPanels[] = {"diagram", "fig6e", "continuation", "physical_map"};
using PanelField = std::optional<SceneTable> SceneFile::*;
PanelField panel_field(const std::string& name) {
  return name == "diagram"        ? &SceneFile::diagram
         : name == "fig6e"        ? &SceneFile::fig6e
         : name == "continuation" ? &SceneFile::continuation
                                  : &SceneFile::physical_map;
}
bool is_panel(const std::string& word) {
  return std::find(std::begin(kPanels), std::end(kPanels), word) != std::end(kPanels);
}

const SceneKey* key_for_keyword(const std::string& word) {
  for (const SceneKey& k : scene_keys())
    if (k.key == word || keyword_of(k) == word) return &k;
  return nullptr;
}

std::string allowed_keywords() {
  std::string out;
  for (const SceneKey& k : scene_keys()) out += (out.empty() ? "" : ", ") + keyword_of(k);
  for (const char* p : kPanels) out += std::string(", ") + p;
  return out + ", source, set_by_keyword";
}

[[noreturn]] void type_error(const std::string& keyword, const std::string& want, const py::handle& v) {
  throw py::type_error("Scene: " + keyword + " must be " + want + ", got " + type_name(v) + " " +
                       std::string(py::repr(v)));
}

bool is_bool(const py::handle& v) { return py::isinstance<py::bool_>(v) || type_name(v) == "bool_"; }

// A number; an integer too large for a double reads as +-inf, which the library's range check refuses by name.
double number_of(const std::string& keyword, const py::handle& v) {
  if (is_bool(v) || py::isinstance<py::str>(v) || !py::hasattr(v, "__float__")) type_error(keyword, "a number", v);
  const double x = PyFloat_AsDouble(v.ptr());
  if (x == -1.0 && PyErr_Occurred()) {
    if (!PyErr_ExceptionMatches(PyExc_OverflowError)) throw py::error_already_set();
    PyErr_Clear();
    return py::int_(v.attr("__index__")()) < py::int_(0) ? -INFINITY : INFINITY;
  }
  return x;
}

// An integer beyond 64 bits: saturated, with its exact text for the message (Python's own digits).
struct Integer {
  long long value = 0;
  bool overflow = false;
  std::string text;
};
Integer integer_of(const std::string& keyword, const py::handle& v) {
  if (is_bool(v) || !py::hasattr(v, "__index__")) type_error(keyword, "an integer", v);
  const py::int_ i(v.attr("__index__")());
  int overflow = 0;
  const long long x = PyLong_AsLongLongAndOverflow(i.ptr(), &overflow);
  if (overflow == 0 && x == -1 && PyErr_Occurred()) throw py::error_already_set();
  return {overflow > 0   ? LLONG_MAX
          : overflow < 0 ? LLONG_MIN
                         : x,
          overflow != 0, i.attr("__str__")().cast<std::string>()};
}

SceneValue value_of(const SceneKey& k, const std::string& keyword, const py::handle& v) {
  switch (k.kind) {
    case ValueKind::number:
      return number_of(keyword, v);
    case ValueKind::quantity:  // SI number, or text with a unit ("3.9um")
      if (py::isinstance<py::str>(v)) return v.cast<std::string>();
      return number_of(keyword, v);
    case ValueKind::integer:
      return integer_of(keyword, v).value;
    case ValueKind::name:
    case ValueKind::text: {
      if (!py::isinstance<py::str>(v)) type_error(keyword, "a string", v);
      const std::string s = v.cast<std::string>();
      if (!k.names.empty() && std::find(k.names.begin(), k.names.end(), s) == k.names.end()) {
        std::string names;
        for (const auto& n : k.names) names += (names.empty() ? "" : ", ") + n;
        throw InvalidArgument(k.key, k.key + " = '" + s + "' is not allowed: must be one of " + names);
      }
      return s;
    }
    case ValueKind::boolean:
      if (!is_bool(v)) type_error(keyword, "True or False", v);
      return v.cast<bool>();
    case ValueKind::modes: {
      if (!py::isinstance<py::dict>(v)) type_error(keyword, "a dict {l: value} of modes l >= 3", v);
      std::map<int, double> modes;
      for (const auto& [l, x] : v.cast<py::dict>()) {
        const Integer mode = integer_of(keyword + " mode", l);
        if (mode.overflow || mode.value < INT_MIN || mode.value > INT_MAX)
          throw InvalidArgument(k.key, k.key + " mode l = " + mode.text + " is out of range: must be a mode l >= 3");
        modes[int(mode.value)] = number_of(keyword + "[" + std::string(py::str(l)) + "]", x);
      }
      return modes;
    }
  }
  throw std::logic_error("value_of: unknown kind");
}

py::object python_value(const SceneValue& v) {
  return std::visit([](const auto& x) -> py::object { return py::cast(x); }, v);
}

// A key's value as Python shows it: None for a key whose default is a choice and that was not given, and for a
// physical quantity not given (NaN inside).
py::object value_or_none(const SceneFile& f, const SceneKey& k) {
  if (default_is_a_choice(k) && f.origin(k.path()) == Origin::default_value) return py::none();
  const SceneValue v = k.get(f);
  if (k.kind == ValueKind::quantity && std::holds_alternative<double>(v) && std::isnan(std::get<double>(v)))
    return py::none();
  return python_value(v);
}

// ---- panel tables: SceneTable <-> dict of scalars, lists and dicts ----

py::object item_python(const SceneTable::Item& i) {
  return std::visit([](const auto& x) -> py::object { return py::cast(x); }, i);
}

py::dict table_python(const SceneTable& t) {
  py::dict out;
  for (const auto& [key, v] : t.values()) {
    if (v.shape == SceneTable::Value::Shape::scalar) {
      out[py::str(key)] = item_python(v.items.at(0));
    } else if (v.shape == SceneTable::Value::Shape::array) {
      py::list l;
      for (const auto& i : v.items) l.append(item_python(i));
      out[py::str(key)] = l;
    } else {
      py::dict d;
      for (std::size_t n = 0; n < v.items.size(); ++n) d[py::str(v.keys[n])] = item_python(v.items[n]);
      out[py::str(key)] = d;
    }
  }
  return out;
}

SceneTable::Item item_of(const std::string& path, const py::handle& v) {
  if (is_bool(v)) return v.cast<bool>();
  if (py::isinstance<py::str>(v)) return v.cast<std::string>();
  if (py::hasattr(v, "__index__")) {
    const Integer i = integer_of(path, v);
    if (i.overflow) throw InvalidArgument(path, path + " = " + i.text + " is out of range: must be a 64-bit integer");
    return i.value;
  }
  if (py::hasattr(v, "__float__")) return number_of(path, v);
  type_error(path, "a number, a string, True or False", v);
}

// A panel table from its dict (a scene file's [name] table): its keys are the module's to check when it runs it,
// as a scene file's are.
SceneTable table_of(const std::string& name, const py::handle& v) {
  if (!py::isinstance<py::dict>(v)) type_error(name, "a dict of the [" + name + "] table's keys (docs/scenes.md)", v);
  SceneTable t(name);
  for (const auto& [key, x] : v.cast<py::dict>()) {
    if (!py::isinstance<py::str>(key)) type_error(name + " key", "a string", key);
    const std::string path = t.path(key.cast<std::string>());
    SceneTable::Value value;
    if (py::isinstance<py::dict>(x)) {
      value.shape = SceneTable::Value::Shape::table;
      for (const auto& [k, item] : x.cast<py::dict>()) {
        value.keys.push_back(py::str(k));
        value.items.push_back(item_of(path + "." + std::string(py::str(k)), item));
      }
    } else if (py::isinstance<py::list>(x) || py::isinstance<py::tuple>(x)) {
      value.shape = SceneTable::Value::Shape::array;
      for (const py::handle item : x) value.items.push_back(item_of(path, item));
    } else {
      value.items.push_back(item_of(path, x));
    }
    t.set(key.cast<std::string>(), std::move(value));
  }
  return t;
}

void set_panel(SceneFile& file, const std::string& name, const py::handle& value) {
  for (auto it = file.origins.begin(); it != file.origins.end();)
    it = it->first.rfind(name + ".", 0) == 0 ? file.origins.erase(it) : std::next(it);
  auto& panel = file.*panel_field(name);
  if (value.is_none()) {
    panel.reset();
    return;
  }
  panel = table_of(name, value);
  for (const auto& [key, v] : panel->values()) file.origins[panel->path(key)] = Origin::flag;
}

// One keyword's value on the file. None resets a key whose default is a choice (L, beta) or a physical quantity
// to "not given"; an integer beyond 64 bits is refused with the library's range and the value as given.
void set_key(SceneFile& file, const SceneKey& k, const std::string& word, const py::handle& value) {
  if (value.is_none() && (default_is_a_choice(k) || k.kind == ValueKind::quantity)) {
    k.set(file, k.kind == ValueKind::quantity ? SceneValue{std::nan("")} : k.get(SceneFile{}));
    file.origins.erase(k.path());
    return;
  }
  if (k.kind != ValueKind::integer) return apply_flag(file, k, value_of(k, word, value));
  const Integer i = integer_of(word, value);
  if (!i.overflow) return apply_flag(file, k, i.value);
  std::string message = k.key + " = " + i.text + " is out of range: must be a 64-bit integer";
  try {
    apply_flag(file, k, i.value);  // its saturation: the library's refusal states the range
  } catch (const InvalidArgument& e) {
    const std::string m = e.what();
    if (const auto at = m.find(" is out of range"); at != std::string::npos)
      message = k.key + " = " + i.text + m.substr(at);
  }
  throw InvalidArgument(k.key, message);
}

// Applies keyword values on top of `file`, then validates. Messages name the keyword, in Python's words.
SceneFile with_keywords(SceneFile file, const py::kwargs& kwargs) {
  std::vector<std::pair<const SceneKey*, std::string>> given;
  std::optional<std::set<std::string>> by_keyword;
  for (const auto& [name, value] : kwargs) {
    const std::string word = name.cast<std::string>();
    if (word == "set_by_keyword") {
      if (!py::isinstance<py::list>(value) && !py::isinstance<py::tuple>(value))
        type_error(word, "a list of key paths ('run.L')", value);
      by_keyword.emplace();
      for (const py::handle path : value) {
        if (!py::isinstance<py::str>(path)) type_error(word, "a list of key paths ('run.L')", path);
        by_keyword->insert(path.cast<std::string>());
      }
      continue;
    }
    if (word == "source") {
      if (!value.is_none() && !py::isinstance<py::str>(value)) type_error(word, "a string (a file name)", value);
      file.source = value.is_none() ? "" : value.cast<std::string>();
      continue;
    }
    try {
      if (is_panel(word)) {
        set_panel(file, word, value);
        continue;
      }
      const SceneKey* k = key_for_keyword(word);
      if (!k) throw py::type_error("Scene: unexpected keyword '" + word + "': must be one of " + allowed_keywords());
      given.emplace_back(k, word);
      set_key(file, *k, word, value);
    } catch (const InvalidArgument& e) {
      throw py::value_error(python_words(e.what()) + " (keyword " + word + ")");
    }
  }
  // A file scene's to_dict(): its values came from the file, but for those a keyword set after (the L_reason of
  // a result says which: "given by the scene file's run.L" or by the keyword).
  if (by_keyword && !file.source.empty())
    for (const auto& [k, word] : given)
      if (file.origin(k->path()) == Origin::flag && !by_keyword->count(k->path()))
        file.origins[k->path()] = Origin::file;
  try {
    resolve_physical(file);
    file.scene.validate();
    file.options.validate();
  } catch (const InvalidArgument& e) {
    std::string from;
    const std::string message = python_words(e.what());
    for (const auto& [k, word] : given)
      if (message.find(k->key) != std::string::npos) from += (from.empty() ? "" : ", ") + word;
    throw py::value_error(message + (from.empty() ? "" : " (keyword " + from + ")"));
  }
  return file;
}

SceneFile from_dict(const py::handle& d) {
  if (!py::isinstance<py::dict>(d)) type_error("Scene.from_dict", "a dict (Scene.to_dict())", d);
  return with_keywords(SceneFile{}, py::kwargs(py::reinterpret_borrow<py::dict>(d)));
}

// Every keyword's value: the scene keys (those a physical scene derives left out: its physical keys give them),
// the panel tables (None when absent), the source file ('' without one) and, for a file scene, the keys a keyword
// set after it was read (set_by_keyword). Scene.from_dict(d) rebuilds it.
py::dict to_dict(const SceneFile& f) {
  py::dict out;
  for (const SceneKey& k : scene_keys()) {
    if (derived_from_physical(f, k)) continue;
    // A quantity a bare number would not give back (implausible in SI, given with a unit): its text with the SI
    // unit, so from_dict reads it as itself.
    const SceneValue v = k.get(f);
    if (k.kind == ValueKind::quantity && needs_unit_text(k.key, std::get<double>(v)))
      out[py::str(k.key)] = with_si_unit(k.key, std::get<double>(v));
    else
      out[py::str(k.key)] = value_or_none(f, k);
  }
  for (const char* p : kPanels) {
    const auto& panel = f.*panel_field(p);
    out[py::str(p)] = panel ? py::object(table_python(*panel)) : py::object(py::none());
  }
  out["source"] = f.source;
  py::list by_keyword;  // a file scene's keys set by a keyword after it was read (their origin shows in results)
  for (const SceneKey& k : scene_keys())
    if (!f.source.empty() && f.origin(k.path()) == Origin::flag && !derived_from_physical(f, k))
      by_keyword.append(k.path());
  out["set_by_keyword"] = by_keyword;
  return out;
}

// to_dict as nested tuples: a canonical, hashable form (the dicts' orders are fixed: key table, std::map).
py::object frozen(const py::handle& v) {
  if (py::isinstance<py::dict>(v)) {
    py::list items;
    for (const auto& [k, x] : v.cast<py::dict>()) items.append(py::make_tuple(k, frozen(x)));
    return py::tuple(items);
  }
  if (py::isinstance<py::list>(v)) {
    py::list items;
    for (const py::handle x : v) items.append(frozen(x));
    return py::tuple(items);
  }
  return py::reinterpret_borrow<py::object>(v);
}

// rbcstab.Scene(...) with the main parameters, then every other keyword that differs from the default scene's:
// eval(repr(s)) == s.
std::string repr(const SceneFile& f) {
  static const std::set<std::string> always{"lambda", "Delta", "Delta0", "B", "C", "beta", "delta", "L", "T"};
  const py::dict d = to_dict(f);
  const py::dict defaults = to_dict(SceneFile{});
  std::string out;
  for (const auto& [key, value] : d) {
    const std::string k = key.cast<std::string>();
    const bool file_marks = k == "set_by_keyword" && !f.source.empty();  // eval needs them to mark file values
    if (!always.count(k) && !file_marks && defaults.contains(key) && value.equal(defaults[key])) continue;
    out += (out.empty() ? "" : ", ") + keyword_of(k) + "=" + std::string(py::repr(value));
  }
  return "rbcstab.Scene(" + out + ")";
}

// How messages name the scene: its name when it has its own, else its file, else "the scene".
std::string label(const SceneFile& f) {
  if (f.scene.name != SceneFile{}.scene.name) return "scene '" + f.scene.name + "'";
  if (!f.source.empty()) return "the scene of " + f.source;
  return "the scene";
}

SceneFile from_toml(const py::object& path) {
  const std::string p = py::str(py::module_::import("os").attr("fsdecode")(path));
  std::error_code ec;
  if (!std::filesystem::exists(p, ec)) {
    PyErr_SetObject(PyExc_FileNotFoundError, py::make_tuple(ENOENT, std::strerror(ENOENT), p).ptr());
    throw py::error_already_set();
  }
  return load_scene(p);
}

}  // namespace

const SceneFile& scene_file(const py::handle& scene) {
  if (!py::isinstance<SceneFile>(scene)) throw py::type_error("scene must be a rbcstab.Scene, got " + type_name(scene));
  return scene.cast<const SceneFile&>();
}

void bind_scene(py::module_& m) {
  py::class_<SceneFile> cls(m, "Scene",
                            R"(A scene: the paper's parameters, the run and the integrator, one keyword per scene key.

Every key of a scene file (docs/scenes.md) is a keyword; ``lambda_`` (or ``**{"lambda": x}``) is lambda.
Defaults are the paper's Fig. 3 out-of-plane case. ``L=None`` (the default) lets each computation choose the
truncation and report why (``L_reason`` in every result); ``beta=None`` (the default) runs at 0.001 and lets a
continuation take its kind's own (0; orbits pi/2). ``diagram``, ``fig6e``, ``continuation``, ``physical_map``: a
scene file's panel tables as dicts (None: none); ``source``: the file it came from (messages name it). Values are
checked as the CLI checks its flags: ValueError names the keyword, its value and the allowed range; a value of
the wrong type is a TypeError. Scenes are immutable and hashable: ``replace(**changes)`` returns a new one;
``to_dict()``, ``repr()``, ``==`` and ``hash()`` show everything a result depends on, and ``copy``, ``pickle`` and
``Scene.from_dict(s.to_dict())`` give a scene that behaves as ``s``.)");
  cls.def(py::init([](const py::kwargs& kwargs) { return with_keywords(SceneFile{}, kwargs); }));
  cls.def_static("from_toml", &from_toml, py::arg("path"),
                 "Reads a scene file (TOML, docs/scenes.md; path: str or os.PathLike). A missing file raises\n"
                 "FileNotFoundError; a syntax error ValueError naming file:line:column; a bad value ValueError naming\n"
                 "the key, its value and the allowed range.");
  cls.def_static(
      "from_toml_text", [](const std::string& text, const std::string& name) { return parse_scene(text, name); },
      py::arg("text"), py::arg("source") = "scene", "Parses scene-file text.");
  cls.def_static("from_dict", &from_dict, py::arg("d"), "The scene of a to_dict() (Scene(**d)).");
  cls.def(
      "replace", [](const SceneFile& f, const py::kwargs& kwargs) { return with_keywords(f, kwargs); },
      "A copy with the given keywords changed (the same keywords as Scene()).");
  cls.def("to_dict", &to_dict,
          "Every keyword's value (keys a physical scene derives left out; L, beta: None when not given; panel\n"
          "tables: None when absent; source: '' without a file; set_by_keyword: a file scene's keys a keyword set\n"
          "after it was read); Scene.from_dict(d) and Scene(**d) rebuild it.");
  cls.def(
      "to_toml", [](const SceneFile& f) { return to_toml(f); }, "The scene as scene-file text.");
  cls.def(
      "origin", [](const SceneFile& f, const std::string& key) { return to_string(f.origin(key)); }, py::arg("key"),
      "Where a key's value came from: 'default', 'file' or 'flag' (a keyword), e.g. origin('parameters.B');\n"
      "a copy or pickle keeps it, from_dict marks every value a keyword's.");
  cls.def_property_readonly(
      "source", [](const SceneFile& f) { return f.source; }, "the scene file's name, '' without one");
  cls.def_property_readonly(
      "label", &label, "how messages name the scene: scene 'name' (its own name), the scene of FILE, or the scene");
  for (const char* p : kPanels) {
    const std::string name = p;
    cls.def_property_readonly(
        p,
        [name](const SceneFile& f) -> py::object {
          const auto& panel = f.*panel_field(name);
          return panel ? py::object(table_python(*panel)) : py::object(py::none());
        },
        ("the scene file's [" + name + "] table as a dict, None without one").c_str());
  }
  for (const SceneKey& k : scene_keys()) {
    const SceneKey* key = &k;
    cls.def_property_readonly(
        keyword_of(k).c_str(), [key](const SceneFile& f) { return value_or_none(f, *key); }, key->help.c_str());
  }
  for (const SceneParameter q : composite_parameters()) {
    const ParameterRow& row = parameter_row(q);
    // As the stored parameters' keys say it (io's scene_keys): the unit (or dimensionless) and the domain.
    const std::string doc = std::string(row.description) +
                            (*row.unit ? std::string(" [") + row.unit + "]" : " (dimensionless)") + ", " +
                            parameter_domain(q, Parameters{}).text(false);
    cls.def_property_readonly(
        row.name, [q](const SceneFile& f) { return get_parameter(f.scene, q); }, doc.c_str());
  }
  cls.def("__repr__", &repr);
  cls.def("__eq__", [](const SceneFile& a, const py::object& b) -> py::object {
    if (!py::isinstance<SceneFile>(b)) return py::reinterpret_borrow<py::object>(Py_NotImplemented);
    return py::bool_(to_dict(a).equal(to_dict(b.cast<const SceneFile&>())));
  });
  cls.def("__hash__", [](const SceneFile& f) { return py::hash(frozen(to_dict(f))); });
  // A copy or pickle keeps where each value came from (origin()) and the file's text beside to_dict().
  cls.def(py::pickle(
      [](const SceneFile& f) {
        py::dict origins;
        for (const auto& [key, o] : f.origins) origins[py::str(key)] = to_string(o);
        return py::make_tuple(to_dict(f), origins, f.text);
      },
      [](const py::tuple& t) {
        SceneFile f = from_dict(t[0]);
        f.origins.clear();
        for (const auto& [key, o] : t[1].cast<py::dict>())
          f.origins[key.cast<std::string>()] = o.cast<std::string>() == "file" ? Origin::file : Origin::flag;
        f.text = t[2].cast<std::string>();
        return f;
      }));
  cls.def_static(
      "_keywords",
      [] {
        py::list out;
        for (const auto& [key, value] : to_dict(SceneFile{}))
          out.append(py::make_tuple(keyword_of(py::str(key)), value));
        return out;
      },
      "(keyword, default) of every keyword, in to_dict() order: the signature of Scene().");

  m.def(
      "scene_keys",
      [] {
        py::list out;
        const SceneFile defaults;
        for (const SceneKey& k : scene_keys()) {
          py::dict d;
          d["key"] = k.key;
          d["keyword"] = keyword_of(k);
          d["table"] = k.table;
          d["path"] = k.path();
          d["flag"] = k.flag;
          d["help"] = k.help;
          d["names"] = k.names;
          d["default"] = value_or_none(defaults, k);
          d["type"] = python_type(k);
          out.append(d);
        }
        return out;
      },
      "Every scene key: keyword, TOML path, CLI flag, help (meaning and range), allowed names, default, and the\n"
      "Python type it takes as an annotation (the stubs' source: python/tools/stubs.py).");

  m.def(
      "parameter_table",
      [] {
        py::list out;
        const Parameters defaults;
        for (const ParameterRow& r : parameter_table()) {
          py::dict d;
          d["name"] = r.name;
          d["keyword"] = keyword_of(r.name);  // as Scene(...) takes it
          d["symbol"] = r.symbol;
          d["label"] = tex_symbol(r.name);
          d["unicode"] = r.unicode;
          d["unit"] = r.unit;
          d["description"] = r.description;
          d["table"] = r.table ? py::object(py::str(r.table)) : py::object(py::none());
          d["scale"] = to_string(r.scale);
          d["moves"] = to_string(moved_parameter(r.id));
          d["definition"] = r.definition ? py::object(py::str(r.definition)) : py::object(py::none());
          d["domain"] = parameter_domain(r.id, defaults).text(false);
          py::list levels;
          for (ModelLevel l : {ModelLevel::reduced, ModelLevel::modal, ModelLevel::full})
            if (r.levels & level_bit(l)) levels.append(to_string(l));
          d["levels"] = levels;
          d["continuation"] = r.continuation;
          d["axis"] = r.axis;
          d["formula"] = r.physical.formula ? py::object(py::str(r.physical.formula)) : py::object(py::none());
          d["reference"] = r.physical.reference ? py::object(py::str(r.physical.reference)) : py::object(py::none());
          out.append(d);
        }
        return out;
      },
      "Every parameter, one dict per row of the library's parameter table: name, Scene keyword, TeX symbol and\n"
      "figure label, Unicode symbol, unit, description, scene-file table (None: derived), axis scale, the stored\n"
      "parameter it moves, definition of a composite, domain, model levels it moves, whether it can be a\n"
      "continuation parameter or a diagram axis, and its formula from physical inputs (docs/units.md).");
}

}  // namespace rbcstab::python
