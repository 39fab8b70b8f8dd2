#include "rbcstab/continuation/detail/diagram_journal.hpp"

#include <charconv>
#include <variant>

#include "rbcstab/continuation/branch_file.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/io/record_journal.hpp"

namespace rbcstab::detail {

namespace {
JournalFormat branch_journal_format() {
  JournalFormat f;
  f.magic = "# rbcstab bifurcation diagram journal ";
  f.version = "v1";
  f.key = "branch";
  f.item = "branch";
  f.choose = "--save or --journal";
  return f;
}

// The branch of one record, or why it is refused.
RecordKey read_branch_record(const std::string& line, const std::string& hash, const std::string& source,
                             std::map<std::size_t, JournaledBranch>& parsed) {
  const UnsealedRecord sealed = unseal_record(line);
  if (!sealed.body) return {std::nullopt, sealed.error};
  const std::string& body = *sealed.body;
  const std::string head = "B " + hash + " ";
  if (body.rfind("B ", 0) != 0) return {std::nullopt, "malformed record (it does not start with 'B ')"};
  if (body.rfind(head, 0) != 0)
    return {std::nullopt, "record of another configuration (this run's hash is " + hash + ")"};
  const auto space = body.find(' ', head.size());
  int number = 0;
  const char* first = body.data() + head.size();
  const char* last = body.data() + (space == std::string::npos ? body.size() : space);
  const auto r = std::from_chars(first, last, number);
  if (space == std::string::npos || r.ec != std::errc() || r.ptr != last || number < 1)
    return {std::nullopt, "malformed record (no branch number)"};
  const nlohmann::json j = nlohmann::json::parse(body.substr(space + 1), nullptr, /*allow_exceptions=*/false);
  JournaledBranch b;
  try {
    if (!j.is_object()) return {std::nullopt, "malformed record (its data is not a JSON object)"};
    const ContinuationRun run = parse_branch_json(j.at("file"), source, "journal");
    const SceneBranch* s = std::get_if<SceneBranch>(&run);
    if (!s) return {std::nullopt, "the record holds a curve, not a branch"};
    b.run = *s;
    const nlohmann::json& dg = j.at("file").at("diagram");
    if (dg.at("branch").get<int>() != number)
      return {std::nullopt,
              "the record of branch " + std::to_string(number) + " holds branch " + dg.at("branch").dump()};
    b.parent = dg.at("parent").is_null() ? 0 : dg.at("parent").get<int>();
    b.parent_label = dg.at("parent_label").is_null() ? 0 : dg.at("parent_label").get<int>();
    b.side = dg.at("side").get<int>();
    b.depth = dg.at("depth").get<int>();
    b.parent_point = j.at("parent_point").get<int>();
    b.closed = j.at("closed").get<bool>();
    b.next_label = j.at("next_label").get<int>();
  } catch (const nlohmann::json::exception& e) {
    return {std::nullopt, std::string("malformed record (") + e.what() + ")"};
  } catch (const InvalidArgument& e) {
    return {std::nullopt, e.what()};
  }
  parsed.insert_or_assign(static_cast<std::size_t>(number), std::move(b));
  return {static_cast<std::size_t>(number), {}};
}
}  // namespace

DiagramJournal::DiagramJournal(const std::string& path, const std::string& config_hash) : hash_(config_hash) {
  records_ = std::make_unique<RecordJournal>(
      path, config_hash, branch_journal_format(),
      [&](const std::string& line) { return read_branch_record(line, config_hash, path, parsed_); },
      /*sync_interval=*/0.0);  // a branch takes seconds: every record is synced
  for (auto it = parsed_.begin(); it != parsed_.end();)
    it = records_->records().count(it->first) ? std::next(it) : parsed_.erase(it);
}

DiagramJournal::~DiagramJournal() = default;

const JournaledBranch* DiagramJournal::find(int number) const {
  const auto it = parsed_.find(static_cast<std::size_t>(number));
  return it == parsed_.end() ? nullptr : &it->second;
}

void DiagramJournal::append(int number, const nlohmann::json& file, int parent_point, bool closed, int next_label) {
  const nlohmann::json j{
      {"file", file}, {"parent_point", parent_point}, {"closed", closed}, {"next_label", next_label}};
  records_->append(static_cast<std::size_t>(number),
                   seal_record("B " + hash_ + " " + std::to_string(number) + " " + j.dump()));
}

const std::vector<std::string>& DiagramJournal::rejected() const { return records_->rejected(); }

const std::string& DiagramJournal::path() const { return records_->path(); }

}  // namespace rbcstab::detail
