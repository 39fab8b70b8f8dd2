// The measures of a point of each kind by name (measure_names, curve_measure_names) and their values, in
// that order; MeasuredBranch's measures by name.
#include "rbcstab/continuation/scene_measures.hpp"

#include <cmath>
#include <stdexcept>
#include <utility>

#include "rbcstab/continuation/detail/scene_measures.hpp"
#include "rbcstab/core/error.hpp"

namespace rbcstab {

namespace {

using detail::Values;

template <class State>  // ModalState, FullEquilibriumState
Values modal_values(const State& st) {
  Values v{st.r, st.Psi, st.sigma};
  for (double D : st.Delta_l) v.emplace_back(D);
  return v;
}

// winding, kind, trivial_multiplier (NaN when the system conserves no norm).
void append_cycle_values(Values& v, const OrbitSummary& s, const Floquet& f) {
  v.emplace_back(s.winding);
  v.emplace_back(to_string(s.kind));
  v.emplace_back(f.trivial ? *f.trivial : std::nan(""));
}

}  // namespace

namespace detail {

// ---- the measures of a point, in the order of measure_names / curve_measure_names ----

Values polar_values(const Eigen::VectorXd& x) {  // of (Re z, Im z, w), the first three unknowns
  const PolarState s = polar(x.head(3));
  return {s.r, s.Psi};
}

Values equilibrium_values(const ReducedEquilibriumProblem&, const Eigen::VectorXd& x, double) {
  return polar_values(x);
}
Values equilibrium_values(const ModalEquilibriumProblem& pr, const Eigen::VectorXd& x, double p) {
  return modal_values(pr.observe(x, p));
}
Values equilibrium_values(const FullEquilibriumProblem& pr, const Eigen::VectorXd& x, double p) {
  return modal_values(pr.observe(x, p));
}

Values orbit_values(const PeriodicOrbitProblem& pr, const ReducedForcedSystem&, const Eigen::VectorXd& X, double p) {
  const OrbitSummary s = pr.summary(X, p);
  Values v{s.r0, s.Psi0, s.r_min, s.r_max, s.Psi_min, s.Psi_max};
  append_cycle_values(v, s, pr.floquet(X, p));
  return v;
}
Values orbit_values(const PeriodicOrbitProblem& pr, const ModalForcedSystem& sys, const Eigen::VectorXd& X, double p) {
  Values v = modal_values(sys.observe(0.0, pr.state_at_zero(X), p));
  append_cycle_values(v, pr.summary(X, p), pr.floquet(X, p));
  return v;
}

MeasuredBranch measured(Branch b, std::vector<std::string> names, StabilityKind spectrum_kind, const Measure& measure) {
  MeasuredBranch m;
  m.spectrum_kind = spectrum_kind;
  m.measure_names = std::move(names);
  auto row = [&](const Eigen::VectorXd& x, double p) {
    Values v = measure(x, p);
    if (v.size() != m.measure_names.size())
      throw std::logic_error("measures: " + std::to_string(v.size()) + " values for " +
                             std::to_string(m.measure_names.size()) + " names");
    return v;
  };
  for (const BranchPoint& pt : b.points) m.point_measures.push_back(row(pt.x, pt.p));
  for (const SpecialPoint& sp : b.special_points) m.special_measures.push_back(row(sp.x, sp.p));
  m.branch = std::move(b);
  return m;
}

}  // namespace detail

std::vector<std::string> measure_names(ProblemKind kind, int L) {
  std::vector<std::string> names{"r", "Psi"};
  if (model_level(kind) != ModelLevel::reduced) {
    names.emplace_back("sigma");
    for (int l = 2; l <= L; ++l) names.push_back("Delta_" + std::to_string(l));
  }
  if (kind == ProblemKind::orbit) names.insert(names.end(), {"r_min", "r_max", "Psi_min", "Psi_max"});
  if (is_orbit(kind)) names.insert(names.end(), {"winding", "kind", "trivial_multiplier"});
  return names;
}

std::vector<std::string> curve_measure_names(ProblemKind kind, CurveSystem system, int L) {
  if (is_orbit(kind)) {
    std::vector<std::string> names{"r", "Psi"};
    if (system == CurveSystem::ellipsoidal_orbit_branch_point) names.insert(names.end(), {"sigma_bar", "mode"});
    if (system == CurveSystem::event) names.emplace_back("t_passage");
    return names;
  }
  std::vector<std::string> names = measure_names(kind, L);
  if (system == CurveSystem::hopf) names.emplace_back("omega");
  return names;
}

bool is_csv_measure(std::string_view name) { return name != "trivial_multiplier"; }

const MeasureValue& MeasuredBranch::measure(std::size_t k, std::string_view name) const {
  for (std::size_t i = 0; i < measure_names.size(); ++i)
    if (measure_names[i] == name) return point_measures.at(k).at(i);
  std::string list;
  for (const auto& n : measure_names) list += (list.empty() ? "" : ", ") + n;
  throw InvalidArgument(
      "measure", "measure = '" + std::string(name) + "' is not a measure of this branch: must be one of " + list);
}

double MeasuredBranch::number(std::size_t k, std::string_view name) const {
  const MeasureValue& v = measure(k, name);
  if (const double* d = std::get_if<double>(&v)) return *d;
  if (const int* i = std::get_if<int>(&v)) return *i;
  throw InvalidArgument("measure", "measure = '" + std::string(name) + "' is a label, not a number");
}

}  // namespace rbcstab
