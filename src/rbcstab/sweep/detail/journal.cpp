#include "rbcstab/sweep/detail/journal.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <ctime>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

#include "rbcstab/core/error.hpp"
#include "rbcstab/io/files.hpp"
#include "rbcstab/sweep/point_record.hpp"

namespace rbcstab::detail {

namespace {
double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }
// v2: records carry checksums; v3: and the early termination (terminated_at, margin). Older journals are
// refused rather than trusted.
constexpr const char* kMagic = "# rbcstab diagram journal ";
std::string header(const std::string& hash) { return std::string(kMagic) + "v3 " + hash + "\n"; }
std::string lock_path(const std::string& path) { return path + ".lock"; }

void write_all(int fd, const std::string& text, const std::string& path) {
  const char* p = text.data();
  std::size_t left = text.size();
  while (left > 0) {
    const ssize_t w = ::write(fd, p, left);
    if (w < 0) {
      if (errno == EINTR) continue;
      throw std::runtime_error("cannot append to journal '" + path + "': " + std::strerror(errno));
    }
    p += w;
    left -= std::size_t(w);
  }
}

std::string read_all(int fd, const std::string& path) {
  std::string content;
  char buf[1 << 16];
  for (off_t off = 0;;) {
    const ssize_t r = ::pread(fd, buf, sizeof buf, off);
    if (r < 0) {
      if (errno == EINTR) continue;
      throw std::runtime_error("cannot read journal '" + path + "': " + std::strerror(errno));
    }
    if (r == 0) return content;
    content.append(buf, std::size_t(r));
    off += r;
  }
}

// "pid 1234 on host h (started 2024-05-01 12:00:00 UTC)"
std::string holder_text() {
  char host[256] = "?";
  ::gethostname(host, sizeof host - 1);
  const std::time_t t = std::time(nullptr);
  char when[64];
  std::strftime(when, sizeof when, "%Y-%m-%d %H:%M:%S UTC", std::gmtime(&t));
  return "pid " + std::to_string(::getpid()) + " on host " + host + " (started " + when + ")";
}
}  // namespace

Journal::Journal(const std::string& path, const std::string& config_hash, const DiagramSpec& spec, int L,
                 double sync_interval)
    : path_(path), hash_(config_hash), sync_interval_(sync_interval) {
  require_file_output(path, "--journal");
  fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (fd_ < 0) throw std::runtime_error("cannot open journal '" + path + "': " + std::strerror(errno));
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const int e = errno;
    ::close(fd_);
    fd_ = -1;
    if (e != EWOULDBLOCK) throw std::runtime_error("cannot lock journal '" + path + "': " + std::strerror(e));
    std::string holder;
    std::getline(std::ifstream(lock_path(path)), holder);
    if (holder.empty()) holder = "another process";
    throw InvalidArgument("journal", "the journal '" + path + "' is being written by " + holder +
                                         ": wait for it to finish or choose another --out or --journal");
  }
  try {
    { std::ofstream(lock_path(path), std::ios::trunc) << holder_text() << "\n"; }
    load(spec, L);
  } catch (...) {
    ::unlink(lock_path(path_).c_str());
    ::close(fd_);
    throw;
  }
  last_sync_ = now();
}

void Journal::load(const DiagramSpec& spec, int L) {
  const std::string content = read_all(fd_, path_);
  const std::string h = header(hash_);
  std::string kept = h;  // the header and every accepted record, byte for byte
  bool rewrite = content.empty();
  if (!content.empty() && content.compare(0, h.size(), h) != 0) {
    const auto eol = content.find('\n');
    if (eol == std::string::npos && h.compare(0, content.size(), content) == 0) {
      rewrite = true;  // torn header: start again
    } else {
      const std::string first = content.substr(0, eol);
      const bool v1 = first.rfind(std::string(kMagic) + "v1 ", 0) == 0;
      const bool v2 = first.rfind(std::string(kMagic) + "v2 ", 0) == 0;
      throw InvalidArgument("journal", "journal '" + path_ + "' " +
                                           (v1   ? "has the older format v1 (records without checksums)"
                                            : v2 ? "has the older format v2 (records without the early termination)"
                                                 : "belongs to another configuration") +
                                           " (its first line is '" + first + "', this run needs '" +
                                           h.substr(0, h.size() - 1) + "'): remove it or choose another --journal");
    }
  } else if (!content.empty()) {
    std::map<std::size_t, std::size_t> line_of;  // index -> line of its accepted record
    std::map<std::size_t, std::string> text_of;
    std::set<std::size_t> duplicated;
    std::size_t pos = h.size(), line_no = 1;
    while (pos < content.size()) {
      ++line_no;
      const auto eol = content.find('\n', pos);
      const std::string line = content.substr(pos, eol == std::string::npos ? std::string::npos : eol + 1 - pos);
      pos = eol == std::string::npos ? content.size() : eol + 1;
      const std::string where = path_ + ":" + std::to_string(line_no) + ": ";
      ParsedPoint r = parse_point_line(line, hash_, spec, L);
      if (!r.point) {
        rejected_.push_back(where + (eol == std::string::npos ? "torn last record (a crash during a write)" : r.error) +
                            "; dropped, the point is recomputed");
        continue;
      }
      const std::size_t idx = r.point->index;
      if (duplicated.count(idx) || line_of.count(idx)) {
        rejected_.push_back(where + "index " + std::to_string(idx) + " is recorded again" +
                            (line_of.count(idx) ? " (first at line " + std::to_string(line_of[idx]) + ")" : "") +
                            "; both dropped, the point is recomputed");
        duplicated.insert(idx);
        finished_.erase(idx);
        line_of.erase(idx);
        continue;
      }
      line_of[idx] = line_no;
      text_of[idx] = line;
      finished_.emplace(idx, *r.point);
    }
    rewrite = !rejected_.empty();
    if (rewrite)
      for (const auto& [idx, line] : text_of)
        if (line_of.count(idx)) kept += line;
  }
  if (rewrite) {
    // Under the lock nobody else writes: cut the file and write back only what was accepted.
    if (::ftruncate(fd_, 0) != 0)
      throw std::runtime_error("cannot rewrite journal '" + path_ + "': " + std::strerror(errno));
    write_all(fd_, kept, path_);
  }
  ::fdatasync(fd_);
}

Journal::~Journal() {
  if (fd_ >= 0) {
    ::fdatasync(fd_);
    ::unlink(lock_path(path_).c_str());
    ::close(fd_);
  }
}

void Journal::append(const PointResult& p) {
  write_all(fd_, point_to_line(p, hash_), path_);
  finished_.emplace(p.index, p);
  if (now() - last_sync_ >= sync_interval_) sync();
}

void Journal::sync() {
  ::fdatasync(fd_);
  last_sync_ = now();
}

}  // namespace rbcstab::detail
