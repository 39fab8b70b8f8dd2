// Branch files (continuation/branch_file.hpp): parse_branch_file on arbitrary text. For an accepted file
//   - every value the run keeps is the one the file gave: branch_file_json of the run holds, at each place, the
//     file's value (no number truncated to an int, no name defaulted, no label dropped), the views the writer
//     derives from the spec and the spectrum (kDerived, never read) aside; spec.scene, a scene file, must hold
//     the same scene (its text is written canonically: "0.301" as "0.30099999999999999");
//   - writing is a fixed point: that JSON parses back (parse_branch_file accepts what save_branch writes) to a run
//     with the very same JSON.
#include "rbcstab/continuation/branch_file.hpp"
#include "fuzz_check.hpp"
#include "json_compare.hpp"
#include "rbcstab/io/files.hpp"
#include "rbcstab/io/scene_file.hpp"

using namespace rbcstab;
using namespace rbcstab::fuzz;

namespace {
// Written for readers of the file, derived from the spec, the curve system or the spectrum; never read back.
const std::set<std::string> kDerived{"beta",
                                     "free_parameter",
                                     "kind",
                                     "level",
                                     "parameters",
                                     "segments",
                                     "curve.type",
                                     "curve.parameters",
                                     "curve.start",
                                     "curve.one_parameter_points",
                                     ".trivial_multiplier",
                                     ".critical",
                                     "spec.scene"};

// The scene of a scene file's text, written canonically (without the run options, which a branch does not keep).
std::string scene_text(const nlohmann::json& doc) {
  return to_toml(SceneFile{parse_scene(doc.at("spec").at("scene").get<std::string>()).scene, {}});
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size > (std::size_t(1) << 20)) return 0;
  const std::string text = text_of(data, size);
  ContinuationRun run;
  if (!accepted([&] { run = parse_branch_file(text, "fuzz.json"); })) return 0;
  const nlohmann::json written = branch_file_json(run);
  const std::string differs = first_difference(written, nlohmann::json::parse(text), kDerived);
  expect(differs.empty(), "a branch file value is read as another: " + differs);
  expect(scene_text(written) == scene_text(nlohmann::json::parse(text)), "spec.scene is read as another scene");
  const std::string dumped = written.dump(1);
  ContinuationRun back;
  expect(accepted([&] { back = parse_branch_file(dumped, "round-trip.json"); }),
         "parse_branch_file refuses what branch_file_json wrote for a file it accepted");
  const nlohmann::json again = branch_file_json(back);
  if (again != written) {
    const nlohmann::json diff = nlohmann::json::diff(written, again);
    fail("a branch file does not round-trip: " + diff.dump().substr(0, 2000));
  }
  return 0;
}
