#pragma once
// Append-only checkpoint journal of finished grid points (one point_to_line per point).
// Every line goes to the kernel with one write() as soon as its point is done, so a process killed
// by any signal loses nothing; fdatasync at most every sync_interval seconds bounds what a power
// cut could lose. A torn last line (a crash inside write) is cut off when the journal is reopened.
#include <map>
#include <string>

#include "rbcstab/sweep/diagram.hpp"

namespace rbcstab::detail {

class Journal {
 public:
  // Opens or creates path; a journal of another configuration throws InvalidArgument("journal").
  Journal(const std::string& path, const std::string& config_hash, const DiagramSpec& spec, double sync_interval);
  ~Journal();
  Journal(const Journal&) = delete;
  Journal& operator=(const Journal&) = delete;

  const std::map<std::size_t, PointResult>& finished() const { return finished_; }
  void append(const PointResult& p);  // not thread-safe: callers serialise
  void sync();

 private:
  std::string path_, hash_;
  int fd_ = -1;
  double sync_interval_;
  double last_sync_ = 0;
  std::map<std::size_t, PointResult> finished_;
};

}  // namespace rbcstab::detail
