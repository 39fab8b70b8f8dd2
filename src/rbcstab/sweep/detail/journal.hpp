#pragma once
// The phase diagram's checkpoint journal: one point_to_line record per finished grid point in a RecordJournal
// (io/record_journal.hpp: the header with the configuration hash, the lock, the checks on opening). A record is
// accepted when its checksum, hash, index and values are valid (parse_point_line); a torn, corrupt, foreign or
// duplicated record is reported, removed from the file and the point recomputed.
#include <map>
#include <string>
#include <vector>

#include "rbcstab/io/record_journal.hpp"
#include "rbcstab/sweep/diagram.hpp"

namespace rbcstab::detail {

class Journal {
 public:
  // Opens or creates path for the modes l = 2..L. Throws InvalidArgument("journal") for a journal
  // of another configuration or format, or one locked by another process.
  Journal(const std::string& path, const std::string& config_hash, const DiagramSpec& spec, int L,
          double sync_interval);

  const std::map<std::size_t, PointResult>& finished() const { return finished_; }
  // "path:line: why" for every record dropped on opening.
  const std::vector<std::string>& rejected() const { return records_.rejected(); }
  void append(const PointResult& p);  // not thread-safe: callers serialise
  void sync() { records_.sync(); }

 private:
  std::string hash_;
  std::map<std::size_t, PointResult> parsed_;  // every valid record read, duplicates included
  RecordJournal records_;
  std::map<std::size_t, PointResult> finished_;
};

}  // namespace rbcstab::detail
