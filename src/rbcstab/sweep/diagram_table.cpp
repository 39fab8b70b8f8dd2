#include "rbcstab/sweep/diagram_table.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <tuple>

#include "rbcstab/core/error.hpp"
#include "rbcstab/core/text.hpp"

namespace rbcstab {

DiagramSpec diagram_spec(const SceneFile& scene) {
  DiagramSpec s;
  if (!scene.diagram) return s;
  const SceneTable& t = *scene.diagram;
  t.allow_only({"axes", "x_range", "y_range", "counts", "classifier", "alpha"});
  if (t.has("axes")) {
    const auto names = t.texts("axes", 2, "an array of two axis names, e.g. [\"lnB\", \"lnC\"]");
    s.x.axis = axis_from_string(names[0]);
    s.y.axis = axis_from_string(names[1]);
  }
  for (auto [key, axis] : {std::pair{"x_range", &s.x}, std::pair{"y_range", &s.y}}) {
    if (!t.has(key)) continue;
    const auto range = t.numbers(key, 2, "an array of two numbers");
    axis->min = range[0];
    axis->max = range[1];
  }
  if (t.has("counts")) {
    const auto n = t.integers("counts", 2, "an array of two integers");
    for (long long c : n) require(c >= 1 && c <= 1'000'000, "diagram.counts", double(c), "integers in [1, 1000000]");
    s.x.count = int(n[0]);
    s.y.count = int(n[1]);
  }
  if (t.has("classifier")) s.classifier = classifier_from_string(t.text("classifier"));
  if (t.has("alpha")) s.alpha = t.number("alpha");
  s.validate();
  return s;
}

namespace {
// A field of two values: min, max (or nx, ny); the message shows what was given.
template <class T>
void require_pair(const std::vector<T>& v, const std::string& field, const std::string& what) {
  if (v.size() == 2) return;
  std::ostringstream given;
  given << std::setprecision(17);
  for (std::size_t k = 0; k < v.size(); ++k) given << (k ? ", " : "") << v[k];
  throw InvalidArgument(field, field + " takes " + what + ", got " + std::to_string(v.size()) +
                                   (v.size() == 1 ? " value" : " values") + " (" + given.str() + ")");
}
}  // namespace

DiagramSpec plane_spec(const SceneFile& scene, const PlaneChoice& c) {
  DiagramSpec spec = diagram_spec(scene);
  if (!c.axes.empty()) {
    require_pair(c.axes, "axes", "two axis names x,y (e.g. lnB,lnC)");
    spec.x.axis = axis_from_string(c.axes[0]);
    spec.y.axis = axis_from_string(c.axes[1]);
  }
  for (auto [field, range, axis] :
       {std::tuple{"x_range", &c.x_range, &spec.x}, std::tuple{"y_range", &c.y_range, &spec.y}}) {
    if (range->empty()) continue;
    require_pair(*range, field, "two numbers min,max");
    for (double v : *range) require(std::isfinite(v), field, v, "finite");
    axis->min = (*range)[0];
    axis->max = (*range)[1];
  }
  if (!c.counts.empty()) {
    require_pair(c.counts, "counts", "two integers nx,ny");
    for (long long n : c.counts) require(n >= 1 && n <= 1'000'000, "counts", double(n), "integers in [1, 1000000]");
    spec.x.count = int(c.counts[0]);
    spec.y.count = int(c.counts[1]);
  }
  if (!c.classifier.empty()) spec.classifier = classifier_from_string(c.classifier);
  if (c.alpha_fixed) {
    require(std::isfinite(*c.alpha_fixed) && *c.alpha_fixed >= 0, "alpha_fixed", *c.alpha_fixed,
            "finite and >= 0 (0: off)");
    spec.alpha = *c.alpha_fixed;
  }
  spec.validate();
  return spec;
}

std::vector<long long> parse_counts(const std::vector<std::string>& texts, const std::string& name) {
  std::vector<long long> out;
  std::string given;
  bool ok = true;
  for (std::string text : texts) {
    given += (given.empty() ? "" : " ") + text;
    std::replace(text.begin(), text.end(), 'x', ',');
    for (const std::string& item : comma_items(text)) {
      const std::optional<long long> v = read_integer(item);
      ok = ok && v && *v >= 1 && *v <= 1'000'000;
      out.push_back(v.value_or(0));
    }
  }
  if (!ok || out.size() != 2)
    throw InvalidArgument(name, name + " = '" + given + "' must be two integers in [1, 1000000]: nx,ny or NxM");
  return out;
}

}  // namespace rbcstab
