// rbcstab units: physical values to the paper's dimensionless numbers and back (model/physical.hpp), each number
// with its formula and equation. The physical flags are the scene's [physical] keys, read as a scene reads them.
#include <iostream>
#include <map>
#include <memory>

#include "commands.hpp"
#include "rbcstab/io/scene_file.hpp"
#include "rbcstab/io/units_io.hpp"
#include "rbcstab/model/parameter_table.hpp"
#include "scene_options.hpp"

namespace rbcstab::cli {

namespace {
struct UnitsOptions {
  std::map<std::string, std::string> physical;  // by scene key path, as given
  std::map<std::string, CLI::Option*> physical_options;
  UnitsQuery query;  // the dimensionless inputs (the cell is read from `physical` when run)
  bool json = false;
};

int run(const UnitsOptions& o) {
  SceneFile f;
  for (const SceneKey& k : scene_keys())  // scene_keys order: the temperature before a value in kBT
    if (k.kind == ValueKind::quantity && o.physical_options.at(k.path())->count() > 0)
      apply_unit_flag(f, k, o.physical.at(k.path()));
  UnitsQuery q = o.query;
  if (f.scene.physical) q.cell = *f.scene.physical;
  const UnitsAnswer a = convert_units(q);
  if (o.json)
    std::cout << units_json(a).dump(2) << "\n";
  else
    std::cout << units_text(a);
  return kOk;
}

Runner add_units(CLI::App& app) {
  auto o = std::make_shared<UnitsOptions>();
  for (const SceneKey& k : scene_keys())
    if (k.kind == ValueKind::quantity)
      o->physical_options[k.path()] = app.add_option(k.unit_flag, o->physical[k.path()], k.help)->type_name("QUANTITY");
  const std::string fix = " (dimensionless; completes the physical value it fixes: see docs/units.md)";
  for (const ParameterRow& r : parameter_table())
    if (r.physical.input)
      app.add_option(std::string("--") + r.name, o->query.*r.physical.input,
                     std::string(r.description) + ": gives " + r.physical.completes + fix);
  app.add_flag("--json", o->json, "print one JSON object on stdout");
  return [o] { return run(*o); };
}

const RegisterCommand kRegisterUnits{
    "units",
    "Physical units (shear rate, viscosities, moduli, size) to the paper's dimensionless "
    "numbers and back",
    add_units, 95};
}  // namespace

}  // namespace rbcstab::cli
