#pragma once
// The --help text of the parameter plane shared by `diagram` and `trace` (the plane itself: the library's
// plane_spec, sweep/diagram_table.hpp).
#include <string>

#include "rbcstab/sweep/diagram_table.hpp"

namespace rbcstab::cli {

// --help of --axes: the parameter table's axes and the default plane.
inline std::string axes_help(const std::string& what) {
  std::string names;
  for (const std::string& n : axis_names()) names += (names.empty() ? "" : " ") + n;
  const DiagramSpec d;
  return what + " x,y from " + names + " (default: the scene's [diagram] or " + to_string(d.x.axis) + "," +
         to_string(d.y.axis) + ")";
}

}  // namespace rbcstab::cli
