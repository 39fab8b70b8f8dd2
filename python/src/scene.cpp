// rbcstab.Scene: a scene file's content (io/scene_file.hpp) built from keywords, one per scene key. The keys,
// their kinds, defaults and ranges come from io's scene_keys(), so the CLI's flags, the TOML keys and these
// keywords cannot drift apart.
#include <pybind11/stl.h>

#include <cmath>
#include <sstream>

#include "bindings.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/model/parameter_table.hpp"
#include "rbcstab/report/bifurcation_plot.hpp"

namespace rbcstab::python {

namespace {

// The keyword of a key: its name, with a trailing underscore where the name is a Python keyword.
// A scene key's Python keyword: the key itself, but lambda_ for lambda (a Python reserved word).
std::string keyword_of(const std::string& key) { return key == "lambda" ? "lambda_" : key; }
std::string keyword_of(const SceneKey& k) { return keyword_of(k.key); }

const SceneKey* key_for_keyword(const std::string& word) {
  for (const SceneKey& k : scene_keys())
    if (k.key == word || keyword_of(k) == word) return &k;
  return nullptr;
}

std::string allowed_keywords() {
  std::string out;
  for (const SceneKey& k : scene_keys()) out += (out.empty() ? "" : ", ") + keyword_of(k);
  return out;
}

[[noreturn]] void type_error(const std::string& keyword, const std::string& want, const py::handle& v) {
  throw py::type_error("Scene: " + keyword + " must be " + want + ", got " + type_name(v) + " " +
                       std::string(py::repr(v)));
}

bool is_bool(const py::handle& v) { return py::isinstance<py::bool_>(v) || type_name(v) == "bool_"; }

double number_of(const std::string& keyword, const py::handle& v) {
  if (is_bool(v) || py::isinstance<py::str>(v) || !py::hasattr(v, "__float__")) type_error(keyword, "a number", v);
  return v.cast<double>();
}

long long integer_of(const std::string& keyword, const py::handle& v) {
  if (is_bool(v) || !py::hasattr(v, "__index__")) type_error(keyword, "an integer", v);
  return py::int_(v.attr("__index__")()).cast<long long>();
}

SceneValue value_of(const SceneKey& k, const std::string& keyword, const py::handle& v) {
  switch (k.kind) {
    case ValueKind::number:
      return number_of(keyword, v);
    case ValueKind::quantity:  // SI number, or text with a unit ("3.9um")
      if (py::isinstance<py::str>(v)) return v.cast<std::string>();
      return number_of(keyword, v);
    case ValueKind::integer:
      return integer_of(keyword, v);
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
      for (const auto& [l, x] : v.cast<py::dict>())
        modes[int(integer_of(keyword + " mode", l))] = number_of(keyword + "[" + std::string(py::str(l)) + "]", x);
      return modes;
    }
  }
  throw std::logic_error("value_of: unknown kind");
}

py::object python_value(const SceneValue& v) {
  return std::visit([](const auto& x) -> py::object { return py::cast(x); }, v);
}

// Applies keyword values on top of `file`, then validates; L = None restores the automatic truncation.
SceneFile with_keywords(SceneFile file, const py::kwargs& kwargs) {
  std::vector<std::pair<const SceneKey*, std::string>> given;
  for (const auto& [name, value] : kwargs) {
    const std::string word = name.cast<std::string>();
    const SceneKey* k = key_for_keyword(word);
    if (!k) throw py::type_error("Scene: unexpected keyword '" + word + "': must be one of " + allowed_keywords());
    given.emplace_back(k, word);
    if (k->path() == "run.L" && value.is_none()) {
      file.scene.L = SceneFile{}.scene.L;
      file.origins.erase("run.L");
      continue;
    }
    try {
      apply_flag(file, *k, value_of(*k, word, value));
    } catch (const InvalidArgument& e) {
      throw py::value_error(std::string(e.what()) + " (keyword " + word + ")");
    }
  }
  try {
    resolve_physical(file);
    file.scene.validate();
    file.options.validate();
  } catch (const InvalidArgument& e) {
    std::string from;
    const std::string message = e.what();
    for (const auto& [k, word] : given)
      if (message.find(k->key) != std::string::npos) from += (from.empty() ? "" : ", ") + word;
    throw py::value_error(message + (from.empty() ? "" : " (keyword " + from + ")"));
  }
  return file;
}

py::dict to_dict(const SceneFile& f) {
  py::dict out;
  for (const SceneKey& k : scene_keys()) {
    if (derived_from_physical(f, k)) continue;  // Scene(**d) derives it again from the physical keys
    if (k.path() == "run.L" && f.origin("run.L") == Origin::default_value)
      out[py::str(k.key)] = py::none();
    else
      out[py::str(k.key)] = python_value(k.get(f));
  }
  return out;
}

std::string short_number(double x) {
  std::ostringstream s;
  s << x;
  return s.str();
}

std::string repr(const SceneFile& f) {
  const Scene& s = f.scene;
  const Parameters& p = s.parameters;
  std::ostringstream out;
  out << "Scene('" << s.name << "': lambda=" << short_number(p.lambda) << ", Delta=" << short_number(p.Delta)
      << ", Delta0=" << short_number(p.Delta0) << ", B=" << short_number(p.B) << ", C=" << short_number(p.C)
      << ", beta=" << short_number(s.beta) << ", delta=" << short_number(s.delta)
      << ", L=" << (f.origin("run.L") == Origin::default_value ? std::string("auto") : std::to_string(s.L))
      << ", T=" << short_number(s.T) << ")";
  return out.str();
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
truncation and report why (``L_reason`` in every result). Values are checked as the CLI checks its flags:
ValueError names the parameter, its value and the allowed range; a value of the wrong type is a TypeError.
Scenes are immutable: ``replace(**changes)`` returns a new one.)");
  cls.def(py::init([](const py::kwargs& kwargs) { return with_keywords(SceneFile{}, kwargs); }));
  cls.def_static(
      "from_toml", [](const std::string& path) { return load_scene(path); }, py::arg("path"),
      "Reads a scene file (TOML, docs/scenes.md); errors name the key, its value and the allowed range.");
  cls.def_static(
      "from_toml_text", [](const std::string& text, const std::string& name) { return parse_scene(text, name); },
      py::arg("text"), py::arg("source") = "scene", "Parses scene-file text.");
  cls.def(
      "replace", [](const SceneFile& f, const py::kwargs& kwargs) { return with_keywords(f, kwargs); },
      "A copy with the given keywords changed (the same keywords as Scene()).");
  cls.def("to_dict", &to_dict, "Every scene key and its value (L: None when automatic); Scene(**d) rebuilds it.");
  cls.def(
      "to_toml", [](const SceneFile& f) { return to_toml(f); }, "The scene as scene-file text.");
  cls.def(
      "origin", [](const SceneFile& f, const std::string& key) { return to_string(f.origin(key)); }, py::arg("key"),
      "Where a key's value came from: 'default', 'file' or 'flag' (a keyword), e.g. origin('parameters.B').");
  cls.def_property_readonly(
      "source", [](const SceneFile& f) { return f.source; }, "the scene file's name, '' without one");
  for (const SceneKey& k : scene_keys()) {
    const SceneKey* key = &k;
    cls.def_property_readonly(
        keyword_of(k).c_str(),
        [key](const SceneFile& f) -> py::object {
          if (key->path() == "run.L" && f.origin("run.L") == Origin::default_value) return py::none();
          return python_value(key->get(f));
        },
        key->help.c_str());
  }
  for (const SceneParameter q : composite_parameters()) {
    const ParameterRow& row = parameter_row(q);
    cls.def_property_readonly(
        row.name, [q](const SceneFile& f) { return get_parameter(f.scene, q); }, row.description);
  }
  cls.def("__repr__", &repr);
  cls.def("__eq__", [](const SceneFile& a, const py::object& b) {
    return py::isinstance<SceneFile>(b) && to_toml(a) == to_toml(b.cast<const SceneFile&>()) &&
           a.origin("run.L") == b.cast<const SceneFile&>().origin("run.L");
  });
  cls.attr("__hash__") = py::none();
  cls.def(py::pickle([](const SceneFile& f) { return to_dict(f); },
                     [](const py::dict& d) { return with_keywords(SceneFile{}, py::kwargs(d)); }));

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
          d["default"] = python_value(k.get(defaults));
          out.append(d);
        }
        return out;
      },
      "Every scene key: keyword, TOML path, CLI flag, help (meaning and range), allowed names, default.");

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
