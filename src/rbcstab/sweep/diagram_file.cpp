#include "rbcstab/sweep/diagram_file.hpp"

#include <set>
#include <sstream>
#include <toml++/toml.h>

#include "rbcstab/core/error.hpp"
#include "rbcstab/io/detail/scene_toml.hpp"

namespace rbcstab {

namespace {

const toml::array& pair_of(const toml::table& t, const char* key) {
  const toml::array* a = t.get(key)->as_array();
  if (!a || a->size() != 2)
    throw InvalidArgument(std::string("diagram.") + key, std::string("diagram.") + key + " must be an array of two values");
  return *a;
}
}  // namespace

bool has_diagram_table(const std::string& toml_text) {
  const toml::table root = detail::parse_scene_toml(toml_text, "scene");
  return root.get("diagram") != nullptr;
}

DiagramSpec parse_diagram_table(const std::string& toml_text, const std::string& source_name) {
  const toml::table root = detail::parse_scene_toml(toml_text, source_name);
  DiagramSpec s;
  const toml::node* node = root.get("diagram");
  if (!node) return s;
  const toml::table* t = node->as_table();
  if (!t) throw InvalidArgument("diagram", "scene key 'diagram' must be a table ([diagram])");
  const std::set<std::string> allowed{"axes", "x_range", "y_range", "counts", "classifier", "alpha"};
  for (const auto& [k, v] : *t)
    if (!allowed.count(std::string(k.str())))
      throw InvalidArgument("diagram." + std::string(k.str()),
                            "unknown scene key 'diagram." + std::string(k.str()) +
                                "' (allowed here: alpha, axes, classifier, counts, x_range, y_range)");
  if (t->get("axes")) {
    const toml::array& a = pair_of(*t, "axes");
    auto name = [&](std::size_t k) {
      auto v = a[k].value_exact<std::string>();
      if (!v) throw InvalidArgument("diagram.axes", "diagram.axes must hold two axis names, e.g. [\"lnB\", \"lnC\"]");
      return axis_from_string(*v);
    };
    s.x.axis = name(0);
    s.y.axis = name(1);
  }
  for (auto [key, axis] : {std::pair{"x_range", &s.x}, std::pair{"y_range", &s.y}}) {
    if (!t->get(key)) continue;
    const toml::array& a = pair_of(*t, key);
    auto lo = a[0].value<double>(), hi = a[1].value<double>();
    if (!lo || !hi) throw InvalidArgument(std::string("diagram.") + key, std::string("diagram.") + key + " must hold two numbers");
    axis->min = *lo;
    axis->max = *hi;
  }
  if (t->get("counts")) {
    const toml::array& a = pair_of(*t, "counts");
    auto nx = a[0].value_exact<int64_t>(), ny = a[1].value_exact<int64_t>();
    if (!nx || !ny) throw InvalidArgument("diagram.counts", "diagram.counts must hold two integers");
    require(*nx >= 1 && *nx <= 1'000'000, "diagram.counts", double(*nx), "integers in [1, 1000000]");
    require(*ny >= 1 && *ny <= 1'000'000, "diagram.counts", double(*ny), "integers in [1, 1000000]");
    s.x.count = int(*nx);
    s.y.count = int(*ny);
  }
  if (const toml::node* c = t->get("classifier")) {
    auto v = c->value_exact<std::string>();
    if (!v) throw InvalidArgument("diagram.classifier", "diagram.classifier must be a string: auto, final or tail");
    s.classifier = classifier_from_string(*v);
  }
  if (const toml::node* a = t->get("alpha")) {
    auto v = a->value<double>();
    if (!v) throw InvalidArgument("diagram.alpha", "diagram.alpha must be a number");
    s.alpha = *v;
  }
  s.validate();
  return s;
}

}  // namespace rbcstab
