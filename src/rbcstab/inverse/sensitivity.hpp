#pragma once
// Sensitivities of the in-plane observables from the variational equations of the attracting 2 pi-periodic orbit
// (docs/inverse.md "Sensitivities"). The reduced l = 2 system depends on the parameters only through a = 1/Lambda
// and kappa = 1/(Lambda S) (ReducedModel::coefficient_derivatives), so each observable's derivative is two numbers
// per condition, chained through the closed-form physical map to the fitted coordinates.
#include <array>
#include <span>
#include <string>
#include <vector>

#include "rbcstab/core/enum_table.hpp"
#include "rbcstab/inverse/forward.hpp"

namespace rbcstab {

// How the fit's Jacobian is taken: the variational equations for the in-plane rows (the other rows, e.g. the
// transition shear rate, by central differences), or central differences for every row.
enum class JacobianMethod { variational, finite_difference };
template <>
struct EnumTable<JacobianMethod> {
  static constexpr EnumName<JacobianMethod> entries[] = {{JacobianMethod::variational, "variational"},
                                                         {JacobianMethod::finite_difference, "finite_difference"}};
};

// d/da and d/dkappa of the orbit's mean psi and swinging amplitude (rad), from one period of the orbit with its
// monodromy M and parameter sensitivities eta_p: the periodic orbit's shift solves (I - M) dx0 = eta_p(2 pi) on the
// sphere's tangent plane (x0 . dx0 = 0: |x|^2 is conserved, M has the trivial multiplier 1 along it).
struct OrbitSensitivity {
  bool ok = false;
  std::string reason;
  double mean_invL = 0, mean_kappa = 0;            // d mean_psi / d(1/Lambda), d mean_psi / d kappa
  double amplitude_invL = 0, amplitude_kappa = 0;  // the same for amplitude_psi
  double multiplier = kNotGiven;                   // the largest |nontrivial Floquet multiplier|
};
// `m`: a converged swinging or tank-treading in_plane_motion at p (its orbit_state and extremum times).
OrbitSensitivity orbit_sensitivity(const Parameters& p, const InPlaneMotion& m, const ForwardOptions& options);

// d(1/Lambda)/dx and d kappa/dx at one condition for the fitted coordinate x of `q` (ln q for a log-scaled
// parameter): central differences of the closed-form map (condition_parameters, Parameters::Lambda and
// inv_Lambda_S) at a step of 1e-6 (max(1, |x|)), whose error (~1e-10 relative) is far below the orbit's.
std::array<double, 2> coefficient_gradient(const CellModel& cell, FitParameter q, bool log_scale, double shear_rate,
                                           double viscosity);

}  // namespace rbcstab
