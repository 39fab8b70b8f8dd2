#include "rbcstab/io/files.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>

#include "rbcstab/core/error.hpp"

namespace rbcstab {

namespace fs = std::filesystem;

namespace {

constexpr const char* kTmpTag = ".tmp-";

enum class Kind { standard_output, write_through, replace };

struct Target {
  std::string flag;   // as the user knows it ("output" when none was given)
  std::string shown;  // the path as given
  fs::path path;      // the file actually written (the final target of a link)
  Kind kind = Kind::replace;
  bool exists = false;
  mode_t mode = 0;
};

std::string quoted(const Target& t) {
  std::string s = "'" + t.shown + "'";
  if (t.path.string() != t.shown) s += " (a link to '" + t.path.string() + "')";
  return s;
}

// A path that cannot be an output is found only when the output is due (after the computation), so it
// is an OutputError like a failed write (exit 3), never an input error.
[[noreturn]] void failed(const Target& t, const std::string& why) {
  throw OutputError(t.flag + ": cannot write " + quoted(t) + ": " + why);
}

std::string folder_of(const fs::path& p) { return p.has_parent_path() ? p.parent_path().string() : "."; }

// Classifies an output path, following symbolic links to their final target; throws OutputError for a
// path that cannot be an output.
Target resolve(const std::string& path, const std::string& flag) {
  Target t;
  t.flag = flag.empty() ? "output" : flag;
  t.shown = path;
  t.path = path;
  if (path.empty()) failed(t, "the path is empty");
  if (path == "-") {
    t.kind = Kind::standard_output;
    return t;
  }
  struct stat st {};
  for (int hops = 0;; ++hops) {
    if (::lstat(t.path.c_str(), &st) != 0) {
      if (errno != ENOENT) failed(t, std::strerror(errno));
      break;
    }
    t.exists = true;
    if (!S_ISLNK(st.st_mode)) break;
    if (hops == 40) failed(t, "too many levels of symbolic links");
    std::error_code ec;
    const fs::path link = fs::read_symlink(t.path, ec);
    if (ec) failed(t, ec.message());
    t.path = link.is_absolute() ? link : t.path.parent_path() / link;
    t.exists = false;
  }
  if (t.exists) {
    t.mode = st.st_mode;
    if (S_ISDIR(st.st_mode)) failed(t, "it is a directory");
    if (S_ISFIFO(st.st_mode) || S_ISCHR(st.st_mode)) {
      t.kind = Kind::write_through;
      return t;
    }
    if (!S_ISREG(st.st_mode)) failed(t, "it is a block device or a socket");
  }
  const std::string folder = folder_of(t.path);
  struct stat dir {};
  if (::stat(folder.c_str(), &dir) != 0) failed(t, "the folder '" + folder + "' does not exist");
  if (!S_ISDIR(dir.st_mode)) failed(t, "'" + folder + "' is not a folder");
  if (::access(folder.c_str(), W_OK | X_OK) != 0) failed(t, "the folder '" + folder + "' is not writable");
  return t;
}

void write_all(int fd, const std::string& content, const Target& t) {
  const char* p = content.data();
  std::size_t left = content.size();
  while (left > 0) {
    const ssize_t w = ::write(fd, p, left);
    if (w < 0) {
      if (errno == EINTR) continue;
      failed(t, std::strerror(errno));
    }
    p += w;
    left -= std::size_t(w);
  }
}

// Writes content to a fresh hidden sibling of the target, fsync'd; returns its path.
std::string stage(const Target& t, const std::string& content) {
  const fs::path folder = folder_of(t.path);
  const std::string name = t.path.filename().string();
  remove_stale_staging(folder.string(), name, kTmpTag);
  std::random_device rd;
  for (int attempt = 0;; ++attempt) {
    std::ostringstream tmp_name;
    tmp_name << staging_prefix(name, kTmpTag) << std::hex << rd() << rd();
    const std::string tmp = (folder / tmp_name.str()).string();
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0) {
      if (errno == EEXIST && attempt < 8) continue;
      if (errno == EACCES || errno == EPERM || errno == EROFS)
        failed(t, "the folder '" + folder.string() + "' is not writable");
      failed(t, std::strerror(errno));
    }
    try {
      if (t.exists) (void)::fchmod(fd, t.mode & 07777);  // a replaced file keeps its permissions
      write_all(fd, content, t);
      if (::fsync(fd) != 0) failed(t, std::strerror(errno));
    } catch (...) {
      ::close(fd);
      ::unlink(tmp.c_str());
      throw;
    }
    if (::close(fd) != 0) {
      const int e = errno;
      ::unlink(tmp.c_str());
      failed(t, std::strerror(e));
    }
    return tmp;
  }
}

void write_through(const Target& t, const std::string& content) {
  if (t.kind == Kind::standard_output) {
    std::cout.flush();  // keep the order of what the program printed before
    std::fflush(stdout);
    write_all(STDOUT_FILENO, content, t);
    return;
  }
  // No O_CREAT, no O_TRUNC: the FIFO or device stays what it is. A FIFO blocks here until a reader opens it.
  const int fd = ::open(t.path.c_str(), O_WRONLY | O_CLOEXEC | O_NOCTTY);
  if (fd < 0) failed(t, std::strerror(errno));
  try {
    write_all(fd, content, t);
  } catch (...) {
    ::close(fd);
    throw;
  }
  if (::close(fd) != 0) failed(t, std::strerror(errno));
}

// The temporaries of a set not yet renamed; removed if the set fails.
struct Staged {
  std::vector<std::string> tmp;
  ~Staged() {
    for (const std::string& p : tmp)
      if (!p.empty()) ::unlink(p.c_str());
  }
};

void sync_folder(const std::string& folder) {
  const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  (void)::fsync(fd);  // makes the renames durable; a folder that cannot be synced still has them
  ::close(fd);
}

}  // namespace

std::string staging_prefix(const std::string& target_name, const std::string& tag) {
  return "." + target_name + tag + std::to_string(::getpid()) + "-";
}

void remove_stale_staging(const std::string& folder, const std::string& target_name, const std::string& tag) {
  const std::string head = "." + target_name + tag;
  std::error_code ec;
  for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.compare(0, head.size(), head) != 0) continue;
    const std::size_t dash = name.find('-', head.size());
    if (dash == std::string::npos || dash == head.size()) continue;
    const std::string digits = name.substr(head.size(), dash - head.size());
    if (digits.find_first_not_of("0123456789") != std::string::npos || digits.size() > 9) continue;
    const pid_t pid = pid_t(std::stol(digits));
    if (pid == ::getpid() || ::kill(pid, 0) == 0 || errno != ESRCH) continue;
    std::error_code rm;
    fs::remove_all(it->path(), rm);
  }
}

void require_file_output(const std::string& path, const std::string& flag) {
  const Target t = resolve(path, flag);
  if (t.kind != Kind::replace) failed(t, "it must be a regular file (it is read back and appended to)");
}

void write_files_atomic(const std::vector<OutputFile>& files) {
  std::vector<Target> targets;
  for (const OutputFile& f : files) targets.push_back(resolve(f.path, f.flag));
  Staged staged;
  staged.tmp.resize(files.size());
  for (std::size_t i = 0; i < files.size(); ++i)
    if (targets[i].kind == Kind::replace) staged.tmp[i] = stage(targets[i], files[i].content);
  for (std::size_t i = 0; i < files.size(); ++i)
    if (targets[i].kind != Kind::replace) write_through(targets[i], files[i].content);
  for (std::size_t i = 0; i < files.size(); ++i) {
    if (targets[i].kind != Kind::replace) continue;
    if (::rename(staged.tmp[i].c_str(), targets[i].path.c_str()) != 0) failed(targets[i], std::strerror(errno));
    staged.tmp[i].clear();
    sync_folder(folder_of(targets[i].path));
  }
}

void write_file_atomic(const std::string& path, const std::string& content, const std::string& flag) {
  write_files_atomic({OutputFile{path, content, flag}});
}

std::string read_file(const std::string& path, const std::string& parameter, std::size_t max_bytes) {
  const std::string named = parameter + " = '" + path + "'";
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0)
    throw InvalidArgument(parameter, named + ": cannot read: " + std::strerror(errno));
  if (!S_ISREG(st.st_mode) && !S_ISFIFO(st.st_mode))
    throw InvalidArgument(parameter, named + " is " + (S_ISDIR(st.st_mode) ? "a directory" : "a device or socket") +
                                         ": must be a regular file or a pipe");
  const std::string bound = std::to_string(max_bytes) + " bytes";
  if (S_ISREG(st.st_mode) && std::uintmax_t(st.st_size) > max_bytes)
    throw InvalidArgument(parameter, named + " has " + std::to_string(st.st_size) + " bytes: must be at most " + bound);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InvalidArgument(parameter, named + ": cannot read: no such file or not readable");
  std::string text;
  char chunk[1 << 16];
  while (text.size() <= max_bytes && in.read(chunk, sizeof chunk).gcount() > 0)
    text.append(chunk, std::size_t(in.gcount()));
  if (text.size() > max_bytes)
    throw InvalidArgument(parameter, named + " holds more than " + bound + ": must be at most " + bound);
  return text;
}

std::string output_prefix_problem(const std::string& path) {
  if (path.empty()) return "'' is empty: must be a file name or prefix";
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode) && !S_ISDIR(st.st_mode))
    return "'" + path + "' is a device, FIFO or socket, and this flag takes a prefix (its files would be '" + path +
           ".<suffix>'): give a file name prefix";
  return "";
}

}  // namespace rbcstab
