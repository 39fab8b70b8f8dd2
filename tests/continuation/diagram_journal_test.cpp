// The bifurcation diagram's journal: a diagram stopped after k branches and run again with its journal gives the
// uninterrupted diagram (its tree JSON and every branch file) byte for byte, continuing none of the recorded
// branches again; a torn or edited record is reported with file and line and its branch continued again; a journal
// of another configuration is refused. The modal walk-through scene of docs/continuation.md (9 branches at depth 1).
#include <gtest/gtest.h>

#include <atomic>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "continuation/modal_fixtures.hpp"
#include "continuation/scene_spec_fixture.hpp"
#include "rbcstab/continuation/bifurcation_diagram.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/io/record_journal.hpp"
#include "test_files.hpp"

namespace rbcstab {
namespace {

BifurcationDiagramSpec journal_spec(const std::string& journal) {
  BifurcationDiagramSpec s;
  s.start = test::spec_of(modal_fixtures::scene(0.04, 6), ProblemKind::modal, ContinuationParameter::C, 0.01, 0.1,
                          Direction::both);
  s.depth = 1;
  s.journal = journal;
  return s;
}

// Everything save_diagram writes: the tree and each branch file.
std::vector<std::string> rendered(const BifurcationDiagram& d) {
  std::vector<std::string> out{to_json(d).dump(1)};
  for (std::size_t k = 0; k < d.branches.size(); ++k) out.push_back(diagram_branch_file(d, k).dump(1));
  return out;
}

const std::vector<std::string>& uninterrupted() {
  static const std::vector<std::string> r = rendered(bifurcation_diagram(journal_spec("")));
  return r;
}

std::vector<std::string> journal_lines(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string l; std::getline(in, l);) lines.push_back(l + "\n");
  return lines;
}

void write_journal(const std::string& path, const std::vector<std::string>& lines, const std::string& tail = "") {
  std::ofstream out(path, std::ios::trunc);
  for (const std::string& l : lines) out << l;
  out << tail;
}

// Changes one digit of a point's parameter ("p":0.0DDD...) in a record; false when there is none.
bool edit_digit(std::string& record) {
  for (auto at = record.find("\"p\":0.0"); at != std::string::npos; at = record.find("\"p\":0.0", at + 1))
    if (at + 9 < record.size() && std::isdigit(record[at + 7]) && std::isdigit(record[at + 8]) &&
        std::isdigit(record[at + 9])) {
      record[at + 9] = record[at + 9] == '1' ? '2' : '1';
      return true;
    }
  return false;
}

// The diagram stopped from on_branch once `k` branches are done (Ctrl-C's flag).
BifurcationDiagram stopped_after(const std::string& journal, std::size_t k) {
  std::atomic<bool> stop{false};
  BifurcationDiagramSpec s = journal_spec(journal);
  s.on_branch = [&](std::size_t done, std::size_t) {
    if (done >= k) stop = true;
  };
  s.stop = &stop;
  return bifurcation_diagram(s);
}

TEST(DiagramJournal, StoppedThenResumedEqualsTheUninterruptedDiagram) {
  const std::filesystem::path dir = test::fresh_dir("diagram_journal", "resume");
  const std::string journal = (dir / "d.json.journal").string();
  const BifurcationDiagram part = stopped_after(journal, 4);
  ASSERT_TRUE(part.interrupted);
  EXPECT_FALSE(part.complete());
  EXPECT_NE(outcome(part).failure.find("resume from the journal"), std::string::npos) << outcome(part).failure;
  // The header and branches 1..4 (the stop is seen after the fourth is recorded).
  ASSERT_EQ(journal_lines(journal).size(), 5u);
  const BifurcationDiagram d = bifurcation_diagram(journal_spec(journal));
  EXPECT_EQ(d.resumed, 4u);
  EXPECT_TRUE(d.rejected.empty());
  EXPECT_TRUE(d.complete());
  EXPECT_EQ(rendered(d), uninterrupted());
  // Run again: everything is read back, nothing continued, nothing appended.
  const BifurcationDiagram again = bifurcation_diagram(journal_spec(journal));
  EXPECT_EQ(again.resumed, 9u);
  EXPECT_EQ(journal_lines(journal).size(), 10u);
  EXPECT_EQ(rendered(again), uninterrupted());
  std::filesystem::remove_all(dir);
}

// An edited record (one digit of a point changed), a record of another configuration and a torn last record are
// reported with file and line and their branches continued again: the diagram is still the uninterrupted one. The
// comparison can fail: the same edit with its checksum recomputed (a forged record) is resumed, and then the diagram
// differs.
TEST(DiagramJournal, EditedAndTornRecordsAreReportedAndContinuedAgain) {
  const std::filesystem::path dir = test::fresh_dir("diagram_journal", "edited");
  const std::string journal = (dir / "d.journal").string();
  bifurcation_diagram(journal_spec(journal));
  std::vector<std::string> l = journal_lines(journal);
  ASSERT_EQ(l.size(), 10u);
  const std::string clean3 = l[2];
  ASSERT_TRUE(edit_digit(l[2]));  // a point's C in branch 2's record
  const std::string torn = l[9].substr(0, l[9].size() / 2);
  l.pop_back();
  // Branch 5's record under another configuration's hash, its checksum valid (spliced from another journal).
  const std::string body5 = l[5].substr(0, l[5].size() - 19);
  l[5] = seal_record("B 0123456789abcdef" + body5.substr(body5.find(' ', 2)));
  write_journal(journal, l, torn);
  const BifurcationDiagram d = bifurcation_diagram(journal_spec(journal));
  ASSERT_EQ(d.rejected.size(), 3u) << ::testing::PrintToString(d.rejected);
  EXPECT_EQ(d.rejected[0].rfind(journal + ":3: checksum", 0), 0u) << d.rejected[0];
  EXPECT_EQ(d.rejected[1].rfind(journal + ":6: record of another configuration", 0), 0u) << d.rejected[1];
  EXPECT_EQ(d.rejected[2].rfind(journal + ":10: torn last record", 0), 0u) << d.rejected[2];
  EXPECT_EQ(d.resumed, 6u);
  EXPECT_EQ(rendered(d), uninterrupted());
  EXPECT_EQ(journal_lines(journal).size(), 10u);  // the three records dropped from the file, then written again
  // The forged record: body edited, checksum recomputed.
  l = journal_lines(journal);
  std::string body = clean3.substr(0, clean3.size() - 19);  // without " *<16 digits>\n"
  ASSERT_TRUE(edit_digit(body));
  const std::string branch2 = body.substr(0, body.find(' ', 2) + 3);  // "B <hash> 2 "
  for (std::string& line : l)
    if (line.rfind(branch2, 0) == 0) line = seal_record(body);
  write_journal(journal, l);
  const BifurcationDiagram forged = bifurcation_diagram(journal_spec(journal));
  EXPECT_TRUE(forged.rejected.empty());
  EXPECT_EQ(forged.resumed, 9u);
  EXPECT_NE(rendered(forged), uninterrupted());
  std::filesystem::remove_all(dir);
}

// A journal of another configuration (depth 2 instead of 1) is refused naming it; nothing in it is touched.
TEST(DiagramJournal, AnotherConfigurationIsRefused) {
  const std::filesystem::path dir = test::fresh_dir("diagram_journal", "foreign");
  const std::string journal = (dir / "d.journal").string();
  BifurcationDiagramSpec other = journal_spec("");
  other.depth = 2;
  write_journal(journal, {"# rbcstab bifurcation diagram journal v1 " + diagram_config_hash(other) + "\n"});
  EXPECT_NE(diagram_config_hash(other), diagram_config_hash(journal_spec("")));
  try {
    bifurcation_diagram(journal_spec(journal));
    ADD_FAILURE() << "a journal of another configuration was used";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.parameter(), "journal");
    EXPECT_NE(std::string(e.what()).find("belongs to another configuration"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(journal), std::string::npos) << e.what();
  }
  EXPECT_EQ(journal_lines(journal).size(), 1u);
  // What the hash leaves out: the journal's path, the progress and the stop.
  BifurcationDiagramSpec same = journal_spec("elsewhere.journal");
  same.on_branch = [](std::size_t, std::size_t) {};
  EXPECT_EQ(diagram_config_hash(same), diagram_config_hash(journal_spec("")));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace rbcstab
