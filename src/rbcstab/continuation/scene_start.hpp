#pragma once
// How a scene branch starts (StartPoint, find_start): the kind's start or a restart's given state, solved
// by Newton where the kind needs it, with its certified stability.
#include <limits>
#include <string>
#include "rbcstab/continuation/dense.hpp"

#include "rbcstab/continuation/branch_spec.hpp"
#include "rbcstab/continuation/continuation.hpp"
#include "rbcstab/core/enum_table.hpp"
#include "rbcstab/model/scene.hpp"

namespace rbcstab {

// How a branch starts from its scene. equilibrium: the scene relaxed for relax_T (on the stable branch
// when one attracts it); modal: the ellipsoidal equilibrium's closed form; full: the closed form without
// stress-free l >= 3 content, else the scene relaxed by the full model (Newton from the ellipsoid may land
// on an unstable member of the unfolded pitchfork); orbits: the relaxed state's shooting guess. Full and
// orbits are then solved by Newton at fixed parameter; the other kinds leave that to the engine's start.
enum class StartMethod { relaxed, ellipsoidal, restart };  // restart: BranchSpec::start_state
template <>
struct EnumTable<StartMethod> {
  static constexpr EnumName<StartMethod> entries[] = {
      {StartMethod::relaxed, "relaxed"}, {StartMethod::ellipsoidal, "ellipsoidal"}, {StartMethod::restart, "restart"}};
};
struct StartPoint {
  StartMethod method = StartMethod::relaxed;
  Eigen::VectorXd x;      // the problem's unknowns (orbits: the shooting vector)
  double p = 0;           // the free parameter's start value
  bool newton = false;    // Newton at fixed p solved x (full, orbits)
  bool converged = true;  // false: no solution near the start state; message says which
  int iterations = 0;
  double residual_norm = 0;
  // Orbits: the relaxation before Newton (BranchSpec::relax_tol).
  int relaxation_periods = 0;  // forcing periods relaxed in all (relax_T's and the adaptive ones)
  double periodicity_defect = std::numeric_limits<double>::quiet_NaN();  // of the last period relaxed
  double periodicity_tol = std::numeric_limits<double>::quiet_NaN();     // spec.relax_tol
  bool relaxed = false;  // the defect fell below the tolerance within relax_max_periods
  // The solution's stability at the start (equilibria: after Newton at fixed p from x), certified as
  // every branch point is (certify_solution); stable and n_unstable as BranchPoint's.
  bool stable = true;
  int n_unstable = 0;
  Stability stability = Stability::uncertain;
  double margin = std::numeric_limits<double>::quiet_NaN();
  double margin_error = std::numeric_limits<double>::quiet_NaN();
  CertificateTerm uncertain_because = CertificateTerm::spectrum;
  bool refused = false;  // an orbit certified unstable without spec.allow_unstable_start: not continued
  // Why it failed or was refused; else a note (an unstable or uncertain start, a relaxation that
  // reached its bound), or empty.
  std::string message;
};
StartPoint find_start(const BranchSpec& spec);  // validates spec

// The scene the problem is built from: a modal orbit's Delta is the simulated scene's total excess area
// (spec.scene as it is for a restart).
Scene problem_scene_of(const BranchSpec& spec);

}  // namespace rbcstab
