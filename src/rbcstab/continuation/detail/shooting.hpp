#pragma once
// Multiple shooting shared by the forced (orbit.hpp) and autonomous (autonomous_orbit.hpp) orbit problems: the
// N segment flows of x' = f(t, x, p) over [0, length] from the segments' states, with their variational matrices
// and parameter sensitivities. An autonomous system shoots through the same code as a ForcedSystem that ignores t
// (its segment length T / N is then the only place the period enters).
#include <cstddef>
#include <vector>
#include "rbcstab/continuation/dense.hpp"

#include "rbcstab/continuation/forced_system.hpp"
#include "rbcstab/continuation/orbit.hpp"
#include "rbcstab/integrate/integrator.hpp"

namespace rbcstab::detail {

// The integrator every orbit shooting uses (rk8pd at the options' tolerances and poll).
IntegratorOptions orbit_integrator_options(const OrbitOptions& o);

// Integrates segment j of X = (x_0, ..., x_{N-1}) (x_j at t_j = length j / N) to t_{j+1} with its variational
// equations. Stops at the first failed integration (ok = false). Returns the number of integrations done.
std::size_t shoot_segments(const ForcedSystem& sys, const Eigen::VectorXd& X, double p, int N, double length,
                           const IntegratorOptions& io, ShootingFlows& out);

// The monodromy M_{N-1} ... M_0 of a successful shooting.
Eigen::MatrixXd monodromy_product(const ShootingFlows& sh);
// The linearised solution through v0 at the segments' starts (v_{j+1} = M_j v_j), as the unknowns' layout; NaN
// after a failed shooting.
Eigen::VectorXd segment_variation(const ShootingFlows& sh, const Eigen::VectorXd& v0);
// d phi / dp over all segments of a successful shooting: s_{N-1} + M_{N-1} (s_{N-2} + ...).
Eigen::VectorXd sensitivity_product(const ShootingFlows& sh);

}  // namespace rbcstab::detail
