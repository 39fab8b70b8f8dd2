// Mode pair lists (io/scene_file.hpp parse_modes: --delta-l 3=1e-3,4=2e-3, --rest-delta-l). The input's lines
// are the flag's occurrences. An accepted list must
//   - give one mode per piece: as many modes as comma-separated pieces, each piece "l=v" read back by strtol and
//     strtod to the same l and the same v (nothing dropped, merged, or read from a prefix of the text);
//   - round-trip: the modes written "l=v" (shortest round-trip digits) parse back to the same modes;
//   - once set on a scene that validates, hold modes l in [3, L] with finite values in range.
#include <cerrno>
#include <cstdlib>

#include "fuzz_check.hpp"
#include "rbcstab/io/scene_file.hpp"
#include "rbcstab/sweep/point_record.hpp"

using namespace rbcstab;
using namespace rbcstab::fuzz;

namespace {
// A piece read by the C library, whole: l before the first '=', v after it.
bool read_piece(const std::string& piece, long& l, double& v) {
  const std::size_t eq = piece.find('=');
  if (eq == std::string::npos) return false;
  const std::string ls = piece.substr(0, eq), vs = piece.substr(eq + 1);
  char* end = nullptr;
  errno = 0;
  l = std::strtol(ls.c_str(), &end, 10);
  if (errno || end == ls.c_str() || *end) return false;
  v = std::strtod(vs.c_str(), &end);
  return end != vs.c_str() && !*end && vs.find('\0') == std::string::npos && ls.find('\0') == std::string::npos;
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size > 4096) return 0;
  const std::vector<std::string> items = split(text_of(data, size), '\n');
  const std::string flag = "--delta-l";
  std::map<int, double> modes;
  if (!accepted([&] { modes = parse_modes(items, flag); })) return 0;

  std::size_t pieces = 0;
  for (const std::string& item : items)
    for (const std::string& piece : split(item, ',')) {
      ++pieces;
      long l = 0;
      double v = 0;
      expect(read_piece(piece, l, v), "parse_modes accepted the piece '" + piece + "', which is not l=value");
      const auto it = modes.find(int(l));
      expect(long(int(l)) == l && it != modes.end() && same(it->second, v),
             "parse_modes read the piece '" + piece + "' as something else");
    }
  expect(pieces == modes.size(),
         "parse_modes gives " + std::to_string(modes.size()) + " modes for " + std::to_string(pieces) + " pieces");

  std::string written;
  for (const auto& [l, v] : modes) {
    if (!written.empty()) written += ',';
    written.append(std::to_string(l)).append("=").append(exact(v));
  }
  std::map<int, double> back;
  expect(accepted([&] { back = parse_modes({written}, flag); }), "the modes written as '" + written + "' are refused");
  expect(back.size() == modes.size(), "'" + written + "' parses back to another number of modes");
  for (const auto& [l, v] : modes)
    expect(back.count(l) && same(back.at(l), v), "'" + written + "' does not round-trip");

  for (const SceneKey* k : scene_flags()) {
    if (k->kind != ValueKind::modes) continue;
    SceneFile file;
    apply_flag(file, *k, modes);
    if (!accepted([&] { validate_scene_file(file); })) continue;
    for (const auto& [l, v] : modes)
      expect(l >= 3 && l <= file.scene.L && std::isfinite(v) && v >= 0,
             k->flag + ": a scene with mode " + std::to_string(l) + " = " + exact(v) + " validates");
  }
  return 0;
}
