#include "rbcstab/sweep/diagram_file.hpp"

#include "rbcstab/core/error.hpp"

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

}  // namespace rbcstab
