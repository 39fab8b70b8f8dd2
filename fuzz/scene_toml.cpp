// Scene files (io/scene_file.hpp): parse_scene on arbitrary text. An accepted file must
//   - validate (validate_scene_file): parse_scene never returns a scene the library would refuse;
//   - hold one mode per key of its mode tables (no key silently merged into another, "3" and "03");
//   - round-trip: to_toml gives TOML that parse_scene accepts and that gives back every key's value bit for
//     bit (branch files and diagram headers store scenes this way);
//   - give panel tables ([diagram], [fig6e], [continuation]) that are read or refused with InvalidArgument,
//     and a [diagram] spec that validates.
#include <toml++/toml.h>

#include "fuzz_check.hpp"
#include "rbcstab/io/files.hpp"
#include "rbcstab/io/scene_file.hpp"
#include "rbcstab/report/panels.hpp"
#include "rbcstab/sweep/diagram_table.hpp"

using namespace rbcstab;
using namespace rbcstab::fuzz;

namespace {
bool same_value(const SceneValue& a, const SceneValue& b) {
  if (a.index() != b.index()) return false;
  if (const double* x = std::get_if<double>(&a)) return same(*x, std::get<double>(b));
  if (const auto* m = std::get_if<std::map<int, double>>(&a)) {
    const auto& n = std::get<std::map<int, double>>(b);
    if (m->size() != n.size()) return false;
    for (auto i = m->begin(), j = n.begin(); i != m->end(); ++i, ++j)
      if (i->first != j->first || !same(i->second, j->second)) return false;
    return true;
  }
  return a == b;
}

// The number of keys of the inline table table.key in the file's own TOML (0 when absent).
std::size_t keys_in(const std::string& text, const SceneKey& k) {
  const toml::table root = toml::parse(text);
  const toml::table* t = root[k.table][k.key].as_table();
  return t ? t->size() : 0;
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size > kMaxSceneBytes) return 0;  // load_scene refuses a longer file before parsing it
  const std::string text = text_of(data, size);
  SceneFile file;
  if (!accepted([&] { file = parse_scene(text, "fuzz.toml"); })) return 0;

  expect(accepted([&] { validate_scene_file(file); }), "parse_scene accepted a scene that validate_scene_file refuses");
  for (const SceneKey& k : scene_keys()) {
    if (k.kind != ValueKind::modes) continue;
    const std::size_t given = keys_in(text, k), read = std::get<std::map<int, double>>(k.get(file)).size();
    expect(given == read, k.path() + " has " + std::to_string(given) + " keys but " + std::to_string(read) +
                              " modes were read: keys were merged silently");
  }

  const std::string toml = to_toml(file);
  SceneFile back;
  expect(accepted([&] { back = parse_scene(toml, "round-trip"); }), "to_toml gives text parse_scene refuses:\n" + toml);
  for (const SceneKey& k : scene_keys())
    expect(same_value(k.get(file), k.get(back)), k.path() + " changes through to_toml and parse_scene:\n" + toml);

  DiagramSpec spec;
  if (accepted([&] { spec = diagram_spec(file); })) {
    expect(accepted([&] { spec.validate(); }), "diagram_spec returned a spec that does not validate");
    expect(spec.size() >= 1 && spec.size() <= std::size_t(kMaxDiagramPoints), "diagram_spec size outside the bound");
  }
  accepted([&] { (void)panel_kind(file); });
  accepted([&] { fig6e_options(file).validate(); });
  accepted([&] { (void)continuation_panel(file); });
  return 0;
}
