#pragma once
// Normal forms at the special points of orbit branches (LPC, PD, NS): those of the period map P of a forced orbit
// (x0 -> the state after the orbit's period 2 pi k, one shooting of the trajectory through x0 at t = 0), with A = DP
// the monodromy, or of the Poincare map of an autonomous orbit (poincare_map.hpp: on the section through x0 normal
// to f(x0), the trivial multiplier dropped); B, C its second and third derivatives by central differences of
// shootings. Formulas (Kuznetsov, Elements of Applied Bifurcation Theory, the map cases), steps and checks:
// docs/continuation.md, "Normal forms". Amplitude laws are in x0 (the state at t = 0; for an autonomous orbit the
// point on the section), |x0 - x0*|_2.
#include "rbcstab/continuation/autonomous_orbit.hpp"
#include "rbcstab/continuation/continuation.hpp"
#include "rbcstab/continuation/normal_form.hpp"
#include "rbcstab/continuation/orbit.hpp"

namespace rbcstab {

// The difference steps, in units of 1 + |x0|_inf: second differences at `second` and second / 2, third differences at
// `third` and third / 2, each pair Richardson-extrapolated (the O(h^2) errors carry P's fourth and fifth derivatives,
// large over a period of 2 pi). A shooting is accurate to ~1e-11 relative (rtol 1e-12): rounding stays below 1e-6
// of the terms.
struct PeriodMapSteps {
  double second = 1e-3;
  double third = 2.5e-3;
  void validate() const;  // throws InvalidArgument naming the field: each finite, in (0, 0.1]
};

// LPC (fold of cycles, multiplier 1) at X: the fold of P(x0, p) - x0 (fold_normal_form's coefficients a, w_Fp, p2
// with J = A - I and F_p = P_p; x0 - x0* = s v, p = p* + p2 s^2), kind fold_of_cycles. Criticality not_applicable.
NormalForm fold_of_cycles_normal_form(const PeriodicOrbitProblem& problem, const Eigen::VectorXd& X, double p,
                                      const PeriodMapSteps& steps = {});

// PD (flip, multiplier -1) at X: eta -> -eta + c eta^3 on the centre manifold, "c" = <w, C(q, q, q)> / 6 +
// <w, B(q, h2)> / 2, h2 = (I - A)^{-1} B(q, q) (A q = -q, A^T w = -w, |q| = 1, <w, q> = 1); "mu_p" = d mu / dp =
// <w, D^2 P[(q, 0), (x_p, 1)]>, x_p = (I - A)^{-1} P_p. c > 0: supercritical (the doubled orbit exists where the
// orbit is unstable, and is stable); c < 0: subcritical. Amplitude law of the doubled orbit: x0 = x0* +- eta q,
// eta^2 = -mu_p (p - p*) / c.
NormalForm period_doubling_normal_form(const PeriodicOrbitProblem& problem, const Eigen::VectorXd& X, double p,
                                       const PeriodMapSteps& steps = {});

// NS (multipliers e^{+-i theta}) at X: z -> e^{i theta} z (1 + d |z|^2) + ..., "d" = Re(e^{-i theta} c1),
// c1 = <p, C(q, q, qb) + 2 B(q, (I - A)^{-1} B(q, qb)) + B(qb, (e^{2 i theta} I - A)^{-1} B(q, q))> / 2 (A q = e^{i
// theta} q, A^T p = e^{-i theta} p, <q, q> = 1, <p, q> = 1); "theta"; "modulus_p" = d|mu|/dp. d < 0:
// supercritical (a stable invariant circle of P where the orbit is unstable); d > 0: subcritical. Degenerate at the
// strong resonances e^{i k theta} = 1, k <= 4. Amplitude law of the invariant circle's peak (x0 = x0* + 2 Re(z q),
// |z|^2 = -modulus_p (p - p*) / d), as for a Hopf orbit.
NormalForm neimark_sacker_normal_form(const PeriodicOrbitProblem& problem, const Eigen::VectorXd& X, double p,
                                      const PeriodMapSteps& steps = {});

// The same of an autonomous orbit X (its period is X's last unknown): the Poincare map's, in orthonormal coordinates
// of the section (lengths as in x). Throws InvalidArgument for bad steps or f(x0) = 0.
NormalForm fold_of_cycles_normal_form(const AutonomousOrbitProblem& problem, const Eigen::VectorXd& X, double p,
                                      const PeriodMapSteps& steps = {});
NormalForm period_doubling_normal_form(const AutonomousOrbitProblem& problem, const Eigen::VectorXd& X, double p,
                                       const PeriodMapSteps& steps = {});
NormalForm neimark_sacker_normal_form(const AutonomousOrbitProblem& problem, const Eigen::VectorXd& X, double p,
                                      const PeriodMapSteps& steps = {});

// The normal form of a located LPC, PD or NS of an orbit branch: the above for a PeriodicOrbitProblem or an
// AutonomousOrbitProblem; not_computed with the reason for a guess, a norm-conserving system, another problem kind
// or n > kNormalFormMaxDimension.
NormalForm period_map_normal_form(const ContinuationProblem& problem, const SpecialPoint& sp);

}  // namespace rbcstab
