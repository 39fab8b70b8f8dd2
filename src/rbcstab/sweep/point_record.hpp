#pragma once
// One grid point as one text record (journal lines, MPI messages): every finite double in its
// shortest round-trip form, so a point read back is bit-identical to the one written.
#include <climits>
#include <optional>
#include <string>
#include <string_view>

#include "rbcstab/io/record_journal.hpp"  // exact, fnv1a_hex, seal_record
#include "rbcstab/sweep/diagram.hpp"

namespace rbcstab {

// "P <hash> <index> <verdict> <l_Delta> <growth> <oscillating> <sigma_final> <status> <t_reached>
//  <steps> <failed_steps> <rhs_evaluations> <seconds> <terminated_at> <margin> |<reason> *<checksum>\n": the reason is
//  free
// text up to the checksum (newlines replaced), a non-finite number is written "-" (never "nan"), and
// the checksum is seal_record's (io/record_journal.hpp), so an edited or spliced record is detected.
std::string point_to_line(const PointResult& p, const std::string& config_hash);

// The point of a record, or why the record is refused (error empty when point is set): a torn or
// malformed record, a wrong checksum, another configuration's hash, or values no run can produce
// (point_value_error with modes 2..L).
struct ParsedPoint {
  std::optional<PointResult> point;
  std::string error;
};
ParsedPoint parse_point_line(const std::string& line, const std::string& config_hash, const DiagramSpec& spec,
                             int L = INT_MAX);
// parse_point_line's point, nullopt when the record is refused.
std::optional<PointResult> point_from_line(const std::string& line, const std::string& config_hash,
                                           const DiagramSpec& spec);

// Why p cannot be a result of spec with modes l = 2..L; empty when it can: an index outside the
// grid, l_Delta outside [2, L],
// a verdict that disagrees with verdict_of(status, l_Delta), a non-finite growth or sigma_final of a
// point that was not failed, a t_reached or seconds that is not finite and >= 0.
struct FieldError {
  std::string field, why;  // the PointResult member at fault ("l_Delta") and the message
  bool empty() const { return why.empty(); }
};
FieldError point_value_error(const PointResult& p, const DiagramSpec& spec, int L);

}  // namespace rbcstab
