#pragma once
// Module-private: the measures of a point of each kind, in the order of measure_names / curve_measure_names,
// and the MeasuredBranch built from them (scene_measures.cpp); the scene problems and curves read them.
#include <functional>
#include <string>
#include <vector>
#include "rbcstab/continuation/dense.hpp"

#include "rbcstab/continuation/continuation.hpp"
#include "rbcstab/continuation/equilibrium.hpp"
#include "rbcstab/continuation/full_equilibrium.hpp"
#include "rbcstab/continuation/modal_equilibrium.hpp"
#include "rbcstab/continuation/modal_orbit.hpp"
#include "rbcstab/continuation/orbit.hpp"
#include "rbcstab/continuation/problem.hpp"
#include "rbcstab/continuation/scene_measures.hpp"

namespace rbcstab::detail {

using Values = std::vector<MeasureValue>;
using Measure = std::function<Values(const Eigen::VectorXd& x, double p)>;

Values polar_values(const Eigen::VectorXd& x);  // of (Re z, Im z, w), the first three unknowns
Values equilibrium_values(const ReducedEquilibriumProblem&, const Eigen::VectorXd& x, double);
Values equilibrium_values(const ModalEquilibriumProblem& pr, const Eigen::VectorXd& x, double p);
Values equilibrium_values(const FullEquilibriumProblem& pr, const Eigen::VectorXd& x, double p);
Values orbit_values(const PeriodicOrbitProblem& pr, const ReducedForcedSystem&, const Eigen::VectorXd& X, double p);
Values orbit_values(const PeriodicOrbitProblem& pr, const ModalForcedSystem& sys, const Eigen::VectorXd& X, double p);
// b with its measures: measure(x, p) of every point and special point, one value per name.
MeasuredBranch measured(Branch b, std::vector<std::string> names, StabilityKind spectrum_kind, const Measure& measure);

}  // namespace rbcstab::detail
