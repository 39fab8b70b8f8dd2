#pragma once
// Append-only checkpoint journals of checksummed one-line records, shared by the phase diagram (one record per grid
// point, sweep/detail/journal.hpp) and the bifurcation diagram (one record per branch). The file starts with a header
// "<magic><version> <config hash>\n" and is held under an exclusive flock for the run, so a second writer is refused
// (naming the holder from PATH.lock) instead of splicing its records into ours. Every record goes to the kernel with
// one write() as soon as it is appended, so a process killed by any signal loses nothing; fdatasync at most every
// sync_interval seconds bounds what a power cut could lose. On opening, every record is checked (its checksum, then
// the caller's check): a torn, corrupt, foreign or duplicated record is reported with file and line, removed from
// the file and recomputed; a journal of another configuration or format is refused.
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rbcstab {

// Shortest round-trip text of a double ("inf", "-inf", "nan" for non-finite values).
std::string exact(double v);

// 16 lower-case hex digits of the FNV-1a 64 hash of text.
std::string fnv1a_hex(std::string_view text);

// A record: body (no newline) + " *" + fnv1a_hex(body) + "\n", so an edited or spliced record is detected.
std::string seal_record(const std::string& body);
// The body of a sealed record, or why it is refused (error empty when body is set): no end of line (torn), no
// checksum, a checksum that does not match.
struct UnsealedRecord {
  std::optional<std::string> body;
  std::string error;
};
UnsealedRecord unseal_record(const std::string& line);

struct JournalFormat {
  std::string magic;                         // the header's start, e.g. "# rbcstab diagram journal "
  std::string version;                       // e.g. "v3"
  std::map<std::string, std::string> older;  // an older version and what it lacks: refused, naming it
  std::string key = "index";                 // what identifies a record ("index 4 is recorded again")
  std::string item = "point";                // what a dropped record costs ("the point is recomputed")
  std::string choose = "--journal";          // how to choose another journal ("--out or --journal")
};

// A record's key, or why it is refused (error empty when key is set).
struct RecordKey {
  std::optional<std::size_t> key;
  std::string error;
};

class RecordJournal {
 public:
  // Opens or creates path. check reads one whole line (its end of line included) and says its key or why it is
  // refused. Throws InvalidArgument("journal") for a journal of another configuration or format, or one locked by
  // another process; std::runtime_error when the file cannot be read or written.
  RecordJournal(const std::string& path, const std::string& config_hash, const JournalFormat& format,
                const std::function<RecordKey(const std::string& line)>& check, double sync_interval);
  ~RecordJournal();
  RecordJournal(const RecordJournal&) = delete;
  RecordJournal& operator=(const RecordJournal&) = delete;

  const std::string& path() const { return path_; }
  // The accepted records by key, each line as in the file.
  const std::map<std::size_t, std::string>& records() const { return records_; }
  // "path:line: why" for every record dropped on opening.
  const std::vector<std::string>& rejected() const { return rejected_; }
  void append(std::size_t key, const std::string& line);  // not thread-safe: callers serialise
  void sync();

 private:
  std::string path_, hash_;
  JournalFormat format_;
  int fd_ = -1;
  double sync_interval_;
  double last_sync_ = 0;
  std::map<std::size_t, std::string> records_;
  std::vector<std::string> rejected_;
  void load(const std::function<RecordKey(const std::string&)>& check);
};

}  // namespace rbcstab
