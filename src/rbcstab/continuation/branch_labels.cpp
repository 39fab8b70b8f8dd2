// Labels (AUTO's LAB): numbering a branch's points, MeasuredBranch's labels, and a run's labelled points.
#include "rbcstab/continuation/branch_labels.hpp"

#include <algorithm>
#include <cctype>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "rbcstab/continuation/detail/branch_labels.hpp"
#include "rbcstab/core/error.hpp"

namespace rbcstab {

namespace {

using detail::branch_of;

// "its labels are 1 to 12" or the list.
std::string label_list(const std::vector<LabelledPoint>& all) {
  if (all.empty()) return "it has no labels";
  bool contiguous = true;
  for (std::size_t i = 0; i < all.size(); ++i) contiguous = contiguous && all[i].label == static_cast<int>(i) + 1;
  if (contiguous) return "its labels are 1 to " + std::to_string(all.size());
  std::string list;
  for (const LabelledPoint& p : all) list += (list.empty() ? "" : ", ") + std::to_string(p.label);
  return "its labels are " + list;
}

// "6 (BP l = 3)": a label with its type and mode, for the lists of resolve_label's messages.
std::string described(const ContinuationRun& run, const LabelledPoint& p) {
  std::string t = std::to_string(p.label) + " (" + (p.type.empty() ? "regular" : p.type);
  if (p.special) {
    const SpecialPoint& sp = branch_of(run, p.branch)->branch.special_points[p.index];
    if (sp.mode_l) t += " l = " + std::to_string(*sp.mode_l);
    if (sp.mode_m) t += " m = " + std::to_string(*sp.mode_m);
  }
  return t + ")";
}

// A selector's integer field ("l=3"): an integer in [0, 1000].
int selector_int(const std::string& text, const std::string& flag, const std::string& selector) {
  const bool digits = !text.empty() && text.size() <= 4 &&
                      std::all_of(text.begin(), text.end(), [](unsigned char c) { return std::isdigit(c) != 0; });
  if (!digits || std::stoi(text) > 1000)
    throw InvalidArgument(flag, flag + " = '" + selector + "': '" + text + "' must be an integer in [0, 1000]");
  return std::stoi(text);
}

}  // namespace

namespace detail {

int label_branch(MeasuredBranch& m, int label_every, int next) {
  const auto& pts = m.branch.points;
  const auto& sps = m.branch.special_points;
  m.point_labels.assign(pts.size(), 0);
  m.special_labels.assign(sps.size(), 0);
  std::size_t j = 0;
  for (std::size_t k = 0; k < pts.size(); ++k) {
    if (!m.point_type(k).empty() || (label_every > 0 && k % static_cast<std::size_t>(label_every) == 0))
      m.point_labels[k] = next++;
    for (; j < sps.size() && sps[j].after_index <= k; ++j) m.special_labels[j] = next++;
  }
  for (; j < sps.size(); ++j) m.special_labels[j] = next++;
  return next;
}

const MeasuredBranch* branch_of(const ContinuationRun& run, int b) {
  if (const SceneCurve* c = std::get_if<SceneCurve>(&run)) return b == 1 ? &c->one.branch : &c->curve;
  const SceneBranch& r = std::get<SceneBranch>(run);
  if (b == 1) return &r.branch;
  return r.switched ? &r.switched->branch : nullptr;
}

int run_last_label(const SceneBranch& r) {
  return std::max(r.branch.last_label(), r.switched ? r.switched->branch.last_label() : 0);
}

int run_last_label(const ContinuationRun& run) {
  if (const SceneCurve* c = std::get_if<SceneCurve>(&run))
    return std::max(run_last_label(c->one), c->curve.last_label());
  return run_last_label(std::get<SceneBranch>(run));
}

}  // namespace detail

int MeasuredBranch::point_label(std::size_t k) const { return k < point_labels.size() ? point_labels[k] : 0; }

int MeasuredBranch::special_label(std::size_t k) const { return k < special_labels.size() ? special_labels[k] : 0; }

std::string MeasuredBranch::point_type(std::size_t k) const {
  return k == 0 || k + 1 == branch.points.size() ? to_string(SpecialPointType::EP) : "";
}

int MeasuredBranch::last_label() const {
  int m = 0;
  for (int l : point_labels) m = std::max(m, l);
  for (int l : special_labels) m = std::max(m, l);
  return m;
}

std::vector<LabelledPoint> labelled_points(const ContinuationRun& run) {
  std::vector<LabelledPoint> out;
  for (int b = 1; b <= 2; ++b) {
    const MeasuredBranch* m = branch_of(run, b);
    if (!m) continue;
    for (std::size_t k = 0; k < m->branch.points.size(); ++k)
      if (const int l = m->point_label(k)) out.push_back({l, m->point_type(k), b, false, k});
    for (std::size_t k = 0; k < m->branch.special_points.size(); ++k)
      if (const int l = m->special_label(k))
        out.push_back({l, to_string(m->branch.special_points[k].type), b, true, k});
  }
  std::sort(out.begin(), out.end(), [](const LabelledPoint& a, const LabelledPoint& b) { return a.label < b.label; });
  return out;
}

LabelledPoint find_label(const ContinuationRun& run, int label, const std::string& flag) {
  const std::vector<LabelledPoint> all = labelled_points(run);
  for (const LabelledPoint& p : all)
    if (p.label == label) return p;
  throw InvalidArgument(flag, flag + " = " + std::to_string(label) + " is not a label of this run: " + label_list(all));
}

int resolve_label(const ContinuationRun& run, const std::string& selector, const std::string& flag) {
  const std::string form = "a label, an integer in [1, 1000000000], or TYPE[:l=L][:m=M] (e.g. BP:l=3)";
  if (!selector.empty() &&
      std::all_of(selector.begin(), selector.end(), [](unsigned char c) { return std::isdigit(c) != 0; })) {
    if (selector.size() > 10 || std::stoll(selector) < 1 || std::stoll(selector) > 1000000000)
      throw InvalidArgument(flag, flag + " = '" + selector + "' must be " + form);
    return static_cast<int>(std::stoll(selector));
  }
  std::vector<std::string> parts;
  for (std::size_t a = 0, b = 0; b != std::string::npos; a = b + 1) {
    b = selector.find(':', a);
    parts.push_back(selector.substr(a, b == std::string::npos ? std::string::npos : b - a));
  }
  const std::string& type = parts.front();
  if (type.empty() || !std::all_of(type.begin(), type.end(), [](unsigned char c) { return std::isupper(c) != 0; }))
    throw InvalidArgument(flag, flag + " = '" + selector + "' must be " + form);
  std::optional<int> l, m;
  for (std::size_t i = 1; i < parts.size(); ++i) {
    const std::string& f = parts[i];
    std::optional<int>& field = f.rfind("l=", 0) == 0 ? l : m;
    if ((f.rfind("l=", 0) != 0 && f.rfind("m=", 0) != 0) || field)
      throw InvalidArgument(flag, flag + " = '" + selector + "': '" + f + "' must be l=L or m=M, each at most once");
    field = selector_int(f.substr(2), flag, selector);
  }
  const std::vector<LabelledPoint> all = labelled_points(run);
  std::vector<LabelledPoint> hits, of_type;
  for (const LabelledPoint& p : all) {
    if (p.type != type) continue;
    of_type.push_back(p);
    const SpecialPoint* sp = p.special ? &branch_of(run, p.branch)->branch.special_points[p.index] : nullptr;
    if ((l && (!sp || sp->mode_l != l)) || (m && (!sp || sp->mode_m != m))) continue;
    hits.push_back(p);
  }
  if (hits.size() == 1) return hits.front().label;
  std::string list;
  for (const LabelledPoint& p : hits.empty() ? of_type : hits) list += (list.empty() ? "" : ", ") + described(run, p);
  if (hits.empty())
    throw InvalidArgument(
        flag, flag + " = '" + selector + "' matches no labelled point of this run: " +
                  (list.empty() ? "it has no point of type " + type : "its " + type + " labels are " + list));
  throw InvalidArgument(flag, flag + " = '" + selector + "' matches " + std::to_string(hits.size()) +
                                  " labelled points, " + list + ": give the label or the mode (:l=L, :m=M)");
}

}  // namespace rbcstab
