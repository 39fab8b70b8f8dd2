#include "rbcstab/io/record_journal.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <ctime>
#include <fstream>
#include <set>
#include <stdexcept>

#include "rbcstab/core/error.hpp"
#include "rbcstab/io/files.hpp"

namespace rbcstab {

std::string exact(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

std::string fnv1a_hex(std::string_view text) {
  std::uint64_t h = 14695981039346656037ull;  // the FNV-1a 64 offset basis
  for (unsigned char c : text) {
    h ^= c;
    h *= 1099511628211ull;
  }
  char buf[16];
  static const char* hex = "0123456789abcdef";
  for (int k = 15; k >= 0; --k, h >>= 4) buf[k] = hex[h & 15];
  return std::string(buf, 16);
}

namespace {
constexpr std::string_view kChecksumMark = " *";
constexpr std::size_t kChecksumDigits = 16;

double journal_now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
std::string lock_path(const std::string& path) { return path + ".lock"; }

void journal_write_all(int fd, const std::string& text, const std::string& path) {
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

std::string journal_read_all(int fd, const std::string& path) {
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

std::string seal_record(const std::string& body) { return body + std::string(kChecksumMark) + fnv1a_hex(body) + '\n'; }

UnsealedRecord unseal_record(const std::string& line) {
  std::string text = line;
  if (text.empty() || text.back() != '\n') return {std::nullopt, "incomplete record (no end of line)"};
  text.pop_back();
  const std::size_t tail = kChecksumMark.size() + kChecksumDigits;
  if (text.size() < tail || text.compare(text.size() - tail, kChecksumMark.size(), kChecksumMark) != 0)
    return {std::nullopt, "no checksum at the end of the record"};
  std::string body = text.substr(0, text.size() - tail);
  const std::string sum = text.substr(text.size() - kChecksumDigits);
  if (fnv1a_hex(body) != sum)
    return {std::nullopt, "checksum " + sum + " does not match the record (it was edited or corrupted)"};
  return {std::move(body), {}};
}

RecordJournal::RecordJournal(const std::string& path, const std::string& config_hash, const JournalFormat& format,
                             const std::function<RecordKey(const std::string& line)>& check, double sync_interval)
    : path_(path), hash_(config_hash), format_(format), sync_interval_(sync_interval) {
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
                                         ": wait for it to finish or choose another " + format_.choose);
  }
  try {
    { std::ofstream(lock_path(path), std::ios::trunc) << holder_text() << "\n"; }
    load(check);
  } catch (...) {
    ::unlink(lock_path(path_).c_str());
    ::close(fd_);
    throw;
  }
  last_sync_ = journal_now();
}

void RecordJournal::load(const std::function<RecordKey(const std::string&)>& check) {
  const std::string content = journal_read_all(fd_, path_);
  const std::string h = format_.magic + format_.version + " " + hash_ + "\n";
  std::string kept = h;  // the header and every accepted record, byte for byte
  bool rewrite = content.empty();
  if (!content.empty() && content.compare(0, h.size(), h) != 0) {
    const auto eol = content.find('\n');
    if (eol == std::string::npos && h.compare(0, content.size(), content) == 0) {
      rewrite = true;  // torn header: start again
    } else {
      const std::string first = content.substr(0, eol);
      std::string why = "belongs to another configuration";
      for (const auto& [version, lacks] : format_.older)
        if (first.rfind(format_.magic + version + " ", 0) == 0)
          why = "has the older format " + version + " (" + lacks + ")";
      throw InvalidArgument("journal", "journal '" + path_ + "' " + why + " (its first line is '" + first +
                                           "', this run needs '" + h.substr(0, h.size() - 1) +
                                           "'): remove it or choose another " + format_.choose);
    }
  } else if (!content.empty()) {
    std::map<std::size_t, std::size_t> line_of;  // key -> line of its accepted record
    std::set<std::size_t> duplicated;
    std::size_t pos = h.size(), line_no = 1;
    const std::string dropped = "; dropped, the " + format_.item + " is recomputed";
    while (pos < content.size()) {
      ++line_no;
      const auto eol = content.find('\n', pos);
      const std::string line = content.substr(pos, eol == std::string::npos ? std::string::npos : eol + 1 - pos);
      pos = eol == std::string::npos ? content.size() : eol + 1;
      const std::string where = path_ + ":" + std::to_string(line_no) + ": ";
      if (eol == std::string::npos) {
        rejected_.push_back(where + "torn last record (a crash during a write)" + dropped);
        continue;
      }
      const RecordKey r = check(line);
      if (!r.key) {
        rejected_.push_back(where + r.error + dropped);
        continue;
      }
      const std::size_t key = *r.key;
      if (duplicated.count(key) || line_of.count(key)) {
        rejected_.push_back(where + format_.key + " " + std::to_string(key) + " is recorded again" +
                            (line_of.count(key) ? " (first at line " + std::to_string(line_of[key]) + ")" : "") +
                            "; both dropped, the " + format_.item + " is recomputed");
        duplicated.insert(key);
        records_.erase(key);
        line_of.erase(key);
        continue;
      }
      line_of[key] = line_no;
      records_.emplace(key, line);
    }
    rewrite = !rejected_.empty();
    if (rewrite)
      for (const auto& [key, line] : records_) kept += line;
  }
  if (rewrite) {
    // Under the lock nobody else writes: cut the file and write back only what was accepted.
    if (::ftruncate(fd_, 0) != 0)
      throw std::runtime_error("cannot rewrite journal '" + path_ + "': " + std::strerror(errno));
    journal_write_all(fd_, kept, path_);
  }
  ::fdatasync(fd_);
}

RecordJournal::~RecordJournal() {
  if (fd_ >= 0) {
    ::fdatasync(fd_);
    ::unlink(lock_path(path_).c_str());
    ::close(fd_);
  }
}

void RecordJournal::append(std::size_t key, const std::string& line) {
  journal_write_all(fd_, line, path_);
  records_.emplace(key, line);
  if (journal_now() - last_sync_ >= sync_interval_) sync();
}

void RecordJournal::sync() {
  ::fdatasync(fd_);
  last_sync_ = journal_now();
}

}  // namespace rbcstab
