#pragma once
// The measures of a scene branch's points by name (measure_names per kind, curve_measure_names per curve
// system) and MeasuredBranch, the branch with its measures and labels that every rendering and plot reads.
#include <cstddef>
#include <string>
#include <string_view>
#include <variant>
#include <vector>
#include "rbcstab/continuation/dense.hpp"

#include "rbcstab/continuation/continuation.hpp"
#include "rbcstab/continuation/problem.hpp"
#include "rbcstab/continuation/scene_kinds.hpp"

namespace rbcstab {

// A named measure of a point: a number, an integer (winding, mode) or a label (orbit kind).
using MeasureValue = std::variant<double, int, std::string>;

// The measures of a point of a branch of `kind` (L: the scene's truncation), in output order:
//   equilibrium: r, Psi;  modal, full: r, Psi, sigma, Delta_2 ... Delta_L;
//   orbit: r, Psi (t = 0), r_min, r_max, Psi_min, Psi_max, winding, kind, trivial_multiplier;
//   modal_orbit: r, Psi, sigma, Delta_2 ... Delta_L (t = 0), winding, kind, trivial_multiplier.
std::vector<std::string> measure_names(ProblemKind kind, int L);
// The measures of a point of a curve continued by `system` from a branch of `kind`: an equilibrium's
// measures (plus omega on a Hopf curve); for orbits r, Psi at t = 0 (plus sigma_bar, mode on the
// ellipsoidal-orbit BP curve; t_passage on the event curve: the time of the passage through z = 0,
// continuous along the curve, not reduced mod 2 pi).
std::vector<std::string> curve_measure_names(ProblemKind kind, CurveSystem system, int L);
// Whether a measure is a CSV column: not trivial_multiplier, a check of the shooting (1 up to rounding)
// rather than a property of the orbit, which JSON carries.
bool is_csv_measure(std::string_view name);

// A branch (or curve) and its points' measures: what every rendering and plot reads. The points keep
// their parameters, full state x, spectrum and stability (Branch); measures are aligned with measure_names.
struct MeasuredBranch {
  Branch branch;
  StabilityKind spectrum_kind = StabilityKind::eigenvalues;  // eigenvalues or Floquet multipliers
  std::vector<std::string> measure_names;
  std::vector<std::vector<MeasureValue>> point_measures;    // [k]: of branch.points[k]
  std::vector<std::vector<MeasureValue>> special_measures;  // [k]: of branch.special_points[k]
  // Labels (AUTO's LAB): positive integers, unique over a run (a branch, its switched branch, a curve and
  // the branch it started from), on every special point, on the two ends of the branch and on every
  // label_every-th point counted from the first; 0: an unlabelled point. Numbered along the branch.
  std::vector<int> point_labels;    // [k]: of branch.points[k]
  std::vector<int> special_labels;  // [k]: of branch.special_points[k]
  // The label of point k / special point k (0 when unlabelled or labels were never assigned).
  int point_label(std::size_t k) const;
  int special_label(std::size_t k) const;
  // "EP" for the first and the last point of the branch, "" for a regular point.
  std::string point_type(std::size_t k) const;
  int last_label() const;  // the largest label, 0 if none
  // The measure `name` of point k; throws InvalidArgument("measure", ...) for an unknown name.
  const MeasureValue& measure(std::size_t k, std::string_view name) const;
  // The same as a number (integers converted); throws InvalidArgument("measure", ...) for a label.
  double number(std::size_t k, std::string_view name) const;
};

}  // namespace rbcstab
