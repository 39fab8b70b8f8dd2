// The whole bifurcation diagram of a scene: the start branch (continue_scene), the tree grown from it on the
// scene's problem (grow_tree), every branch measured and labelled after the ones before it, and its renderings.
#include "rbcstab/continuation/bifurcation_diagram.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <memory>
#include <sstream>
#include <utility>
#include <variant>

#include "rbcstab/continuation/branch_file.hpp"
#include "rbcstab/continuation/branch_io.hpp"
#include "rbcstab/continuation/detail/branch_labels.hpp"
#include "rbcstab/continuation/detail/diagram_journal.hpp"
#include "rbcstab/continuation/detail/scene_problem.hpp"
#include "rbcstab/continuation/detail/scene_switch.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/io/files.hpp"
#include "rbcstab/io/json.hpp"
#include "rbcstab/io/record_journal.hpp"

namespace rbcstab {

namespace {

std::string side_text(int side) { return side > 0 ? "+" : side < 0 ? "-" : ""; }

std::string outcome_text(const DiagramEmanation& e) {
  switch (e.outcome) {
    case EmanationOutcome::followed:
      return "followed: branch " + std::to_string(e.branch_to);
    case EmanationOutcome::duplicate:
      return "not followed: a duplicate of branch " + std::to_string(e.branch_to);
    case EmanationOutcome::symmetric:
      return "not followed: the symmetric copy of branch " + std::to_string(e.branch_to);
    case EmanationOutcome::already_switched:
      return "not switched at again: the point of label " + std::to_string(e.label_to) + " on branch " +
             std::to_string(e.branch_to);
    case EmanationOutcome::not_available:
      return "not followed (switching not available" + (e.message.empty() ? "" : ": " + e.message) + ")";
    case EmanationOutcome::rotating_wave:
      return "not followed as a branch of its own: rotating waves of " +
             (e.branch_to > 0 ? "branch " + std::to_string(e.branch_to) + " (from the BP of label "
                              : "the branch (not followed here) from the BP of label ") +
             std::to_string(e.label_to) + (e.branch_to > 0 ? ")" : "") + ": " + e.message;
    case EmanationOutcome::not_located:
      return "not followed: " + e.message;
    case EmanationOutcome::depth_limit:
      return "not followed: the depth limit";
    case EmanationOutcome::failed:
      return "switching failed: " + e.message;
    case EmanationOutcome::interrupted:
      return "not followed: interrupted";
    case EmanationOutcome::branch_limit:
      return "not followed: max_branches reached";
  }
  return "";
}

const SpecialPoint& point_of(const BifurcationDiagram& d, const DiagramEmanation& e) {
  const MeasuredBranch& m = d.branches.at(static_cast<std::size_t>(e.branch - 1)).branch;
  const auto it = std::find(m.special_labels.begin(), m.special_labels.end(), e.label);
  return m.branch.special_points.at(static_cast<std::size_t>(it - m.special_labels.begin()));
}

std::string range_text(const Branch& b) {
  if (b.points.empty()) return "no points";
  const auto [lo, hi] = std::minmax_element(b.points.begin(), b.points.end(),
                                            [](const BranchPoint& a, const BranchPoint& c) { return a.p < c.p; });
  std::ostringstream out;
  out << std::setprecision(10) << b.points.size() << " points from " << lo->p << " to " << hi->p;
  return out.str();
}

// save_diagram's file of branch k beside the tree: "<stem>.b<K>.json".
std::string branch_path(const std::string& path, std::size_t k) {
  const bool has_suffix = path.size() > 5 && path.substr(path.size() - 5) == ".json";
  return (has_suffix ? path.substr(0, path.size() - 5) : path) + ".b" + std::to_string(k + 1) + ".json";
}

}  // namespace

void BifurcationDiagramSpec::validate() const {
  start.validate();
  require(!start.switch_at_bp, "switch_at_bp", 1, "false: the diagram switches at every BP");
  TreeOptions o;
  o.depth = depth;
  o.switching.amplitude = amplitude;
  o.duplicate_tol = duplicate_tol;
  o.max_branches = max_branches;
  o.validate();
}

bool BifurcationDiagram::complete() const {
  return !interrupted && std::none_of(emanations.begin(), emanations.end(), [](const DiagramEmanation& e) {
    return e.outcome == EmanationOutcome::interrupted || e.outcome == EmanationOutcome::branch_limit;
  });
}

BifurcationDiagram bifurcation_diagram(const BifurcationDiagramSpec& spec) {
  spec.validate();
  BranchSpec start_spec = spec.start;
  if (spec.stop) {
    auto user_stop = start_spec.engine.stop;
    start_spec.engine.stop = [flag = spec.stop, user_stop](const Eigen::VectorXd& x, double p) {
      return flag->load() || (user_stop && user_stop(x, p));
    };
  }
  BifurcationDiagram d;
  d.depth = spec.depth;
  std::unique_ptr<detail::DiagramJournal> journal;
  if (!spec.journal.empty()) {
    journal = std::make_unique<detail::DiagramJournal>(spec.journal, diagram_config_hash(spec));
    d.journal = spec.journal;
    d.rejected = journal->rejected();
  }
  const auto stopped = [&] { return spec.stop && spec.stop->load(); };
  if (const detail::JournaledBranch* j = journal ? journal->find(1) : nullptr) {
    d.start = j->run;
    // What a branch file cannot hold, as given (continue_scene keeps them as they are).
    d.start.spec.engine.on_progress = spec.start.engine.on_progress;
    d.start.spec.monitors = spec.start.monitors;
    ++d.resumed;
  } else {
    d.start = continue_scene(start_spec);
  }
  d.start.spec.engine.stop = spec.start.engine.stop;  // the run as asked (a branch file stores no function)
  const bool started = d.start.start.converged && !d.start.start.refused;
  // Branch 1 keeps continue_scene's measures and labels; the others are numbered after it.
  DiagramBranch first;
  first.branch = d.start.branch;
  d.branches.push_back(std::move(first));
  int next = d.start.branch.last_label() + 1;
  if (journal && started && d.resumed == 0 && !stopped())
    journal->append(1, diagram_branch_file(d, 0), -1, false, next);
  const auto sp = detail::make_problem(d.start.spec, d.start.problem_scene);
  TreeOptions o;
  o.depth = spec.depth;
  o.switching.amplitude = spec.amplitude;
  o.switching.continuation = d.start.spec.engine;  // its bounds as set_domain_bounds landed them
  o.duplicate_tol = spec.duplicate_tol;
  o.max_branches = spec.max_branches;
  o.stop = spec.stop;
  o.on_branch = spec.on_branch;
  // HB: orbit_switch_start refuses every HB of a scene's problem, naming why (none is an autonomous system's
  // equilibrium problem; the model's l >= 3 onset's orbits are rotating waves of its BP's branch). PD: the doubled
  // orbit would be a problem of its own that the scene's measures, monitors and branch files do not describe.
  o.switchers[SpecialPointType::PD] = [](const ContinuationProblem&, const Branch&, const SpecialPoint&,
                                         const BranchSwitchOptions&) {
    EmanatingStart e;
    e.refused = true;
    e.message = detail::kScenePeriodDoublingRefusal;
    return std::vector<EmanatingStart>{std::move(e)};
  };
  // The run's monitors label (or stop) every branch, as a switched branch's (scene_switch.cpp).
  const std::vector<std::string> names = measure_names(d.start.spec.kind, d.start.problem_scene.L);
  o.events = [&](const Eigen::VectorXd& x0, double p0) {
    return detail::monitor_events(*sp, names, d.start.spec.monitors, x0, p0);
  };
  // Branch k + 1 measured and labelled after the ones before it, as it comes (grow_tree's order).
  const auto add_branch = [&](std::size_t k, const TreeBranch& t, MeasuredBranch m) {
    DiagramBranch b;
    b.number = static_cast<int>(k) + 1;
    b.parent = t.parent + 1;
    b.side = t.side;
    b.depth = t.depth;
    b.parent_label =
        d.branches[static_cast<std::size_t>(t.parent)].branch.special_labels[static_cast<std::size_t>(t.parent_point)];
    b.branch = std::move(m);
    d.branches.push_back(std::move(b));
  };
  if (journal) {
    o.recall = [&](std::size_t k, TreeBranch& t) {
      const detail::JournaledBranch* j = journal->find(static_cast<int>(k) + 1);
      if (!j || d.branches.size() != k) return false;
      if (j->parent != t.parent + 1 || j->parent_point != t.parent_point || j->side != t.side || j->depth != t.depth) {
        d.rejected.push_back(journal->path() + ": branch " + std::to_string(k + 1) + " was recorded from BR " +
                             std::to_string(j->parent) + " side " + std::to_string(j->side) +
                             ", this run reaches it from BR " + std::to_string(t.parent + 1) + " side " +
                             std::to_string(t.side) + "; not used, the branch is recomputed");
        return false;
      }
      t.branch = j->run.branch.branch;
      t.closed = j->closed;
      add_branch(k, t, j->run.branch);
      next = j->next_label;
      ++d.resumed;
      return true;
    };
    o.on_followed = [&](std::size_t k, const TreeBranch& t) {
      if (d.branches.size() != k) return;
      add_branch(k, t, detail::measure_branch(*sp, d.start, t.branch));
      next = detail::label_branch(d.branches.back().branch, d.start.spec.label_every, next);
      journal->append(static_cast<int>(k) + 1, diagram_branch_file(d, k), t.parent_point, t.closed, next);
    };
  }
  BranchTree tree = started ? grow_tree(sp->problem(), d.start.branch.branch, o) : BranchTree{};
  if (!started) tree.branches.push_back({d.start.branch.branch, nullptr, -1, -1, 0, 0});
  d.interrupted = tree.interrupted || stopped();
  for (std::size_t k = d.branches.size(); k < tree.branches.size(); ++k) {
    TreeBranch& t = tree.branches[k];
    add_branch(k, t, detail::measure_branch(*sp, d.start, std::move(t.branch)));
    next = detail::label_branch(d.branches.back().branch, d.start.spec.label_every, next);
  }
  for (const TreeEmanation& t : tree.emanations) {
    const MeasuredBranch& on = d.branches[static_cast<std::size_t>(t.branch)].branch;
    DiagramEmanation e;
    e.branch = t.branch + 1;
    e.label = on.special_labels[t.point];
    e.type = on.branch.special_points[t.point].type;
    e.side = t.side;
    e.outcome = t.outcome;
    e.message = t.message;
    if (t.branch_to >= 0) e.branch_to = t.branch_to + 1;
    if (t.outcome == EmanationOutcome::rotating_wave)
      e.label_to = on.special_labels[static_cast<std::size_t>(t.point_to)];  // the BP on the same branch
    else if (t.point_to >= 0)
      e.label_to =
          d.branches[static_cast<std::size_t>(t.branch_to)].branch.special_labels[static_cast<std::size_t>(t.point_to)];
    d.emanations.push_back(std::move(e));
  }
  return d;
}

std::string diagram_config_hash(const BifurcationDiagramSpec& spec) {
  return fnv1a_hex(branch_spec_json(spec.start).dump() + "\ndepth " + std::to_string(spec.depth) + " amplitude " +
                   exact(spec.amplitude) + " duplicate_tol " + exact(spec.duplicate_tol) + " max_branches " +
                   std::to_string(spec.max_branches) + "\n");
}

RunOutcome outcome(const BifurcationDiagram& d) {
  RunOutcome o = outcome(d.start);
  if (!o.has_output) return o;
  const auto add = [&](const std::string& why) { o.failure += (o.failure.empty() ? "" : "; ") + why; };
  for (std::size_t k = 1; k < d.branches.size(); ++k)
    if (const Branch& b = d.branches[k].branch.branch; !ended_normally(b.status))
      add("branch " + std::to_string(k + 1) + ": continuation stopped: " + to_string(b.status) + ": " + b.message);
  for (const DiagramEmanation& e : d.emanations)
    if (e.outcome == EmanationOutcome::failed)
      add("switching at label " + std::to_string(e.label) + " (side " + side_text(e.side) + ") failed: " + e.message);
  if (!d.complete())
    add(!d.interrupted ? "max_branches reached: the diagram is incomplete"
        : d.journal.empty()
            ? "interrupted: the diagram is incomplete (no journal: run it again to recompute it)"
            : "interrupted: the diagram is incomplete (run it again to resume from the journal '" + d.journal + "')");
  return o;
}

SceneBranch diagram_run(const BifurcationDiagram& d, std::size_t k) {
  require(k < d.branches.size(), "branch", static_cast<double>(k + 1),
          "a branch of the diagram, 1 to " + std::to_string(d.branches.size()));
  if (k == 0) return d.start;
  const DiagramBranch& b = d.branches[k];
  SceneBranch r;
  r.spec = d.start.spec;
  r.problem_scene = d.start.problem_scene;
  r.spec.scene = d.start.problem_scene;
  r.branch = b.branch;
  const Branch& br = b.branch.branch;
  if (!br.points.empty()) {
    const BranchPoint& p0 = br.points.front();
    r.spec.start_state = p0.x;
    r.spec.start_parameter = p0.p;
    r.spec.engine.direction = br.points.size() > 1 && br.points[1].p < p0.p ? Direction::backward : Direction::forward;
    r.start.method = StartMethod::restart;
    r.start.x = p0.x;
    r.start.p = p0.p;
    r.start.stable = p0.stable;
    r.start.n_unstable = p0.n_unstable;
    r.start.stability = p0.stability;
    r.start.margin = p0.margin;
    r.start.margin_error = p0.margin_error;
    r.start.uncertain_because = p0.uncertain_because;
  }
  return r;
}

nlohmann::json to_json(const BifurcationDiagram& d) {
  const std::string q = to_string(d.start.spec.parameter);
  nlohmann::json branches = nlohmann::json::array(), points = nlohmann::json::array();
  for (std::size_t k = 0; k < d.branches.size(); ++k) {
    const DiagramBranch& b = d.branches[k];
    const Branch& br = b.branch.branch;
    nlohmann::json range = nlohmann::json::array(), labels = nlohmann::json::array();
    if (!br.points.empty()) {
      const auto [lo, hi] = std::minmax_element(br.points.begin(), br.points.end(),
                                                [](const BranchPoint& a, const BranchPoint& c) { return a.p < c.p; });
      range = {number_or_null(lo->p), number_or_null(hi->p)};
    }
    int first = 0, last = b.branch.last_label();
    for (int l : b.branch.point_labels)
      if (l > 0 && (first == 0 || l < first)) first = l;
    labels = {first, last};
    branches.push_back({{"branch", b.number},
                        {"parent", b.parent > 0 ? nlohmann::json(b.parent) : nlohmann::json()},
                        {"parent_label", b.parent > 0 ? nlohmann::json(b.parent_label) : nlohmann::json()},
                        {"side", b.side},
                        {"depth", b.depth},
                        {"status", to_string(br.status)},
                        {"message", br.message},
                        {"points", br.points.size()},
                        {"labels", labels},
                        {"range", range},
                        {"data", to_json(b.branch)}});
  }
  for (const DiagramEmanation& e : d.emanations) {
    const SpecialPoint& sp = point_of(d, e);
    nlohmann::json j{{"branch", e.branch},
                     {"label", e.label},
                     {"type", to_string(e.type)},
                     {q, number_or_null(sp.p)},
                     {"mode_l", sp.mode_l ? nlohmann::json(*sp.mode_l) : nlohmann::json()},
                     {"mode_m", sp.mode_m ? nlohmann::json(*sp.mode_m) : nlohmann::json()},
                     {"side", e.side},
                     {"outcome", to_string(e.outcome)},
                     {"branch_to", e.branch_to > 0 ? nlohmann::json(e.branch_to) : nlohmann::json()},
                     {"label_to", e.label_to > 0 ? nlohmann::json(e.label_to) : nlohmann::json()},
                     {"message", outcome_text(e)},
                     {"detail", e.message}};
    points.push_back(std::move(j));
  }
  return {{"format", "rbcstab-diagram"},
          {"version", 1},
          {"kind", to_string(d.start.spec.kind)},
          {"free_parameter", q},
          {"depth", d.depth},
          {"complete", d.complete()},
          {"interrupted", d.interrupted},
          {"start", to_json(d.start.start, is_orbit(d.start.spec.kind))},
          {"branches", branches},
          {"special_points", points}};
}

nlohmann::json diagram_branch_file(const BifurcationDiagram& d, std::size_t k) {
  nlohmann::json j = branch_file_json(ContinuationRun{diagram_run(d, k)});
  const DiagramBranch& b = d.branches[k];
  j["diagram"] = {{"branch", b.number},
                  {"parent", b.parent > 0 ? nlohmann::json(b.parent) : nlohmann::json()},
                  {"parent_label", b.parent > 0 ? nlohmann::json(b.parent_label) : nlohmann::json()},
                  {"side", b.side},
                  {"depth", b.depth}};
  return j;
}

std::string to_text(const BifurcationDiagram& d) {
  std::ostringstream out;
  out << std::setprecision(10);
  const std::string q = to_string(d.start.spec.parameter);
  out << "bifurcation diagram in " << q << " to depth " << d.depth << ": " << d.branches.size() << " branch"
      << (d.branches.size() == 1 ? "" : "es")
      << (d.complete()    ? ""
          : d.interrupted ? " (interrupted: incomplete)"
                          : " (max_branches reached: incomplete)")
      << "\n";
  for (const DiagramBranch& b : d.branches) {
    const Branch& br = b.branch.branch;
    out << "BR " << b.number << "  ";
    if (b.parent == 0)
      out << "start branch";
    else
      out << "from label " << b.parent_label << " of BR " << b.parent << " (side " << side_text(b.side) << ")";
    out << ": " << range_text(br) << ", status " << to_string(br.status);
    if (!br.message.empty()) out << " (" << br.message << ")";
    out << "\n";
  }
  for (const DiagramEmanation& e : d.emanations) {
    const SpecialPoint& sp = point_of(d, e);
    out << to_string(e.type) << " " << e.label << " (BR " << e.branch << ", " << q << " = " << sp.p;
    if (sp.mode_l) out << ", l = " << *sp.mode_l;
    if (sp.mode_l && sp.mode_m) out << ", m = " << *sp.mode_m;
    out << ")" << (e.side != 0 ? " side " + side_text(e.side) : "") << ": " << outcome_text(e) << "\n";
  }
  return out.str();
}

std::vector<std::string> save_diagram(const std::string& path, const BifurcationDiagram& d, const std::string& flag) {
  std::vector<OutputFile> files{{path, to_json(d).dump(1) + "\n", flag}};
  std::vector<std::string> paths;
  for (std::size_t k = 0; k < d.branches.size(); ++k) {
    paths.push_back(branch_path(path, k));
    files.push_back({paths.back(), diagram_branch_file(d, k).dump(1) + "\n", flag});
  }
  write_files_atomic(files);
  // Branch files of an earlier, larger diagram saved under the same name would be drawn with this one by
  // `plot <stem>.b*.json`: they go, but only files that are a diagram's branch files.
  for (std::size_t k = d.branches.size();; ++k) {
    const std::string stale = branch_path(path, k);
    std::error_code ec;
    if (!std::filesystem::is_regular_file(stale, ec)) break;
    const nlohmann::json old = nlohmann::json::parse(read_file(stale, flag), nullptr, /*allow_exceptions=*/false);
    if (!old.is_object() || !old.contains("diagram")) break;
    std::filesystem::remove(stale, ec);
  }
  return paths;
}

BifurcationDiagram parse_diagram(const std::string& tree, const std::vector<std::string>& branch_files,
                                 const std::string& source, const std::string& name) {
  const auto fail = [&](const std::string& why) -> void {
    throw InvalidArgument(name, name + " = '" + source + "' is not a valid diagram: " + why);
  };
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(tree);
  } catch (const nlohmann::json::exception&) {
    fail("it is not JSON (a truncated or corrupted file?)");
  }
  BifurcationDiagram d;
  try {
    if (j.value("format", "") != "rbcstab-diagram") fail("it has no \"format\": \"rbcstab-diagram\"");
    if (j.at("version") != 1) fail("version " + j.at("version").dump() + ": this build reads version 1");
    const nlohmann::json& bs = j.at("branches");
    if (bs.size() != branch_files.size() || bs.empty())
      fail(std::to_string(bs.size()) + " branches but " + std::to_string(branch_files.size()) + " branch files");
    d.depth = j.at("depth").get<int>();
    d.interrupted = j.at("interrupted").get<bool>();
    for (std::size_t k = 0; k < bs.size(); ++k) {
      const ContinuationRun run = parse_branch_file(branch_files[k], branch_path(source, k), name);
      const SceneBranch* r = std::get_if<SceneBranch>(&run);
      if (!r) fail("branch file " + std::to_string(k + 1) + " holds a curve");
      if (k == 0) d.start = *r;
      DiagramBranch b;
      b.number = static_cast<int>(k) + 1;
      b.parent = bs[k].at("parent").is_null() ? 0 : bs[k].at("parent").get<int>();
      b.parent_label = bs[k].at("parent_label").is_null() ? 0 : bs[k].at("parent_label").get<int>();
      b.side = bs[k].at("side").get<int>();
      b.depth = bs[k].at("depth").get<int>();
      if ((k == 0) != (b.parent == 0) || b.parent < 0 || b.parent > static_cast<int>(k))
        fail("branches[" + std::to_string(k) + "].parent " + std::to_string(b.parent) + " is not an earlier branch");
      b.branch = r->branch;
      d.branches.push_back(std::move(b));
    }
    for (const nlohmann::json& e : j.at("special_points")) {
      DiagramEmanation x;
      x.branch = e.at("branch").get<int>();
      x.label = e.at("label").get<int>();
      const auto type = try_from_string<SpecialPointType>(e.at("type").get<std::string>());
      const auto outcome = try_from_string<EmanationOutcome>(e.at("outcome").get<std::string>());
      if (!type || !outcome || x.branch < 1 || x.branch > static_cast<int>(d.branches.size()))
        fail("special point " + e.dump() + " names no branch, type or outcome of this build");
      x.type = *type;
      x.side = e.at("side").get<int>();
      x.outcome = *outcome;
      x.branch_to = e.at("branch_to").is_null() ? 0 : e.at("branch_to").get<int>();
      x.label_to = e.at("label_to").is_null() ? 0 : e.at("label_to").get<int>();
      x.message = e.at("detail").get<std::string>();
      const auto& labels = d.branches[static_cast<std::size_t>(x.branch - 1)].branch.special_labels;
      if (std::find(labels.begin(), labels.end(), x.label) == labels.end())
        fail("special point label " + std::to_string(x.label) + " is not a special point of its branch");
      d.emanations.push_back(std::move(x));
    }
  } catch (const nlohmann::json::exception& e) {
    fail(std::string("a key is missing or of the wrong type (") + e.what() + ")");
  }
  return d;
}

BifurcationDiagram load_diagram(const std::string& path, const std::string& name) {
  const std::string tree = read_file(path, name);
  std::vector<std::string> files;
  const std::size_t n = nlohmann::json::parse(tree, nullptr, false).value("branches", nlohmann::json::array()).size();
  for (std::size_t k = 0; k < n; ++k) files.push_back(read_file(branch_path(path, k), name));
  return parse_diagram(tree, files, path, name);
}

}  // namespace rbcstab
