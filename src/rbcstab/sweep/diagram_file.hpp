#pragma once
// The [diagram] table of a scene file (read by parse_scene, interpreted here):
//   [diagram]
//   axes = ["lnB", "lnC"]        # x (fastest-varying), y: any two of the parameter table's axes (axis_names())
//   x_range = [-1.0, 6.0]        # inclusive
//   y_range = [-5.5, 2.0]
//   counts = [64, 64]
//   classifier = "final"         # auto | final | tail
//   alpha = 100                  # optional: hold alpha = B/C fixed (Fig. 5)
#include "rbcstab/io/scene_file.hpp"
#include "rbcstab/sweep/diagram.hpp"

namespace rbcstab {

// The spec from the scene's [diagram] table (defaults for absent keys; a scene without the table gives the
// default spec). Unknown keys and bad values throw InvalidArgument naming "diagram.<key>".
DiagramSpec diagram_spec(const SceneFile& scene);

}  // namespace rbcstab
