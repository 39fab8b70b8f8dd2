#pragma once
// What made an output and from what, stamped on every page the report and the paper write (and in their JSON):
// the version, the git revision of the build, the date, the exact command line of the process and a hash of the
// scene text it ran.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace rbcstab::detail {

struct Provenance {
  std::string version;     // "0.1.0"
  std::string revision;    // `git describe --always --dirty` when the build was configured; "unknown" outside git
  std::string date;        // UTC, ISO 8601, when the output was made
  std::string command;     // the process's command line, each word shell-quoted where needed
  std::string scene_hash;  // 16 hex digits (FNV-1a 64) of the scenes' text, and what it hashes
};

// The build's version and revision (generated at configure time: build_revision.cpp.in).
const char* build_version();
const char* build_revision();

// The command line from /proc/self/cmdline, words quoted for a POSIX shell where they need it; "unknown" if it
// cannot be read.
std::string process_command_line();
// A word as a POSIX shell reads it back: as it is when it holds only safe characters, else in single quotes.
std::string shell_quoted(const std::string& word);

// Now, for the scene texts given (one scene: its to_toml; several: each, in the order given) and what they are.
Provenance make_provenance(const std::vector<std::string>& scene_texts, const std::string& scenes_are);

nlohmann::json provenance_json(const Provenance& p);
Provenance provenance_from_json(const nlohmann::json& j);  // what provenance_json wrote
// One paragraph (HTML, escaped) and one Markdown line naming each field.
std::string provenance_html(const Provenance& p);
std::string provenance_markdown(const Provenance& p);

}  // namespace rbcstab::detail
