// `rbcstab paper --quick` as the library composes it: every figure drawn, every claim evaluated (a claim that fails
// is reported with its measured value, not hidden), the page lists them all, the data behind every figure exists.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "rbcstab/report/paper.hpp"
#include "rbcstab/report/paper_checks.hpp"

namespace rbcstab {
namespace {
namespace fs = std::filesystem;

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

TEST(PaperQuick, EveryFigureDrawnEveryClaimEvaluated) {
  const fs::path parent = fs::temp_directory_path() / ("rbcstab_paper_quick_" + std::to_string(::getpid()));
  fs::remove_all(parent);
  fs::create_directories(parent);
  PaperOptions o;
  o.output = (parent / "paper").string();
  o.quick = true;
  o.threads = 2;
  const PaperResult r = build_paper(o);
  ASSERT_TRUE(r.complete);
  EXPECT_EQ(r.failed_runs, 0u);
  // Figs. 2, 3, 4, 5, 6, app3, app4, app1, app2.
  ASSERT_EQ(r.figures.size(), 9u);
  EXPECT_EQ(r.passed + r.failed, r.claims.size());
  EXPECT_GE(r.claims.size(), 60u);
  const std::string html = slurp(parent / "paper" / "index.html");
  const nlohmann::json claims = nlohmann::json::parse(slurp(parent / "paper" / "claims.json"));
  ASSERT_EQ(claims.size(), r.claims.size());
  std::size_t failed_rows = 0, inconsistent_rows = 0;
  const auto& checks = paper_check::names();
  for (std::size_t k = 0; k < r.claims.size(); ++k) {
    const ClaimCheck& c = r.claims[k];
    EXPECT_FALSE(c.measured.empty()) << c.claim;
    EXPECT_FALSE(c.expected.empty()) << c.claim;
    EXPECT_EQ(claims[k]["passed"].get<bool>(), c.passed);
    // Every claim is decided by a check that paper_checks_test shows failing on wrong inputs.
    EXPECT_NE(std::find(checks.begin(), checks.end(), c.check), checks.end()) << c.claim << ": " << c.check;
    EXPECT_EQ(claims[k]["check"].get<std::string>(), c.check);
    failed_rows += !c.passed;
    if (!c.inconsistency.empty()) {
      EXPECT_FALSE(c.passed) << c.claim;  // an inconsistency is a failed claim, with its evidence on the page
      ++inconsistent_rows;
    }
  }
  EXPECT_EQ(r.inconsistent, inconsistent_rows);
  // Each inconsistency's evidence is on the page (its text goes through html_text's MathML, so it is counted).
  std::size_t evidence = 0;
  for (std::size_t at = html.find("<b>Paper/model inconsistency:</b>"); at != std::string::npos;
       at = html.find("<b>Paper/model inconsistency:</b>", at + 1))
    ++evidence;
  EXPECT_EQ(evidence, inconsistent_rows);
  // One row per claim on the page (their text is written with MathML symbols: report/detail/html_text, tested in
  // tests/report), each failed one shown as failed.
  std::size_t rows = 0;
  for (const char* tag : {"<tr class=\"pass\">", "<tr class=\"fail\">"})
    for (std::size_t at = html.find(tag); at != std::string::npos; at = html.find(tag, at + 1)) ++rows;
  EXPECT_EQ(rows, r.claims.size());
  std::size_t shown = 0;
  for (std::size_t at = html.find("<b>FAILED</b>"); at != std::string::npos; at = html.find("<b>FAILED</b>", at + 1))
    ++shown;
  EXPECT_EQ(shown, failed_rows);
  for (const PaperFigure& f : r.figures) {
    EXPECT_TRUE(fs::is_regular_file(parent / "paper" / (f.id + ".png"))) << f.id;
    EXPECT_GT(fs::file_size(parent / "paper" / (f.id + ".png")), 10000u) << f.id;
    // Its SVG too, which a click on the image opens.
    EXPECT_NE(slurp(parent / "paper" / (f.id + ".svg")).find("<svg"), std::string::npos) << f.id;
    EXPECT_NE(html.find("<a href=\"" + f.id + ".svg\""), std::string::npos) << f.id;
    EXPECT_FALSE(f.data.empty()) << f.id;
    for (const std::string& d : f.data) EXPECT_TRUE(fs::is_regular_file(parent / "paper" / d)) << d;
  }
  // Fig. 6 (a) and (c) carry the final shapes of the OP and IP delta = 1e-3 runs as insets, their grids among the
  // figure's data.
  const nlohmann::json spec = nlohmann::json::parse(slurp(parent / "paper" / "paper.json"));
  bool fig6 = false;
  for (const auto& f : spec["figures"]) {
    if (f["id"] != "fig6") continue;
    fig6 = true;
    for (int panel : {0, 2}) {
      const auto& insets = f["panels"][panel]["insets"];
      ASSERT_EQ(insets.size(), 2u) << panel;
      EXPECT_FALSE(insets[0]["in_plane"].get<bool>());
      EXPECT_TRUE(insets[1]["in_plane"].get<bool>());
      for (const auto& inset : insets) {
        const std::string data = inset["data"];
        EXPECT_NE(std::find(f["data"].begin(), f["data"].end(), data), f["data"].end()) << data;
        EXPECT_TRUE(fs::is_regular_file(parent / "paper" / data)) << data;
      }
    }
  }
  EXPECT_TRUE(fig6);
  // Nothing but the folder was left beside it (no staging leftovers).
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(parent)) ++entries;
  EXPECT_EQ(entries, 1u);
  fs::remove_all(parent);
}

}  // namespace
}  // namespace rbcstab
