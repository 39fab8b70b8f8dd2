#pragma once
// The one output facility: every file rbcstab writes goes through write_file_atomic / write_files_atomic.
// What a path may be and what happens to it:
//   "-"                     the content goes to standard output;
//   a FIFO, a char device   opened for writing and written through, never replaced (a full device is an
//                           OutputError);
//   a symbolic link         followed: its final target is treated as below, the link itself is kept;
//   a regular file, or none replaced atomically: written to a hidden temporary sibling, fsync'd, renamed;
//   a directory, a block device, a socket, a missing or unwritable parent folder: refused, nothing written.
// Every failure is an OutputError (the CLI's exit 3) naming the flag and the path.
// Temporary siblings are named ".NAME.tmp-PID-XXXXXX"; a write removes those of processes that no longer
// exist (a process killed by SIGKILL cannot remove its own).
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace rbcstab {

// An output could not be written (bad path, disk full, device full, I/O error): the CLI's exit 3.
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct OutputFile {
  std::string path;
  std::string content;
  std::string flag;  // the flag (or key) that named the path, for messages; "" reads as "output"
};

// Writes one output (see above). On failure throws OutputError; nothing partial and no temporary file is left.
void write_file_atomic(const std::string& path, const std::string& content, const std::string& flag = "");

// Writes several outputs as a set: every target is checked first, every regular file is fully written
// and fsync'd to its temporary sibling, the write-through targets are written, and only then are the
// temporaries renamed into place one after another. A failure before the renames leaves every target
// untouched and removes every temporary.
void write_files_atomic(const std::vector<OutputFile>& files);

// Why `path` cannot be an output prefix (PREFIX.csv, PREFIX.json, ...), or "": an empty one would write hidden files
// named only by their suffix (".csv"), and one that names a device, FIFO or socket would put its files beside it
// ("--out /dev/null" would create /dev/null.csv, not discard the output).
std::string output_prefix_problem(const std::string& path);

// Throws OutputError unless path can be a regular file that is read back and appended to
// (a journal): not "-", a FIFO, a device, a directory, or a path in a missing or unwritable folder.
void require_file_output(const std::string& path, const std::string& flag);

// The hidden sibling name ".NAME<tag>PID-" that staging files and folders of this process start with.
std::string staging_prefix(const std::string& target_name, const std::string& tag);
// Removes (recursively) the entries of folder whose names are staging_prefix(target_name, tag) of a
// process that no longer exists: the leftovers of killed runs.
void remove_stale_staging(const std::string& folder, const std::string& target_name, const std::string& tag);

// Input files are bounded so that a device or a runaway file cannot hang a run or exhaust memory.
constexpr std::size_t kMaxSceneBytes = std::size_t(1) << 20;     // a scene file: 1 MiB
constexpr std::size_t kMaxDataFileBytes = std::size_t(1) << 30;  // a diagram, journal or branch file: 1 GiB
// The whole of a regular file or a pipe (process substitution) of at most max_bytes. Throws
// InvalidArgument(parameter, "<parameter> = '<path>' ...") if it is missing, unreadable, a directory or a device,
// or longer than the bound (reading stops at the bound: /dev/zero through a pipe ends too).
std::string read_file(const std::string& path, const std::string& parameter = "file",
                      std::size_t max_bytes = kMaxDataFileBytes);

}  // namespace rbcstab
