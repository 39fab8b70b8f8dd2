#pragma once
// Certified early termination of a scene run. simulate() (integrate/simulation.hpp) asks an attractor
// certifier at its accepted steps; this one, at the modal and reduced levels, certifies that the state has
// reached an attracting periodic orbit of the level being integrated (period 2 pi in the level's frame; an
// equilibrium is one of any period) and lets the run resume on that orbit whole periods later, before the
// tail window, so that Delta_l(T), sigma(T), r(T), Psi(T) and the tail means are integrated along the orbit at
// the phase the full run would have.
//
// A certificate needs, at a state x (regular coordinates, |x| = 1: ModalForcedSystem, ReducedForcedSystem):
//  - x within max_distance of the orbit: modes l >= 3 with |a_l| <= max_distance count as decayed (on the
//    orbit they are zero and decouple, a_l' = Upsilon_l(sigma) a_l); the l = 2 block and the other modes
//    (ModalSubsystem) are refined by the chord Newton iteration of refine_periodic_orbit to a residual below
//    its tolerance, with a chord contraction below its bound (the linearisation holds);
//  - every nontrivial Floquet multiplier of the refined orbit, and exp(2 pi <Upsilon_l(sigma)>) of every
//    decayed mode, below exp(-min_rate 2 pi) by more than its error bound (certify, continuation.hpp): a
//    near-neutral direction (|Upsilon_l| small, a multiplier near 1) gives no certificate;
//  - the linear decay bound |M^k| |x - x*| after the k skipped periods below the state tolerance;
//  - the distance (decayed modes included) below sqrt(state tolerance) as well: the skip is exact to first order
//    in it, so its second-order error (a decayed mode's area acting on sigma, the curvature along the approach)
//    stays within the state tolerance and the outputs converge with rtol. The refined orbit's residual and its
//    period map follow the state tolerance too.
// The resumed state is the refined orbit's (scaled to the area the decayed modes leave), and each decayed
// mode's ln Delta_l advanced by 2 k 2 pi Upsilon_l(<sigma>) over the orbit: exact to first order, so Delta_l(T)
// of a decayed mode keeps its relative accuracy.
// The full level is never certified (its runs go to T). Attempts follow a schedule that grows geometrically
// after failures, guided by the periodicity defect of one cheap period.
#include <numbers>

#include "rbcstab/analysis/truncation.hpp"
#include "rbcstab/continuation/attractor.hpp"
#include "rbcstab/core/constants.hpp"
#include "rbcstab/integrate/simulation.hpp"
#include "rbcstab/io/scene_file.hpp"
#include "rbcstab/model/scene.hpp"

namespace rbcstab {

struct EarlyTerminationOptions {
  // Slowest decay rate a certificate accepts: every multiplier |mu| + error <= exp(-min_rate period).
  double min_rate = 1e-3;
  // Linearisation radius |x - x*| (|x| = 1), decayed modes included; the radius used is at most
  // sqrt(state tolerance), so that the skip's second-order error stays below that tolerance.
  double max_distance = 1e-3;
  double state_tolerance = 0;      // decay bound at the resume time; 0: the run's rtol / 10 (the factor 10
                                   // covers growth within a period, which the bound at whole periods misses)
  double first_attempt = 4 * kPi;  // no attempt before this time
  double attempt_growth = 1.25;    // after a failed attempt at t, none before max(growth t, t + period)
  IntegratorOptions screen = {Stepper::rk8pd, 1e-6, 1e-9};  // the one-period defect before a refinement
  PeriodicRefinementOptions refinement;  // its period is replaced by 2 pi, the forcing period of both levels
  void validate() const;                 // throws InvalidArgument naming the field
};

// simulate(scene, options, certifier) with this module's certifier (options.full_horizon: a plain run to T,
// with the note saying so). Throws what simulate throws.
SimulationResult simulate_certified(const Scene& scene, const SimulationOptions& options = {},
                                    const EarlyTerminationOptions& early = {});
SimulationResult simulate_certified(const ValidScene& scene, const SimulationOptions& options = {},
                                    const EarlyTerminationOptions& early = {});

// truncation_transient (analysis/truncation.hpp) with the certified early stop: the reduced run stops integrating
// once this module's certifier (the main run's, on the reduced level) certifies its attractor, and resumes on the
// orbit at most a period before T. A checkpoint t it skipped, t = t_s + m P + rem after the stop at t_s, gets
// J(t_s) + m I + [J(t_r + rem) - J(t_r)] with I the orbit's integral of sigma over a period and t_r the resume time:
// exact to first order in the certified distance, as the skip of a run. Its cost no longer grows with T. Without a
// certificate (or T below the first attempt plus two periods) it is truncation_transient.
ReducedTransient certified_transient(const ValidScene& scene, const TruncationOptions& options = {},
                                     const EarlyTerminationOptions& early = {});

// One scene file run as every front end runs it (simulate, summary, Python): the checked automatic L
// (simulate_truncated) from the certified_transient (the full one when options.full_horizon), the candidate and then
// the run at the L kept both certified (simulate_certified).
// Sets file.scene.L, L_reason and truncation_check as simulate_truncated does.
SimulationResult simulate_scene(SceneFile& file, const SimulationOptions& options,
                                const ReducedTransient* transient = nullptr);
// The same for a file already checked: valid = validated(file) (io), which the run does not check again.
SimulationResult simulate_scene(SceneFile& file, const ValidScene& valid, const SimulationOptions& options,
                                const ReducedTransient* transient = nullptr);

// apply_truncation (analysis/truncation.hpp) deciding a simulation's automatic L as simulate_scene does: from the
// certified_transient and a certified candidate run (the full-horizon ones when file.options.full_horizon). For a
// front end that runs the scene itself afterwards (report, shape): the L and L_reason are simulate_scene's.
void apply_scene_truncation(SceneFile& file, TruncationUse use);
// The scene's reduced transient over [0, T] (TruncationOptions{} checkpoints), as the summary's finite-horizon
// predictor and automatic L read it: certified_transient, or truncation_transient when full_horizon.
ReducedTransient scene_transient(const ValidScene& scene, bool full_horizon);

}  // namespace rbcstab
