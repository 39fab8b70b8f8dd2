// Diagram outputs read back (sweep/diagram_document.hpp merge_diagrams: `rbcstab merge` of shard files). The input
// is one or more diagram JSON documents separated by a line "----". An accepted merge must
//   - hold a header with a valid scene_toml (what `rbcstab merge` reads for the agreement), a spec that validates and
//   points in increasing index order, each inside the grid and passing
//     point_value_error for the modes of the header's scene, with the grid's axis values;
//   - list as missing exactly the grid indices no point holds;
//   - keep every point value as its input gave it: each input point, written back from the merged point of its
//     index (diagram_json), holds the input's values (no fraction truncated to an integer, no disagreeing
//     duplicate dropped), the values derived from the index (i, j, x, y) and the wall-clock seconds aside;
//   - round-trip: the JSON a merge writes (diagram_json) merges back to the same points, bit for bit.
#include <algorithm>

#include "fuzz_check.hpp"
#include "json_compare.hpp"
#include "rbcstab/io/scene_file.hpp"
#include "rbcstab/sweep/diagram_document.hpp"
#include "rbcstab/sweep/point_record.hpp"

using namespace rbcstab;
using namespace rbcstab::fuzz;

namespace {
bool same_point(const PointResult& a, const PointResult& b) {
  return a.index == b.index && a.i == b.i && a.j == b.j && same(a.x, b.x) && same(a.y, b.y) && a.verdict == b.verdict &&
         a.l_Delta == b.l_Delta && same(a.growth, b.growth) && a.oscillating == b.oscillating &&
         same(a.sigma_final, b.sigma_final) && a.status == b.status && a.reason == b.reason &&
         same(a.t_reached, b.t_reached) && a.steps == b.steps && a.failed_steps == b.failed_steps &&
         a.rhs_evaluations == b.rhs_evaluations && same(a.seconds, b.seconds);
}

std::vector<MergeInput> documents(const std::string& text) {
  std::vector<MergeInput> out;
  std::string current;
  for (const std::string& line : split(text, '\n')) {
    if (line == "----") {
      out.push_back({"input" + std::to_string(out.size() + 1) + ".json", current});
      current.clear();
    } else {
      current += line + "\n";
    }
  }
  out.push_back({"input" + std::to_string(out.size() + 1) + ".json", current});
  return out;
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size > (std::size_t(1) << 20)) return 0;
  const std::vector<MergeInput> inputs = documents(text_of(data, size));
  MergeResult m;
  if (!accepted([&] { m = merge_diagrams(inputs); })) return 0;

  expect(accepted([&] { m.spec.validate(); }), "a merge holds a spec that does not validate");
  // `rbcstab merge` reads the header's scene (the agreement of a complete merge): it must be there and valid.
  int L = 0;
  expect(m.header.contains("scene_toml") && m.header.at("scene_toml").is_string(),
         "a merge accepted a header without scene_toml");
  expect(accepted([&] { L = parse_scene(m.header.at("scene_toml").get<std::string>()).scene.L; }),
         "a merge accepted a header whose scene_toml parse_scene refuses");
  std::vector<bool> held(m.spec.size(), false);
  for (std::size_t k = 0; k < m.points.size(); ++k) {
    const PointResult& p = m.points[k];
    expect(k == 0 || m.points[k - 1].index < p.index, "merged points are not in increasing index order");
    const FieldError e = point_value_error(p, m.spec, L);
    expect(e.empty(), "a merged point is invalid: " + e.why);
    expect(p.i == int(p.index % std::size_t(m.spec.x.count)) && p.j == int(p.index / std::size_t(m.spec.x.count)) &&
               same(p.x, m.spec.x.value(p.i)) && same(p.y, m.spec.y.value(p.j)),
           "a merged point's grid position does not match its index");
    held[p.index] = true;
  }
  std::vector<std::size_t> missing;
  for (std::size_t idx = 0; idx < held.size(); ++idx)
    if (!held[idx]) missing.push_back(idx);
  expect(missing == m.missing, "the merge's missing list is not the set of indices no point holds");

  for (const MergeInput& in : inputs) {
    const nlohmann::json doc = nlohmann::json::parse(in.text);
    for (const nlohmann::json& given : doc.at("points")) {
      const std::size_t index = given.at("index").get<std::size_t>();
      const auto p =
          std::find_if(m.points.begin(), m.points.end(), [&](const PointResult& q) { return q.index == index; });
      expect(p != m.points.end(), in.name + ": point " + std::to_string(index) + " is not in the merge");
      const nlohmann::json written = diagram_json(m.header, m.spec, {*p}, {}, {false}).at("points").at(0);
      const std::string differs = first_difference(written, given, {"i", "j", "x", "y"});
      expect(differs.empty(), in.name + ": a point value is merged as another: " + differs);
    }
  }

  const DiagramOutputOptions oo{m.seconds_present};
  (void)diagram_csv(m.spec, m.points, oo);
  const std::string doc = diagram_json(m.header, m.spec, m.points, {}, oo).dump(1);
  MergeResult back;
  expect(accepted([&] {
           back = merge_diagrams(std::vector<MergeInput>{{"merged.json", doc}});
         }),
         "a merged diagram JSON does not merge back");
  expect(back.points.size() == m.points.size() && back.missing == m.missing,
         "a merged diagram merges back to other points");
  for (std::size_t k = 0; k < m.points.size(); ++k) {
    PointResult expected = m.points[k];
    if (!m.seconds_present) expected.seconds = 0;  // not written: reads back as the default
    expect(same_point(back.points[k], expected),
           "point " + std::to_string(expected.index) + " changes when its merge is merged again");
  }
  return 0;
}
