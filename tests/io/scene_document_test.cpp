// The scene document (io/scene_file.hpp): every parameter-table row round-trips from its TOML key to the scene
// and back through get; the flags, continuation parameters and diagram axes are the table's; every value records
// where it came from; the panel tables are kept as plain values; the truncation policy reads the provenance.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

#include "rbcstab/analysis/truncation.hpp"
#include "rbcstab/continuation/continuation_parameter.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/io/json.hpp"
#include "rbcstab/io/scene_file.hpp"
#include "rbcstab/sweep/diagram.hpp"

namespace rbcstab {
namespace {

// A value inside the row's domain at the default scene, different from the default.
double inside(const ParameterRow& r) {
  const Domain d = parameter_domain(r.id, Parameters{});
  if (!std::isfinite(d.lo) && !std::isfinite(d.hi)) return 0.3;
  return std::isfinite(d.hi) ? d.lo + 0.37 * (d.hi - d.lo) : d.lo + 1.7;
}

TEST(SceneDocument, EveryStoredRowRoundTripsFromItsKey) {
  int stored = 0;
  for (const ParameterRow& r : parameter_table()) {
    if (!r.table) continue;
    ++stored;
    const double v = inside(r);
    const std::string text = "[" + std::string(r.table) + "]\n" + r.name + " = " + format_value(v) + "\n";
    const SceneFile f = parse_scene(text);
    EXPECT_EQ(get_parameter(f.scene, r.id), v) << text;
    const std::string key = std::string(r.table) + "." + r.name;
    EXPECT_EQ(f.origin(key), Origin::file) << key;
    // Written back by to_toml, it reads the same.
    EXPECT_EQ(get_parameter(parse_scene(to_toml(f)).scene, r.id), v) << key;
    // Out of its domain the file is refused naming the key and the table's range.
    try {
      parse_scene("[" + std::string(r.table) + "]\n" + r.name + " = nan\n");
      ADD_FAILURE() << key << " = nan accepted";
    } catch (const InvalidArgument& e) {
      EXPECT_EQ(e.parameter(), key);
      EXPECT_NE(std::string(e.what()).find(parameter_domain(r.id, Parameters{}).text(false)), std::string::npos)
          << e.what();
    }
  }
  EXPECT_EQ(stored, 7);
}

// The flags are the table's stored rows (--name) and the run options' rows; the oracle lists the latter.
TEST(SceneDocument, FlagsContinuationParametersAndAxesAreTheTables) {
  std::vector<std::string> expected{"--name"};
  for (const ParameterRow& r : parameter_table())
    if (r.table) expected.push_back("--" + std::string(r.name));
  for (const char* f :
       {"--delta-l", "--rest-delta-l", "--L", "--T", "--dt", "--model", "--stepper", "--rtol", "--atol"})
    expected.emplace_back(f);
  std::vector<std::string> flags;
  for (const SceneKey* k : scene_flags()) flags.push_back(k->flag);
  EXPECT_EQ(flags, expected);
  // Every stored parameter is a scene key at its table, exactly once; every key path is unique.
  std::set<std::string> paths;
  for (const SceneKey& k : scene_keys()) EXPECT_TRUE(paths.insert(k.path()).second) << k.path();
  for (const ParameterRow& r : parameter_table()) {
    if (r.table) {
      EXPECT_EQ(paths.count(std::string(r.table) + "." + r.name), 1u) << r.name;
    }
  }
  EXPECT_EQ(continuation_parameter_names(), parameter_names(ParameterUse::continuation));
  EXPECT_EQ(axis_names(), parameter_names(ParameterUse::axis));
  for (const std::string& n : continuation_parameter_names())
    EXPECT_EQ(to_string(continuation_parameter_from_string(n)), n);
  for (const std::string& n : axis_names()) EXPECT_EQ(to_string(axis_from_string(n)), n);
  EXPECT_THROW(axis_from_string("B"), InvalidArgument);  // a parameter, not an axis (lnB is)
}

TEST(SceneDocument, RecordsWhereEachValueCameFrom) {
  SceneFile f = parse_scene(
      "name = \"p\"\n[parameters]\nB = 3\n[run]\nL = 6\n[initial]\ndelta_l = { 3 = 1e-4 }\n"
      "[diagram]\ncounts = [2, 2]\n",
      "p.toml");
  EXPECT_EQ(f.origin("parameters.B"), Origin::file);
  EXPECT_EQ(f.origin("run.L"), Origin::file);
  EXPECT_EQ(f.origin("name"), Origin::file);
  EXPECT_EQ(f.origin("initial.delta_l"), Origin::file);
  EXPECT_EQ(f.origin("diagram.counts"), Origin::file);
  EXPECT_EQ(f.origin("parameters.C"), Origin::default_value);
  EXPECT_EQ(f.origin("run.T"), Origin::default_value);
  EXPECT_EQ(f.source, "p.toml");
  ASSERT_TRUE(f.diagram.has_value());
  EXPECT_EQ(f.diagram->integers("counts", 2, "two integers"), (std::vector<long long>{2, 2}));
  EXPECT_FALSE(f.fig6e.has_value());
  // Flags apply on top and say so; a mode flag overrides single modes.
  for (const SceneKey* k : scene_flags()) {
    if (k->flag == "--B") apply_flag(f, *k, 4.5);
    if (k->flag == "--T") apply_flag(f, *k, 50.0);
    if (k->flag == "--delta-l") apply_flag(f, *k, parse_modes({"4=2e-4"}, "--delta-l"));
    if (k->flag == "--model") apply_flag(f, *k, std::string("reduced"));
  }
  validate_scene_file(f);
  EXPECT_EQ(f.scene.parameters.B, 4.5);
  EXPECT_EQ(f.origin("parameters.B"), Origin::flag);
  EXPECT_EQ(f.origin("run.T"), Origin::flag);
  EXPECT_EQ(f.origin("run.L"), Origin::file);
  EXPECT_EQ(f.scene.delta_l, (std::map<int, double>{{3, 1e-4}, {4, 2e-4}}));
  EXPECT_EQ(f.scene.model, ModelLevel::reduced);
  EXPECT_EQ(to_string(Origin::default_value), "default");
  EXPECT_EQ(to_string(Origin::flag), "flag");
  EXPECT_THROW(parse_modes({"3:1e-3"}, "--delta-l"), InvalidArgument);
  // A comma list sets every mode it names; every piece must parse in full and each mode appear once.
  EXPECT_EQ(parse_modes({"3=0.05,4=0.07", "5=1e-3"}, "--delta-l"),
            (std::map<int, double>{{3, 0.05}, {4, 0.07}, {5, 1e-3}}));
  for (const char* bad : {"", "3=", "=1", "3=0.1abc", "3=0.1=2", "3.5=0.1", "3=0.1,", ",3=0.1", "3=0.1,3=0.2"})
    EXPECT_THROW(parse_modes({bad}, "--delta-l"), InvalidArgument) << bad;
  EXPECT_THROW(parse_modes({"3=0.1", "3=0.2"}, "--delta-l"), InvalidArgument);
  // Panel tables are read once but interpreted by their owners: a wrong type is named when read.
  try {
    (void)parse_scene("[fig6e]\nB = \"x\"\n").fig6e->numbers("B", 0, "a non-empty array of numbers");
    FAIL();
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.parameter(), "fig6e.B");
  }
}

// The one truncation policy: a given L is kept and says where from; otherwise a simulation gets the automatic
// choice and the other uses keep the scene's L with their reason. JSON outputs carry both.
TEST(SceneDocument, TruncationPolicyReadsTheProvenance) {
  const SceneFile given = parse_scene("[run]\nL = 6\nT = 20.0\n");
  const TruncationDecision file = resolve_truncation(given.scene, given.origin("run.L"), TruncationUse::simulation);
  EXPECT_EQ(file.L, 6);
  EXPECT_EQ(file.reason, "L = 6: given by the scene file's run.L");
  EXPECT_EQ(resolve_truncation(given.scene, Origin::flag, TruncationUse::grid).reason, "L = 6: given by --L");
  const SceneFile none = parse_scene("[run]\nT = 20.0\n");
  TruncationOptions up_to_scene_L;  // the policy never goes above the scene's L
  up_to_scene_L.L_max = none.scene.L;
  const TruncationChoice automatic = choose_truncation(none.scene, up_to_scene_L);
  const TruncationDecision sim = resolve_truncation(none.scene, none.origin("run.L"), TruncationUse::simulation);
  EXPECT_EQ(sim.L, automatic.L);
  EXPECT_EQ(sim.reason, automatic.reason);
  for (TruncationUse use : {TruncationUse::grid, TruncationUse::analysis, TruncationUse::measurement}) {
    const TruncationDecision d = resolve_truncation(none.scene, Origin::default_value, use);
    EXPECT_EQ(d.L, none.scene.L);
    EXPECT_EQ(d.reason.rfind("L = 10: the default", 0), 0u) << d.reason;
  }
  const TruncationDecision reduced = resolve_truncation(given.scene, Origin::file, TruncationUse::reduced);
  EXPECT_EQ(reduced.L, 6);
  EXPECT_NE(reduced.reason.find("not used"), std::string::npos) << reduced.reason;
  SceneFile f = none;
  f.L_reason = sim.reason;
  nlohmann::json j;
  put_truncation(j, f);
  EXPECT_EQ(j.at("L").get<int>(), f.scene.L);
  EXPECT_EQ(j.at("L_reason").get<std::string>(), sim.reason);
}

}  // namespace
}  // namespace rbcstab
