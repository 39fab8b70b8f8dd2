#pragma once
// The [diagram] table of a scene file (ignored by parse_scene, read here):
//   [diagram]
//   axes = ["lnB", "lnC"]        # x (fastest-varying), y: any two of lnB lnC lambda Delta Delta0 alpha beta
//   x_range = [-1.0, 6.0]        # inclusive
//   y_range = [-5.5, 2.0]
//   counts = [64, 64]
//   classifier = "final"         # auto | final | tail
//   alpha = 100                  # optional: hold alpha = B/C fixed (Fig. 5)
#include <string>

#include "rbcstab/sweep/diagram.hpp"

namespace rbcstab {

// The spec from the [diagram] table (defaults for absent keys; a file without the table gives the
// default spec). Unknown keys and bad values throw InvalidArgument naming "diagram.<key>".
DiagramSpec parse_diagram_table(const std::string& toml_text, const std::string& source_name = "scene");
bool has_diagram_table(const std::string& toml_text);

}  // namespace rbcstab
