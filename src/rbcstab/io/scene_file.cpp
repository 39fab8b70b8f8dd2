#include "rbcstab/io/scene_file.hpp"

#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <toml++/toml.h>

#include "rbcstab/core/error.hpp"
#include "rbcstab/io/detail/scene_toml.hpp"
#include "rbcstab/io/files.hpp"

namespace rbcstab {

namespace {
// Reads table.key as a number; absent keys keep the default.
void read_number(const toml::table& table, const std::string& prefix, const char* key, double& out) {
  const toml::node* node = table.get(key);
  if (!node) return;
  if (auto v = node->value<double>()) {
    out = *v;
    return;
  }
  throw InvalidArgument(prefix + key, prefix + key + " must be a number");
}

void read_int(const toml::table& table, const std::string& prefix, const char* key, long long& out) {
  const toml::node* node = table.get(key);
  if (!node) return;
  if (auto v = node->value_exact<int64_t>()) {
    out = *v;
    return;
  }
  throw InvalidArgument(prefix + key, prefix + key + " must be an integer");
}

void read_string(const toml::table& table, const std::string& prefix, const char* key, std::string& out) {
  const toml::node* node = table.get(key);
  if (!node) return;
  if (auto v = node->value_exact<std::string>()) {
    out = *v;
    return;
  }
  throw InvalidArgument(prefix + key, prefix + key + " must be a string");
}

void reject_unknown(const toml::table& table, const std::string& prefix, const std::set<std::string>& allowed) {
  for (const auto& [k, v] : table) {
    const std::string key(k.str());
    if (!allowed.count(key)) {
      std::string list;
      for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
      throw InvalidArgument(prefix + key, "unknown scene key '" + prefix + key + "' (allowed here: " + list + ")");
    }
  }
}

// Library validation names the bare symbol ("B", "rtol", "delta_l.3"); a scene file names its key
// ("parameters.B"), so out-of-range messages point at the line to fix.
std::string scene_key(const std::string& parameter) {
  static const std::map<std::string, std::string> table_of = {
      {"lambda", "parameters"}, {"Delta", "parameters"}, {"Delta0", "parameters"}, {"B", "parameters"},
      {"C", "parameters"},      {"beta", "initial"},     {"delta", "initial"},     {"delta_l", "initial"},
      {"rest_delta_l", "initial"}, {"L", "run"},         {"T", "run"},             {"dt", "run"},
      {"model", "run"},         {"tail_window", "run"},  {"stepper", "integrator"}, {"rtol", "integrator"},
      {"atol", "integrator"},   {"h_init", "integrator"}, {"h_min", "integrator"}, {"max_steps", "integrator"},
      {"max_seconds", "integrator"}};
  const auto it = table_of.find(parameter.substr(0, parameter.find('.')));
  return it == table_of.end() ? parameter : it->second + "." + parameter;
}

template <class F>
void with_scene_keys(F&& check) {
  try {
    check();
  } catch (const InvalidArgument& e) {
    const std::string key = scene_key(e.parameter());
    if (key == e.parameter()) throw;
    std::string message = e.what();
    message = message.rfind(e.parameter(), 0) == 0 ? key + message.substr(e.parameter().size()) : key + ": " + message;
    throw InvalidArgument(key, message);
  }
}

const toml::table* subtable(const toml::table& root, const char* name) {
  const toml::node* node = root.get(name);
  if (!node) return nullptr;
  if (const toml::table* t = node->as_table()) return t;
  throw InvalidArgument(name, std::string("scene key '") + name + "' must be a table ([" + name + "])");
}

void read_mode_map(const toml::table& table, const std::string& prefix, const char* key, std::map<int, double>& out) {
  const toml::node* node = table.get(key);
  if (!node) return;
  const toml::table* t = node->as_table();
  if (!t) throw InvalidArgument(prefix + key, prefix + key + " must be a table of mode = value, e.g. { 3 = 1e-3 }");
  for (const auto& [k, v] : *t) {
    const std::string ks(k.str());
    int l = 0;
    try {
      std::size_t pos = 0;
      l = std::stoi(ks, &pos);
      if (pos != ks.size()) throw std::invalid_argument(ks);
    } catch (const std::exception&) {
      throw InvalidArgument(prefix + key, prefix + key + " has key '" + ks + "': keys must be integer modes l >= 3");
    }
    auto value = v.value<double>();
    if (!value) throw InvalidArgument(prefix + key + "." + ks, prefix + key + "." + ks + " must be a number");
    out[l] = *value;
  }
}
}  // namespace

SceneFile parse_scene(const std::string& toml_text, const std::string& source_name) {
  const toml::table root = detail::parse_scene_toml(toml_text, source_name);
  SceneFile f;
  Scene& s = f.scene;
  // [diagram] belongs to sweeps (rbcstab/sweep/diagram_file.hpp), [fig6e] and [continuation] to figure
  // panels (rbcstab/report/panels.hpp); scenes accept and ignore them.
  reject_unknown(root, "", {"name", "parameters", "initial", "run", "integrator", "diagram", "fig6e", "continuation"});
  read_string(root, "", "name", s.name);
  if (const toml::table* t = subtable(root, "parameters")) {
    reject_unknown(*t, "parameters.", {"lambda", "Delta", "Delta0", "B", "C"});
    read_number(*t, "parameters.", "lambda", s.parameters.lambda);
    read_number(*t, "parameters.", "Delta", s.parameters.Delta);
    read_number(*t, "parameters.", "Delta0", s.parameters.Delta0);
    read_number(*t, "parameters.", "B", s.parameters.B);
    read_number(*t, "parameters.", "C", s.parameters.C);
  }
  if (const toml::table* t = subtable(root, "initial")) {
    reject_unknown(*t, "initial.", {"beta", "delta", "delta_l", "rest_delta_l"});
    read_number(*t, "initial.", "beta", s.beta);
    read_number(*t, "initial.", "delta", s.delta);
    read_mode_map(*t, "initial.", "delta_l", s.delta_l);
    read_mode_map(*t, "initial.", "rest_delta_l", s.rest_delta_l);
  }
  if (const toml::table* t = subtable(root, "run")) {
    reject_unknown(*t, "run.", {"L", "T", "dt", "model", "tail_window"});
    long long L = s.L;
    read_int(*t, "run.", "L", L);
    require(L >= 2 && L <= 100, "run.L", double(L), "an integer in [2, 100]");
    s.L = int(L);
    read_number(*t, "run.", "T", s.T);
    read_number(*t, "run.", "dt", s.dt);
    read_number(*t, "run.", "tail_window", f.options.tail_window);
    std::string model = to_string(s.model);
    read_string(*t, "run.", "model", model);
    with_scene_keys([&] { s.model = model_level_from_string(model); });
  }
  if (const toml::table* t = subtable(root, "integrator")) {
    reject_unknown(*t, "integrator.", {"stepper", "rtol", "atol", "h_init", "h_min", "max_steps", "max_seconds"});
    IntegratorOptions& o = f.options.integrator;
    std::string stepper = to_string(o.stepper);
    read_string(*t, "integrator.", "stepper", stepper);
    with_scene_keys([&] { o.stepper = stepper_from_string(stepper); });
    read_number(*t, "integrator.", "rtol", o.rtol);
    read_number(*t, "integrator.", "atol", o.atol);
    read_number(*t, "integrator.", "h_init", o.h_init);
    read_number(*t, "integrator.", "h_min", o.h_min);
    read_number(*t, "integrator.", "max_seconds", o.max_seconds);
    long long max_steps = static_cast<long long>(o.max_steps);
    read_int(*t, "integrator.", "max_steps", max_steps);
    require(max_steps > 0, "integrator.max_steps", double(max_steps), "> 0");
    o.max_steps = std::size_t(max_steps);
  }
  with_scene_keys([&] {
    s.validate();
    f.options.validate();
  });
  return f;
}

SceneFile load_scene(const std::string& path) { return parse_scene(read_file(path), path); }

bool scene_sets_L(const std::string& toml_text, const std::string& source_name) {
  try {
    const toml::table root = toml::parse(toml_text, source_name);
    const toml::table* run = root["run"].as_table();
    return run && run->contains("L");
  } catch (const toml::parse_error&) {
    return false;  // parse_scene reports the syntax error with its location
  }
}

std::string to_toml(const SceneFile& file) {
  const Scene& s = file.scene;
  auto mode_table = [](const std::map<int, double>& m) {
    toml::table t;
    for (const auto& [l, v] : m) t.insert(std::to_string(l), v);
    return t;
  };
  toml::table root{
      {"name", s.name},
      {"parameters", toml::table{{"lambda", s.parameters.lambda}, {"Delta", s.parameters.Delta},
                                 {"Delta0", s.parameters.Delta0}, {"B", s.parameters.B}, {"C", s.parameters.C}}},
      {"initial", toml::table{{"beta", s.beta}, {"delta", s.delta}, {"delta_l", mode_table(s.delta_l)},
                              {"rest_delta_l", mode_table(s.rest_delta_l)}}},
      {"run", toml::table{{"L", s.L}, {"T", s.T}, {"dt", s.dt}, {"model", to_string(s.model)},
                          {"tail_window", file.options.tail_window}}},
      {"integrator", toml::table{{"stepper", to_string(file.options.integrator.stepper)},
                                 {"rtol", file.options.integrator.rtol},
                                 {"atol", file.options.integrator.atol},
                                 {"h_init", file.options.integrator.h_init},
                                 {"h_min", file.options.integrator.h_min},
                                 {"max_steps", static_cast<int64_t>(file.options.integrator.max_steps)},
                                 {"max_seconds", file.options.integrator.max_seconds}}},
  };
  std::ostringstream ss;
  ss << root << "\n";
  return ss.str();
}

}  // namespace rbcstab
