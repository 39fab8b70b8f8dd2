#include "rbcstab/report/detail/provenance.hpp"

#include <cctype>
#include <chrono>
#include <ctime>
#include <fstream>

#include "rbcstab/report/detail/report_pages.hpp"
#include "rbcstab/sweep/point_record.hpp"

namespace rbcstab::detail {

std::string shell_quoted(const std::string& word) {
  const std::string safe = "@%+=:,./-_";
  bool plain = !word.empty();
  for (char c : word)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || safe.find(c) != std::string::npos)) plain = false;
  if (plain) return word;
  std::string out = "'";
  for (char c : word) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string process_command_line() {
  std::ifstream in("/proc/self/cmdline", std::ios::binary);  // the words, each ended by '\0'
  std::string out, word;
  while (std::getline(in, word, '\0')) out += (out.empty() ? "" : " ") + shell_quoted(word);
  return out.empty() ? "unknown" : out;
}

Provenance make_provenance(const std::vector<std::string>& scene_texts, const std::string& scenes_are) {
  Provenance p;
  p.version = build_version();
  p.revision = build_revision();
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm utc{};
  gmtime_r(&now, &utc);
  char date[32];
  std::strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%SZ", &utc);
  p.date = date;
  p.command = process_command_line();
  std::string all;  // one scene: its text as written (scene.toml); several: joined by a blank line
  for (std::size_t k = 0; k < scene_texts.size(); ++k) all += (k ? "\n\n" : "") + scene_texts[k];
  p.scene_hash = fnv1a_hex(all) + " (" + scenes_are + ")";
  return p;
}

nlohmann::json provenance_json(const Provenance& p) {
  return {{"version", p.version},
          {"revision", p.revision},
          {"date", p.date},
          {"command", p.command},
          {"scene_hash", p.scene_hash}};
}

Provenance provenance_from_json(const nlohmann::json& j) {
  return {j.at("version"), j.at("revision"), j.at("date"), j.at("command"), j.at("scene_hash")};
}

std::string provenance_html(const Provenance& p) {
  return "<p class=\"provenance\"><small>Made by rbcstab " + html_escape(p.version) + " (git " +
         html_escape(p.revision) + ") on " + html_escape(p.date) + " with <code>" + html_escape(p.command) +
         "</code>; scene hash " + html_escape(p.scene_hash) + ".</small></p>\n";
}

std::string provenance_markdown(const Provenance& p) {
  return "Made by rbcstab " + p.version + " (git " + p.revision + ") on " + p.date + " with `" + p.command +
         "`; scene hash " + p.scene_hash + ".\n";
}

}  // namespace rbcstab::detail
