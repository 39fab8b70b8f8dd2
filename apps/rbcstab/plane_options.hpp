#pragma once
// The parameter plane shared by `diagram` and `trace`: the scene's [diagram] table, then the
// --axes, --x-range, --y-range and --alpha-fixed flags. The caller adds its own fields and validates.
#include <string>
#include <vector>

#include "rbcstab/core/error.hpp"
#include "rbcstab/sweep/diagram_file.hpp"

namespace rbcstab::cli {

// --help of --axes: the parameter table's axes and the default plane.
inline std::string axes_help(const std::string& what) {
  std::string names;
  for (const std::string& n : axis_names()) names += (names.empty() ? "" : " ") + n;
  const DiagramSpec d;
  return what + " x,y from " + names + " (default: the scene's [diagram] or " + to_string(d.x.axis) + "," +
         to_string(d.y.axis) + ")";
}

inline DiagramSpec plane_spec(const SceneFile& scene, const std::vector<std::string>& axes,
                              const std::vector<double>& x_range, const std::vector<double>& y_range,
                              double alpha_fixed) {
  DiagramSpec spec = diagram_spec(scene);
  if (!axes.empty()) {
    if (axes.size() != 2) throw InvalidArgument("--axes", "--axes takes two names, e.g. lnB,lnC");
    spec.x.axis = axis_from_string(axes[0]);
    spec.y.axis = axis_from_string(axes[1]);
  }
  if (!x_range.empty()) {
    if (x_range.size() != 2) throw InvalidArgument("--x-range", "--x-range takes two numbers: min,max");
    spec.x.min = x_range[0], spec.x.max = x_range[1];
  }
  if (!y_range.empty()) {
    if (y_range.size() != 2) throw InvalidArgument("--y-range", "--y-range takes two numbers: min,max");
    spec.y.min = y_range[0], spec.y.max = y_range[1];
  }
  if (alpha_fixed >= 0) spec.alpha = alpha_fixed;
  return spec;
}

}  // namespace rbcstab::cli
