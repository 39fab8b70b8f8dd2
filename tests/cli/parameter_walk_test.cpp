// The parameter table (model/parameter_table.hpp) against every interface that names a parameter: scene keys
// and flags, the [physical] flag, continuation parameters, diagram axes, `units` inputs and formulas, the
// summary's parameter lines, figure labels, and the command line's --help of each. A row added to the table
// appears in each of them; a parameter named in one of them and not in the table fails here.
#include <gtest/gtest.h>

#include <cstdio>
#include <memory>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "rbcstab/continuation/continuation_parameter.hpp"
#include "rbcstab/io/scene_file.hpp"
#include "rbcstab/model/parameter_table.hpp"
#include "rbcstab/model/physical.hpp"
#include "rbcstab/report/bifurcation_plot.hpp"
#include "rbcstab/sweep/diagram.hpp"
#include "test_files.hpp"

namespace rbcstab {
namespace {

// stdout of `rbcstab args` (stderr dropped).
std::string cli_output(const std::string& args) {
  const std::string cmd = std::string(RBCSTAB_CLI) + " " + args + " 2>/dev/null";
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(cmd.c_str(), "r"), pclose);
  std::string out;
  char buf[4096];
  for (std::size_t n; pipe && (n = std::fread(buf, 1, sizeof buf, pipe.get())) > 0;) out.append(buf, n);
  return out;
}

// The long flags a --help lists ("  --lambda FLOAT=5   ..." -> "--lambda").
std::set<std::string> help_flags(const std::string& help) {
  std::set<std::string> flags;
  const std::regex flag(R"((?:^|\n)\s+(?:-\w,)?(--[A-Za-z0-9_-]+))");
  for (std::sregex_iterator it(help.begin(), help.end(), flag), end; it != end; ++it) flags.insert((*it)[1]);
  return flags;
}

std::vector<std::string> row_names(bool (*keep)(const ParameterRow&)) {
  std::vector<std::string> names;
  for (const ParameterRow& r : parameter_table())
    if (keep(r)) names.emplace_back(r.name);
  return names;
}

TEST(ParameterWalk, SceneKeysAndFlagsAreTheStoredRows) {
  std::vector<std::string> keys;
  for (const SceneKey& k : scene_keys())
    if ((k.table == "parameters" || k.table == "initial") && k.kind == ValueKind::number) {
      keys.push_back(k.key);
      EXPECT_EQ(k.flag, "--" + k.key);
      const ParameterRow& r = parameter_row(parameter_from_string(k.key, ParameterUse::scene_key));
      EXPECT_EQ(k.table, r.table) << k.key;
      EXPECT_NE(k.help.find(r.description), std::string::npos) << k.help;
    }
  EXPECT_EQ(keys, row_names([](const ParameterRow& r) { return r.table != nullptr; }));
  // The path parameter stored in the physical cell: its [physical] key and unit flag.
  const SceneKey* gamma = nullptr;
  for (const SceneKey& k : scene_keys())
    if (k.table == "physical" && k.key == parameter_row(SceneParameter::shear_rate).name) gamma = &k;
  ASSERT_NE(gamma, nullptr);
  EXPECT_EQ(gamma->unit_flag, "--shear-rate");
}

TEST(ParameterWalk, ContinuationParametersAndAxesAreTheMarkedRows) {
  EXPECT_EQ(continuation_parameter_names(), row_names([](const ParameterRow& r) { return r.continuation; }));
  EXPECT_EQ(axis_names(), row_names([](const ParameterRow& r) { return r.axis; }));
}

// Each row's figure label is its TeX symbol (with its unit), the same in every figure.
TEST(ParameterWalk, FigureLabelsAreTheRowsSymbols) {
  for (const ParameterRow& r : parameter_table()) {
    const std::string unit = *r.unit ? std::string(" [") + r.unit + "]" : "";
    EXPECT_EQ(tex_symbol(r.name), std::string("$") + r.symbol + "$" + unit) << r.name;
  }
}

// The command line: each command's --help offers exactly the table's rows for its use.
TEST(ParameterWalk, CommandLineFlagsAreTheTablesRows) {
  const std::set<std::string> simulate = help_flags(cli_output("simulate --help"));
  for (const ParameterRow& r : parameter_table())
    EXPECT_EQ(simulate.count(std::string("--") + r.name), r.table ? 1u : 0u) << r.name;
  // units: the physical flags, the rows with a units input, --json.
  std::set<std::string> expected{"--help", "--json"};
  for (const SceneKey& k : scene_keys())
    if (k.kind == ValueKind::quantity) expected.insert(k.unit_flag);
  for (const ParameterRow& r : parameter_table())
    if (r.physical.input) expected.insert(std::string("--") + r.name);
  EXPECT_EQ(help_flags(cli_output("units --help")), expected);
  // continue --parameter and diagram --axes list the rows marked for them.
  std::string list;
  for (const std::string& n : continuation_parameter_names()) list += (list.empty() ? "" : ", ") + n;
  EXPECT_NE(cli_output("continue --help").find("free parameter: " + list), std::string::npos) << list;
  const std::string diagram = cli_output("diagram --help");
  for (const std::string& n : axis_names()) EXPECT_NE(diagram.find(n), std::string::npos) << n;
}

// `units --json`: the formulas are R, the rows with a physical formula, the time unit.
TEST(ParameterWalk, UnitsFormulasAreTheRowsFormulas) {
  const std::string out = cli_output(
      "units --radius 3um --viscosity 1mPa.s --shear-rate 100 --bending-modulus 2e-19J "
      "--shear-modulus 6uN/m --json");
  std::set<std::string> expected{"R_m", "time_unit_s"};
  for (const ParameterRow& r : parameter_table())
    if (r.physical.formula) expected.insert(r.name);
  const std::regex key(R"rx("([A-Za-z0-9_]+)": \{\s*"formula")rx");
  std::set<std::string> found;
  for (std::sregex_iterator it(out.begin(), out.end(), key), end; it != end; ++it) found.insert((*it)[1]);
  EXPECT_EQ(found, expected) << out;
}

// summary: its "Parameters" lines name the stored rows, its "Derived" line the composites, in table order.
TEST(ParameterWalk, SummaryLinesNameTheRows) {
  const std::string out = cli_output("summary --T 2 --L 3");
  auto names_on = [&](const std::string& start, const std::string& end) {
    const std::size_t a = out.find(start), b = out.find(end, a);
    const std::string text = out.substr(a, b - a);
    std::vector<std::string> names;
    const std::regex item(R"((?:^|[ ,])([A-Za-z0-9_]+) = )");
    for (std::sregex_iterator it(text.begin(), text.end(), item), e; it != e; ++it) names.push_back((*it)[1]);
    return names;
  };
  std::vector<std::string> stored = row_names([](const ParameterRow& r) { return r.table != nullptr; });
  stored.insert(stored.end(), {"L", "T"});
  EXPECT_EQ(names_on("Parameters", "Derived"), stored) << out;
  EXPECT_EQ(names_on("Derived", "\n"), row_names([](const ParameterRow& r) { return r.definition != nullptr; })) << out;
}

// docs/scenes.md's parameter table is this table, row for row: a row added here and not there fails, with the
// rows to paste in the message.
TEST(ParameterWalk, ScenesDocumentListsTheRows) {
  std::string expected;
  for (const ParameterRow& r : parameter_table()) {
    const std::string stored = r.table                     ? std::string("`[") + r.table + "]`"
                               : r.definition              ? "derived"
                               : r.scale == AxisScale::log ? "log axis"
                                                           : "`[physical]`";
    std::string levels;
    for (ModelLevel l : {ModelLevel::reduced, ModelLevel::modal, ModelLevel::full})
      if (r.levels & level_bit(l)) levels += (levels.empty() ? "" : ", ") + to_string(l);
    expected += std::string("| ") + r.name + " | " + r.unicode + " | " + stored + " | " +
                parameter_domain(r.id, Parameters{}).text(false) + " | " + (r.continuation ? "yes" : "no") + " | " +
                (r.axis ? "yes" : "no") + " | " + to_string(moved_parameter(r.id)) + " | " + levels + " |\n";
  }
  const std::string doc = test::slurp(std::string(RBCSTAB_SOURCE_DIR) + "/docs/scenes.md");
  const std::string header = "| name | symbol | stored in | domain | continuation | axis | set through | levels |\n";
  const std::size_t at = doc.find(header);
  ASSERT_NE(at, std::string::npos) << "docs/scenes.md has no parameter table starting " << header;
  const std::size_t rows = doc.find('\n', at + header.size()) + 1;  // past the |---| line
  const std::size_t end = doc.find("\n\n", rows);
  EXPECT_EQ(doc.substr(rows, end + 1 - rows), expected) << "docs/scenes.md's rows should read:\n" << expected;
}

}  // namespace
}  // namespace rbcstab
