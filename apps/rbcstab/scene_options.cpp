#include "scene_options.hpp"

#include "checks.hpp"
#include "rbcstab/core/error.hpp"

namespace rbcstab::cli {

namespace {
// Every flag's value is read in full and an empty one is refused, a text flag's (--name '') too.
CLI::Validator non_empty_text(const std::string& accepts) {
  return CLI::Validator(
      [accepts](std::string& text) -> std::string { return text.empty() ? "'' is empty (" + accepts + ")" : ""; }, "",
      "TEXT");
}
}  // namespace

void SceneOptions::add_to(CLI::App& app) {
  app.add_option("--scene", scene_path, "Scene file (TOML, keys in docs/scenes.md); flags below override it")
      ->check(CLI::ExistingFile);
  const SceneFile defaults;
  std::vector<const SceneKey*> keys = scene_flags();
  for (const SceneKey& k : scene_keys())
    if (!k.unit_flag.empty()) keys.push_back(&k);
  for (const SceneKey* k : keys) {
    const std::string path = k->path();
    const SceneValue d = k->get(defaults);
    CLI::Option* o = nullptr;
    switch (k->kind) {
      case ValueKind::number:
        o = app.add_option(k->flag, numbers_[path], k->help)
                ->check(number_text(k->help))
                ->default_val(std::get<double>(d));
        break;
      case ValueKind::integer:
        o = app.add_option(k->flag, integers_[path], k->help)
                ->check(integer_text(k->help))
                ->default_val(std::get<long long>(d));
        break;
      case ValueKind::name:
      case ValueKind::text:
        o = app.add_option(k->flag, names_[path], k->help)->default_val(std::get<std::string>(d));
        if (!k->names.empty()) o->check(CLI::IsMember(k->names));
        if (k->kind == ValueKind::text) o->check(non_empty_text(k->help));
        break;
      case ValueKind::modes:
        o = app.add_option(k->flag, modes_[path], k->help);
        break;
      case ValueKind::boolean:
        o = app.add_flag(k->flag, booleans_[path], k->help);
        break;
      case ValueKind::quantity:
        o = app.add_option(k->unit_flag, names_[path], k->help)->type_name("QUANTITY");
        break;
    }
    if (k->kind != ValueKind::modes && k->kind != ValueKind::boolean && k->kind != ValueKind::quantity)
      o->capture_default_str();
    flags_.push_back({k, o});
  }
  full_horizon_option_ =
      app.add_flag("--full-horizon", full_horizon_,
                   "integrate every run to T: no certified early termination (scene key run.full_horizon)");
}

SceneFile SceneOptions::read() const {
  SceneFile f = read_unchecked();
  validate_scene_file(f);
  return f;
}

SceneFile SceneOptions::read_unchecked() const {
  SceneFile f;
  if (!scene_path.empty()) f = load_scene(scene_path);
  for (const Flag& flag : flags_) {
    if (flag.option->count() == 0) continue;
    const std::string path = flag.key->path();
    switch (flag.key->kind) {
      case ValueKind::number:
        apply_flag(f, *flag.key, numbers_.at(path));
        break;
      case ValueKind::integer:
        apply_flag(f, *flag.key, integers_.at(path));
        break;
      case ValueKind::name:
      case ValueKind::text:
        apply_flag(f, *flag.key, names_.at(path));
        break;
      case ValueKind::modes:
        apply_flag(f, *flag.key, parse_modes(modes_.at(path), flag.key->flag));
        break;
      case ValueKind::boolean:
        apply_flag(f, *flag.key, booleans_.at(path));
        break;
      case ValueKind::quantity:
        apply_unit_flag(f, *flag.key, names_.at(path));
        break;
    }
  }
  if (full_horizon_option_ && full_horizon_option_->count() > 0)
    for (const SceneKey& k : scene_keys())
      if (k.path() == "run.full_horizon") apply_flag(f, k, true);
  resolve_physical(f);
  return f;
}

std::vector<std::string> SceneOptions::given_flags() const {
  std::vector<std::string> given;
  for (const Flag& f : flags_)
    if (f.option->count() > 0) given.push_back(f.option->get_name());
  return given;
}

SceneFile SceneOptions::resolve(TruncationUse use) const {
  SceneFile f = read_unchecked();  // apply_scene_truncation checks it
  apply_scene_truncation(f, use);
  return f;
}

void add_shear_rate_range(CLI::App& app, std::string& text) {
  const ShearRateSearchOptions defaults;
  app.add_option("--shear-rate-range", text,
                 "LO,HI: the shear rates [1/s] searched for the thresholds of a physical scene (units as for "
                 "--shear-rate; default " +
                     format_value(defaults.min_rate) + "," + format_value(defaults.max_rate) + ")");
}

}  // namespace rbcstab::cli
