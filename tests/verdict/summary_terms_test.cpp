// The summary's words and units: every term it prints is defined in docs/glossary.md (which it names), every
// physical output carries its unit (sigma also in N/m, Psi also in degrees, times also in s), the unstable
// window's both ends are reported, and the names follow the physics (an out-of-plane start is not "swinging";
// the out-of-plane shape's name follows its parity).
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <iomanip>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include "rbcstab/analysis/predictors.hpp"
#include "rbcstab/core/constants.hpp"
#include "rbcstab/io/scene_file.hpp"
#include "rbcstab/verdict/shear_rate.hpp"
#include "rbcstab/verdict/verdict_io.hpp"
#include "test_files.hpp"

namespace rbcstab {
namespace {

// The terms of a summary text: each line's label (the text at a line start before two spaces, ": ", " (" or
// " max_t"), the table's column heads, each symbol before " = " (without an argument (T), (0), (t) and
// surrounding brackets or bars), and the named values: the regime, the model level, the predictor names, the
// shapes after "-> " and the status.
std::set<std::string> summary_terms(const std::string& text) {
  std::set<std::string> terms;
  const std::regex label(R"(^([A-Z][A-Za-z0-9~ -]*?)(?:  |: | \(| max_t |:$))");
  const std::regex symbol(R"((\S+) = )");
  const std::regex named(R"(^(?:Regime|Model level) +(\S+) -- )");
  const std::regex predictor(R"(\([abc]\) ([a-z]+(?: [a-z]+)?) )");
  const std::regex shape(R"(-> ([a-z -]+?) \()");
  const std::regex status(R"(^Status: (\S+))");
  const std::regex columns(R"(\S+(?: \S+)*)");
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    std::smatch m;
    if (line.rfind("    l ", 0) == 0) {  // the table's column heads, two or more spaces apart
      std::string heads = std::regex_replace(line, std::regex(" {2,}"), "|");
      std::istringstream h(heads);
      for (std::string c; std::getline(h, c, '|');)
        if (!c.empty()) terms.insert(c);
      continue;
    }
    if (std::regex_search(line, m, label)) terms.insert(m[1]);
    if (std::regex_search(line, m, named)) terms.insert(m[1]);
    if (std::regex_search(line, m, status)) terms.insert(m[1]);
    for (std::sregex_iterator it(line.begin(), line.end(), predictor), end; it != end; ++it) terms.insert((*it)[1]);
    for (std::sregex_iterator it(line.begin(), line.end(), shape), end; it != end; ++it) terms.insert((*it)[1]);
    for (std::sregex_iterator it(line.begin(), line.end(), symbol), end; it != end; ++it) {
      std::string t = (*it)[1];
      while (!t.empty() && std::string("([|").find(t.front()) != std::string::npos) t.erase(0, 1);
      while (!t.empty() && std::string(",:|").find(t.back()) != std::string::npos) t.pop_back();
      for (const char* arg : {"(T)", "(0)", "(t)"})
        if (t.size() > 3 && t.ends_with(arg)) t.resize(t.size() - 3);
      if (t.ends_with(")") && t.find('(') == std::string::npos) t.pop_back();
      if (std::any_of(t.begin(), t.end(), [](char c) { return std::isalpha(static_cast<unsigned char>(c)); }))
        terms.insert(t);  // a symbol, not a number
    }
  }
  return terms;
}

// The terms the glossary does not define: a term is defined where it appears in backquotes.
std::set<std::string> undefined_terms(const std::set<std::string>& terms, const std::string& glossary) {
  std::set<std::string> out;
  for (const std::string& t : terms)
    if (glossary.find("`" + t + "`") == std::string::npos) out.insert(t);
  return out;
}

std::string glossary_text() { return test::slurp(std::string(RBCSTAB_SOURCE_DIR) + "/" + kGlossary); }

// R = 3 um, kappa = 2e-19 J: the tension unit kappa/R^2 = 2e-19/9e-12 = 2.2222e-8 N/m; gamma = 1000/s: 1 ms.
SceneFile terms_physical_scene() {
  SceneFile sf = parse_scene(
      "name = 'cell'\n[physical]\nshear_rate = 1000\nviscosity = '1 mPa s'\nradius = '3 um'\n"
      "bending_modulus = '2e-19 J'\nshear_modulus = '2.5 uN/m'\n[parameters]\nDelta = 1\nDelta0 = 0.5\n");
  sf.scene.L = 5;
  sf.scene.T = 20;
  sf.L_reason = "set by the test";
  return sf;
}

// Every variant of the summary's lines: a plain and a physical scene, threshold lines with and without the
// window's end, a warning, an early stop and a failed run.
std::vector<std::string> summary_variants() {
  std::vector<std::string> out;
  SceneFile plain = parse_scene("");
  plain.scene.L = 5;
  plain.scene.T = 20;
  plain.L_reason = "set by the test";
  for (SceneFile sf : {plain, terms_physical_scene()}) {
    SimulationResult r = simulate(sf.scene, sf.options);
    ScenePrediction pr = predict(sf.scene, &r);
    if (sf.scene.physical) {
      ShearRateThreshold found, open, none;
      found.orientation = "in_plane";
      found.found = found.end_found = true;
      found.shear_rate = 600;
      found.end_shear_rate = 5000;
      found.l = 3;
      found.shape = shape_of_mode(3, false);
      open = found;
      open.end_found = false;
      open.end_reason = "unstable up to max_rate = 1e6 1/s (the search's end)";
      open.orientation = "out_of_plane";
      open.shape = shape_of_mode(4, true);
      none.orientation = "out_of_plane";
      none.reason = "stable up to max_rate = 1e6 1/s";
      pr.shear_rate_thresholds = {found, open, none};
    }
    out.push_back(summary_text(sf, r, pr));
    r.warnings = {"a warning"};
    r.early.terminated = true;
    r.early.kind = "equilibrium";
    out.push_back(summary_text(sf, r, pr));
    r.early.terminated = false;
    r.early.note = "integrated to T";
    r.status = IntegrationStatus::step_limit;
    r.reason = "the step limit";
    out.push_back(summary_text(sf, r, pr));
  }
  return out;
}

TEST(SummaryTerms, EveryTermTheSummaryPrintsIsInTheGlossary) {
  const std::string g = glossary_text();
  ASSERT_FALSE(g.empty()) << "cannot read " << kGlossary;
  std::set<std::string> terms;
  for (const std::string& text : summary_variants()) {
    EXPECT_NE(text.find("Glossary     every term below: docs/glossary.md\n"), std::string::npos) << text;
    terms.merge(summary_terms(text));
  }
  // The names the summary can print beyond these runs: every regime, model level, status and shape.
  for (const auto& e : EnumTable<Regime>::entries) terms.insert(std::string(e.name));
  for (const auto& e : EnumTable<ModelLevel>::entries) terms.insert(std::string(e.name));
  for (const auto& e : EnumTable<IntegrationStatus>::entries) terms.insert(std::string(e.name));
  for (int l = 3; l <= 12; ++l)
    for (bool op : {true, false}) {
      const std::string name = shape_of_mode(l, op);
      terms.insert(name.substr(0, name.find(" (")));
    }
  EXPECT_GT(terms.size(), 50u);  // the extraction found the summary's vocabulary
  for (const char* t : {"Parameters", "Regime", "sigma_*", "<sigma_R>", "sigma_l^c", "Psi", "tail mean",
                        "finite horizon", "rolling", "stomatocyte", "1/gamma", "kappa/R^2", "Excess-area drift"})
    EXPECT_TRUE(terms.contains(t)) << t;
  const std::set<std::string> missing = undefined_terms(terms, g);
  std::string list;
  for (const std::string& t : missing) list += " '" + t + "'";
  EXPECT_TRUE(missing.empty()) << "not defined in " << kGlossary << ":" << list;
  // The check fails when a term is missing: the glossary without Psi's entry.
  std::string without = g;
  for (std::size_t at; (at = without.find("`Psi`")) != std::string::npos;) without.erase(at, 5);
  EXPECT_EQ(undefined_terms(terms, without), std::set<std::string>{"Psi"});
}

// On a physical scene: sigma also in N/m (kappa/R^2), Psi also in degrees, the horizon in s; the JSON likewise.
TEST(SummaryTerms, PhysicalOutputsCarryTheirUnits) {
  const SceneFile sf = terms_physical_scene();
  const SimulationResult r = simulate(sf.scene, sf.options);
  const ScenePrediction pr = predict(sf.scene, &r);
  const double unit = 2e-19 / (3e-6 * 3e-6);  // kappa/R^2 [N/m], by hand
  const nlohmann::json j = summary_json(sf, r, pr);
  EXPECT_NEAR(j["physical"]["tension_unit_N_per_m"].get<double>(), unit, 1e-14 * unit);
  EXPECT_NEAR(j["sigma_final_N_per_m"].get<double>(), r.sigma_final * unit, 1e-14 * std::abs(r.sigma_final * unit));
  EXPECT_NEAR(j["Psi_final_deg"].get<double>(), r.Psi_final * 180 / kPi, 1e-12);
  EXPECT_EQ(j["glossary"], kGlossary);
  const std::string text = summary_text(sf, r, pr);
  auto shown = [&](double x, const std::string& unit_name) {
    std::ostringstream o;
    o << std::setprecision(6) << x << unit_name;
    return o.str();
  };
  EXPECT_NE(text.find("sigma(T) = " + shown(r.sigma_final, " (") + shown(r.sigma_final * unit, " N/m)")),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("Psi(T) = " + shown(r.Psi_final, " rad (") + shown(r.Psi_final * 180 / kPi, " deg)")),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("T = 20 (0.02 s)"), std::string::npos) << text;
  EXPECT_NE(text.find("tension unit kappa/R^2 = " + shown(unit, " N/m")), std::string::npos) << text;
  // A plain scene has no physical unit to add: no N/m, no seconds, and Psi still in degrees.
  SceneFile plain = parse_scene("");
  plain.scene.L = 5;
  plain.scene.T = 20;
  const SimulationResult rp = simulate(plain.scene, plain.options);
  const std::string tp = summary_text(plain, rp, predict(plain.scene, &rp));
  EXPECT_EQ(tp.find("N/m"), std::string::npos);
  EXPECT_EQ(tp.find(" s)"), std::string::npos);
  EXPECT_NE(tp.find(" deg)"), std::string::npos);
}

// Out of plane the mode is axisymmetric (m = 0), with parity (-1)^l under z -> -z: only odd l make a cup.
TEST(SummaryTerms, ShapeNamesFollowTheModesParity) {
  EXPECT_EQ(shape_of_mode(3, true), "stomatocyte (l = 3, out of plane)");
  EXPECT_EQ(shape_of_mode(5, true), "axisymmetric cup (l = 5, out of plane)");
  EXPECT_EQ(shape_of_mode(4, true), "mirror-symmetric axisymmetric shape (l = 4, out of plane)");
  EXPECT_EQ(shape_of_mode(6, true), "mirror-symmetric axisymmetric shape (l = 6, out of plane)");
  EXPECT_EQ(shape_of_mode(3, false), "trilobe (l = 3, in plane)");
  EXPECT_EQ(shape_of_mode(4, false), "multilobe (l = 4, in plane)");
}

}  // namespace
}  // namespace rbcstab
