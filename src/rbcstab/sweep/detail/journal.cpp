#include "rbcstab/sweep/detail/journal.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "rbcstab/core/error.hpp"
#include "rbcstab/io/files.hpp"
#include "rbcstab/sweep/point_io.hpp"

namespace rbcstab::detail {

namespace {
double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
std::string header(const std::string& hash) { return "# rbcstab diagram journal v1 " + hash + "\n"; }

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
}  // namespace

Journal::Journal(const std::string& path, const std::string& config_hash, const DiagramSpec& spec,
                 double sync_interval)
    : path_(path), hash_(config_hash), sync_interval_(sync_interval) {
  require_file_output(path, "--journal");
  std::string content;
  {
    std::ifstream in(path, std::ios::binary);
    if (in) {
      std::ostringstream ss;
      ss << in.rdbuf();
      content = ss.str();
    }
  }
  std::size_t keep = 0;  // bytes of complete, valid lines
  if (!content.empty()) {
    const std::string h = header(hash_);
    if (content.compare(0, h.size(), h) != 0) {
      const auto eol = content.find('\n');
      if (eol == std::string::npos && h.compare(0, content.size(), content) == 0) {
        keep = 0;  // torn header: start again
      } else {
        throw InvalidArgument("journal", "journal '" + path + "' belongs to another configuration (its first line is '" +
                                             content.substr(0, eol) + "', this run needs '" +
                                             h.substr(0, h.size() - 1) +
                                             "'): remove it or choose another --journal");
      }
    } else {
      keep = h.size();
      std::size_t pos = keep;
      while (pos < content.size()) {
        const auto eol = content.find('\n', pos);
        if (eol == std::string::npos) break;  // torn last line
        const std::string line = content.substr(pos, eol + 1 - pos);
        if (auto p = point_from_line(line, hash_, spec)) finished_.emplace(p->index, *p);
        pos = eol + 1;
        keep = pos;
      }
    }
  }
  fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0) throw std::runtime_error("cannot open journal '" + path + "': " + std::strerror(errno));
  if (::ftruncate(fd_, off_t(keep)) != 0 || ::lseek(fd_, off_t(keep), SEEK_SET) < 0) {
    const std::string msg = std::strerror(errno);
    ::close(fd_);
    throw std::runtime_error("cannot prepare journal '" + path + "': " + msg);
  }
  if (keep == 0) write_all(fd_, header(hash_), path_);
  ::fdatasync(fd_);
  last_sync_ = now();
}

Journal::~Journal() {
  if (fd_ >= 0) {
    ::fdatasync(fd_);
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
