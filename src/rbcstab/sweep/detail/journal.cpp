#include "rbcstab/sweep/detail/journal.hpp"

#include "rbcstab/sweep/point_record.hpp"

namespace rbcstab::detail {

namespace {
// v2: records carry checksums; v3: and the early termination (terminated_at, margin). Older journals are
// refused rather than trusted.
JournalFormat point_journal_format() {
  JournalFormat f;
  f.magic = "# rbcstab diagram journal ";
  f.version = "v3";
  f.older = {{"v1", "records without checksums"}, {"v2", "records without the early termination"}};
  f.key = "index";
  f.item = "point";
  f.choose = "--out or --journal";
  return f;
}
}  // namespace

Journal::Journal(const std::string& path, const std::string& config_hash, const DiagramSpec& spec, int L,
                 double sync_interval)
    : hash_(config_hash),
      records_(
          path, config_hash, point_journal_format(),
          [&](const std::string& line) -> RecordKey {
            ParsedPoint r = parse_point_line(line, config_hash, spec, L);
            if (!r.point) return {std::nullopt, r.error};
            const std::size_t idx = r.point->index;
            parsed_.insert_or_assign(idx, std::move(*r.point));
            return {idx, {}};
          },
          sync_interval) {
  for (const auto& [idx, line] : records_.records()) finished_.emplace(idx, parsed_.at(idx));
  parsed_.clear();
}

void Journal::append(const PointResult& p) {
  records_.append(p.index, point_to_line(p, hash_));
  finished_.emplace(p.index, p);
}

}  // namespace rbcstab::detail
