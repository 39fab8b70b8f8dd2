#pragma once
// The post-instability state when the surviving modes are not known in advance, as a
// complementarity problem solved by Ipopt (interior point). Unknowns: the l = 2
// coordinates x_2 = (Re z, Im z, w, Re v, Im v) of modal_equilibrium.hpp, sigma, and the area
// fractions d_l = Delta_l/Delta >= 0 (l = 3..L). Constraints:
//   the five l = 2 equilibrium equations at sigma (linear in x_2 for fixed sigma),
//   |x_2|^2 + sum_l d_l = 1                     (total excess area),
//   Upsilon_l(sigma) <= 0, l = 3..L            (no mode grows),
// and complementarity d_l Upsilon_l(sigma) = 0 as the objective sum_l d_l (-Upsilon_l(sigma)), which is
// >= 0 on the feasible set and 0 exactly at the complementary points. Why a penalty objective and not
// d_l Upsilon_l = 0 as constraints: those equalities violate every constraint qualification (MFCQ) at
// the solution (an MPCC), which stalls interior-point methods or needs a relaxation schedule; as an
// objective the feasible set stays regular and its minimum value 0 certifies the answer. The minimiser
// is unique when the sigma_l^c are distinct: sigma >= max_l sigma_l^c, and either all d_l = 0 (the
// ellipsoid, if it is stable) or sigma = sigma_{l_s}^c with only d_{l_s} > 0.
#include <string>
#include <vector>

#include "rbcstab/continuation/modal_equilibrium.hpp"

namespace rbcstab {

struct ComplementarityOptions {
  double tol = 1e-12;                 // Ipopt's tol on the scaled KKT error: the state to ~1e-10
  int max_iterations = 500;           // Ipopt iterations
  double start_area_fraction = 0.05;  // d_l at the start: interior (> 0) and small against Delta_2
  double surviving_threshold = 1e-8;  // d_l above this counts as a surviving mode (Ipopt leaves ~tol)
  int print_level = 0;                // Ipopt's own output (0: silent; only apps/ print)
  void validate() const;              // throws InvalidArgument naming the field
};

struct ComplementarityResult {
  bool converged = false;  // Ipopt reported Solve_Succeeded (or Solved_To_Acceptable_Level)
  std::string status;      // Ipopt's return status
  std::string message;
  Eigen::VectorXd x;  // the state in ModalEquilibriumProblem coordinates: a_l = +sqrt(d_l) for
                      // surviving modes, 0 for the others (Delta_l keeps Ipopt's raw d_l ~ tol)
  double sigma = 0;
  std::vector<double> Delta_l;          // l = 2..L (index l - 2)
  std::vector<int> surviving;           // modes l >= 3 with d_l > surviving_threshold
  double complementarity = 0;           // sum_l d_l (-Upsilon_l(sigma)) at the solution
  double max_constraint_violation = 0;  // of the equalities and Upsilon_l <= 0
  int iterations = 0;
};

// The modal equilibrium with its surviving modes at the free parameter value p of `problem`.
ComplementarityResult solve_surviving_modes(const ModalEquilibriumProblem& problem, double p,
                                            const ComplementarityOptions& options = {});

// The name of Ipopt's return status (Ipopt::ApplicationReturnStatus as an int), for every Ipopt caller's
// result: "Solve_Succeeded", ...; an unnamed one as "Ipopt status N".
std::string ipopt_status_name(int status);

}  // namespace rbcstab
