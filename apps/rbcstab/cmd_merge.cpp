// rbcstab merge: joins the shard outputs of one diagram (rbcstab diagram --shard k/n) into the
// CSV and JSON a single run would have written.
#include <iostream>
#include <memory>

#include "checks.hpp"
#include "commands.hpp"
#include "rbcstab/io/files.hpp"
#include "rbcstab/io/scene_file.hpp"
#include "rbcstab/sweep/sweep_io.hpp"

namespace rbcstab::cli {

namespace {
struct MergeOptions {
  std::vector<std::string> inputs;
  std::string out = "diagram";
  bool allow_incomplete = false;
  bool json = false;
};

int run(const MergeOptions& o) {
  std::vector<MergeInput> inputs;
  for (const auto& path : o.inputs) inputs.push_back({path, read_file(path)});
  const MergeResult m = merge_diagrams(inputs);
  if (!m.missing.empty()) {
    std::cerr << "rbcstab: merge: " << m.missing.size() << " of " << m.spec.size()
              << " points are missing (first: index " << m.missing.front() << ")\n";
    if (!o.allow_incomplete) return kRunFailed;
  }
  const DiagramOutputOptions oo{m.seconds_present};
  const std::string csv = diagram_csv(m.spec, m.points, oo);
  nlohmann::json doc = diagram_json(m.header, m.spec, m.points, {}, oo);
  if (m.missing.empty()) {
    const AgreementOptions defaults;  // named: GCC 12 warns (maybe-uninitialized) on the temporary default argument
    const Scene scene = parse_scene(m.header.at("scene_toml").get<std::string>()).scene;
    doc["agreement"] = agreement_json(scene, m.spec, m.points, defaults);
  }
  write_files_atomic({{o.out + ".csv", csv, "--out"}, {o.out + ".json", doc.dump(1) + "\n", "--out"}});
  std::cerr << "rbcstab: merged " << inputs.size() << " files, " << m.points.size() << " points into " << o.out
            << ".csv and " << o.out << ".json\n";
  if (o.json) std::cout << merge_brief_json(m, inputs.size(), o.out).dump(2) << "\n";
  return m.missing.empty() ? kOk : kRunFailed;
}

Runner add_merge(CLI::App& app) {
  auto o = std::make_shared<MergeOptions>();
  app.add_option("inputs", o->inputs, "diagram JSON files of the shards (PREFIX.shardKofN.json)")
      ->required()
      ->check(CLI::ExistingFile);
  app.add_option("--out", o->out, "output prefix: PREFIX.csv and PREFIX.json")
      ->check(output_name())
      ->capture_default_str();
  app.add_flag("--allow-incomplete", o->allow_incomplete, "write the merge even if points are missing (exit 1)");
  app.add_flag("--json", o->json, "print one JSON object on stdout (output files, points, missing)");
  return [o] { return run(*o); };
}

const RegisterCommand kRegisterMerge{"merge", "Merge the shard outputs of one diagram", add_merge, 41};
}  // namespace

}  // namespace rbcstab::cli
