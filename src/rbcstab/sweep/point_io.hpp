#pragma once
// One grid point as one text line (journal lines, MPI messages): every double in its shortest
// round-trip form, so a point read back is bit-identical to the one written.
#include <optional>
#include <string>

#include "rbcstab/sweep/diagram.hpp"

namespace rbcstab {

// "P <hash> <index> ... <reason>\n"; the reason is the rest of the line (newlines replaced).
std::string point_to_line(const PointResult& p, const std::string& config_hash);
// The point if the line is complete and well formed and carries config_hash; nullopt otherwise.
std::optional<PointResult> point_from_line(const std::string& line, const std::string& config_hash,
                                           const DiagramSpec& spec);

// Shortest round-trip text of a double ("inf", "-inf", "nan" for non-finite values).
std::string exact(double v);

}  // namespace rbcstab
