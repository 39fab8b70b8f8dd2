#pragma once
// Append-only checkpoint journal of finished grid points (one point_to_line record per point).
// The file is opened with O_APPEND and held under an exclusive flock for the run, so a second
// writer is refused (naming the holder from PATH.lock) instead of splicing its records into ours.
// Every record goes to the kernel with one write() as soon as its point is done, so a process
// killed by any signal loses nothing; fdatasync at most every sync_interval seconds bounds what a
// power cut could lose. On opening, every record is checked (checksum, hash, index, values): a
// torn, corrupt, foreign or duplicated record is reported, removed from the file and recomputed.
#include <map>
#include <string>
#include <vector>

#include "rbcstab/sweep/diagram.hpp"

namespace rbcstab::detail {

class Journal {
 public:
  // Opens or creates path for the modes l = 2..L. Throws InvalidArgument("journal") for a journal
  // of another configuration or format, or one locked by another process.
  Journal(const std::string& path, const std::string& config_hash, const DiagramSpec& spec, int L,
          double sync_interval);
  ~Journal();
  Journal(const Journal&) = delete;
  Journal& operator=(const Journal&) = delete;

  const std::map<std::size_t, PointResult>& finished() const { return finished_; }
  // "path:line: why" for every record dropped on opening.
  const std::vector<std::string>& rejected() const { return rejected_; }
  void append(const PointResult& p);  // not thread-safe: callers serialise
  void sync();

 private:
  std::string path_, hash_;
  int fd_ = -1;
  double sync_interval_;
  double last_sync_ = 0;
  std::map<std::size_t, PointResult> finished_;
  std::vector<std::string> rejected_;
  void load(const DiagramSpec& spec, int L);
};

}  // namespace rbcstab::detail
