#pragma once
// The [diagram] table of a scene file (read by parse_scene, interpreted here):
//   [diagram]
//   axes = ["lnB", "lnC"]        # x (fastest-varying), y: any two of the parameter table's axes (axis_names())
//   x_range = [-1.0, 6.0]        # inclusive
//   y_range = [-5.5, 2.0]
//   counts = [64, 64]
//   classifier = "final"         # auto | final | tail
//   alpha = 100                  # optional: hold alpha = B/C fixed (Fig. 5)
#include <optional>
#include <string>
#include <vector>

#include "rbcstab/io/scene_file.hpp"
#include "rbcstab/sweep/diagram.hpp"

namespace rbcstab {

// The spec from the scene's [diagram] table (defaults for absent keys; a scene without the table gives the
// default spec). Unknown keys and bad values throw InvalidArgument naming "diagram.<key>".
DiagramSpec diagram_spec(const SceneFile& scene);

// A plane (and its grid) as a front end gives it on top of the scene's [diagram] table; an empty field keeps the
// table's value (or the default spec's). Field names are the command line's flags (--x-range: x_range).
struct PlaneChoice {
  std::vector<std::string> axes;         // two axis names: x (fastest-varying), y
  std::vector<double> x_range, y_range;  // two finite numbers each: min, max (inclusive)
  std::vector<long long> counts;         // two integers nx, ny in [1, 1000000] (a diagram's grid)
  std::string classifier;                // auto | final | tail (a diagram's l_Delta rule)
  std::optional<double> alpha_fixed;     // >= 0: hold alpha = B/C at this value over the plane (0: off)
};
// A grid's counts as a user types them (`--counts` of diagram and report): "nx,ny", "NxM" or the two as separate
// texts, each an integer in [1, 1000000]. Throws InvalidArgument(name, "<name> = '<texts>' must be two integers in
// [1, 1000000]: nx,ny or NxM"), the texts joined by a space.
std::vector<long long> parse_counts(const std::vector<std::string>& texts, const std::string& name);
// diagram_spec(scene) with the choices applied, validated; InvalidArgument names the field (axes, x_range, ...).
DiagramSpec plane_spec(const SceneFile& scene, const PlaneChoice& choice);

}  // namespace rbcstab
