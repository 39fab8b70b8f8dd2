#pragma once
// The bifurcation diagram's checkpoint journal (bifurcation_diagram.hpp): one record per branch continued to its
// end, "B <config hash> <branch> <JSON>", the JSON {"file": the branch's diagram_branch_file, "parent_point",
// "closed", "next_label"} (what grow_tree and the labelling need to go on after it), in a RecordJournal
// (io/record_journal.hpp: header, lock, checksums, torn or edited records reported with file and line).
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "rbcstab/continuation/scene_continuation.hpp"

namespace rbcstab {
class RecordJournal;
}

namespace rbcstab::detail {

struct JournaledBranch {
  SceneBranch run;  // the branch as its branch file reads back (branch 1: the start branch's run)
  int parent = 0, parent_label = 0, parent_point = -1, side = 0, depth = 0;
  bool closed = false;
  int next_label = 1;  // the first label of the branches after it
};

class DiagramJournal {
 public:
  // Throws InvalidArgument("journal") for a journal of another configuration, or one locked by another process.
  DiagramJournal(const std::string& path, const std::string& config_hash);
  ~DiagramJournal();
  // The record of branch `number` (1, 2, ...), or nullptr.
  const JournaledBranch* find(int number) const;
  void append(int number, const nlohmann::json& file, int parent_point, bool closed, int next_label);
  const std::vector<std::string>& rejected() const;
  const std::string& path() const;

 private:
  std::string hash_;
  std::map<std::size_t, JournaledBranch> parsed_;
  std::unique_ptr<RecordJournal> records_;
};

}  // namespace rbcstab::detail
