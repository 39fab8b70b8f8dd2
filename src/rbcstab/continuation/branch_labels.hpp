#pragma once
// A run (ContinuationRun: a branch with its switched branch, or a curve with the branch it started from)
// and its labelled points (AUTO's LAB), which a restart starts from.
#include <cstddef>
#include <string>
#include <variant>
#include <vector>

#include "rbcstab/continuation/scene_branch.hpp"
#include "rbcstab/continuation/scene_curve.hpp"

namespace rbcstab {

// A run whose labelled points a restart starts from: a one-parameter branch (with its switched branch)
// or a curve (with the one-parameter branch it started from).
using ContinuationRun = std::variant<SceneBranch, SceneCurve>;

// A labelled point of a run and where it lies.
struct LabelledPoint {
  int label = 0;
  std::string type;      // "" or "EP" for a point of a branch, else the special point's type ("BP", "UZ", ...)
  int branch = 1;        // 1: the primary (a curve run: the one-parameter) branch; 2: the switched branch or the curve
  bool special = false;  // a special point (index into special_points) or a point (index into points)
  std::size_t index = 0;
};

// Every labelled point of a run, in label order.
std::vector<LabelledPoint> labelled_points(const ContinuationRun& run);
// Throws InvalidArgument("label", ...) listing the run's labels when it has no such label.
LabelledPoint find_label(const ContinuationRun& run, int label, const std::string& flag = "label");
// A label given by its number ("6") or by type and mode, TYPE[:l=L][:m=M] ("BP:l=3", "BP:l=2:m=0", "LP"):
// the one labelled special point of that type whose BP mode is (L, M). Throws InvalidArgument(flag, ...)
// for a malformed selector, and when no point or several points match (listing them with their modes).
int resolve_label(const ContinuationRun& run, const std::string& selector, const std::string& flag = "label");

}  // namespace rbcstab
