#pragma once
// Shared by the ellipsoidal-orbit BP curve tests and benchmark (modal_orbit_bp_curve.hpp): the in-plane
// modal scene, a point of the Z2-reduced curve, and the BP located on the modal orbit branch.
#include <cmath>
#include <optional>

#include "rbcstab/continuation/continuation.hpp"
#include "rbcstab/continuation/modal_orbit_bp_curve.hpp"
#include "rbcstab/continuation/orbit_two_parameter.hpp"
#include "rbcstab/continuation/two_parameter.hpp"

namespace rbcstab::test {

// The paper's in-plane scene (Fig. 2 parameters: Delta = 1, Delta0 = 0.01), rest shape in the flow plane.
inline Scene in_plane_modal(double lambda, double B, double C, int L) {
  Scene s;
  s.name = "zbp";
  s.parameters.lambda = lambda;
  s.parameters.Delta = 1;
  s.parameters.Delta0 = 0.01;
  s.parameters.B = B;
  s.parameters.C = C;
  s.beta = M_PI / 2;
  s.L = L;
  s.model = ModelLevel::modal;
  return s;
}

// The curve's point near (C_guess, B): the reduced orbit at C_guess, then Newton on the curve system
// (not converged if either Newton fails).
inline NewtonResult curve_point(const ModalOrbitBranchPointCurve& curve, const Scene& s, double C_guess, double B) {
  const Scene at = with_parameter(with_parameter(s, ContinuationParameter::B, B), ContinuationParameter::C, C_guess);
  const ReducedForcedSystem red(at, ContinuationParameter::C);
  const PeriodicOrbitProblem rp(red);
  const NewtonResult rn = solve_fixed_parameter(rp, rp.shooting_guess(red.relaxed_state(200), C_guess), C_guess);
  if (!rn.converged) return rn;
  Eigen::VectorXd X(curve.dimension());
  X << rn.x, C_guess;
  return solve_fixed_parameter(curve, X, B);
}

// The one-parameter run in C (backward from s's C down to C_min, at s's B) of the modal orbit started
// from the embedded ellipsoidal orbit (a_l = 0, v~ = 0), and its located BP (none: bp empty).
struct EllipsoidalOrbitBP {
  bool start_converged = false;
  Branch branch;
  std::optional<SpecialPoint> bp;
};
inline EllipsoidalOrbitBP locate_ellipsoidal_orbit_bp(const ModalForcedSystem2& sys2, const Scene& s, double C_min,
                                                      const OrbitOptions& oo) {
  const double C0 = s.parameters.C, B0 = s.parameters.B;
  const OrbitTwoParameterProblem base(sys2, oo);
  const SliceProblem slice(base, B0);
  const ReducedForcedSystem red(s, ContinuationParameter::C);
  const PeriodicOrbitProblem rp(red);
  EllipsoidalOrbitBP out;
  const NewtonResult rn = solve_fixed_parameter(rp, rp.shooting_guess(red.relaxed_state(200), C0), C0);
  if (!rn.converged) return out;
  Eigen::VectorXd x0 = Eigen::VectorXd::Zero(sys2.dimension());
  x0.head(3) = rp.state_at_zero(rn.x);
  const PeriodicOrbitProblem mp(sys2.at(B0), oo);
  const NewtonResult mn = solve_fixed_parameter(slice, mp.shooting_guess(x0, C0), C0);
  out.start_converged = mn.converged;
  if (!mn.converged) return out;
  ContinuationOptions o;
  o.p_min = C_min;
  o.p_max = 1.1 * C0;
  o.direction = Direction::backward;
  o.initial_step = 0.002;
  o.max_step = 0.005;
  out.branch = continue_branch(slice, mn.x, C0, o);
  const SpecialPoint* bp = find_special_point(out.branch, SpecialPointType::BP);
  if (bp && bp->status == LocationStatus::located) out.bp = *bp;
  return out;
}

}  // namespace rbcstab::test
