#pragma once
// Normal forms at the special points of equilibrium branches (StabilityKind::eigenvalues), from the second and
// third derivatives of residual() by finite differences (detail/multilinear.hpp). Formulas, conventions and
// what was checked: docs/continuation.md, "Normal forms".
//
// The residual is taken as the vector field. Problems whose Newton system adds a constraint term (the sphere:
// G = F + (|x|^2 - 1) x) agree with the dynamics on an invariant manifold holding the equilibria, so the zero
// set (LP, BP) and the centre manifold (HB) are the same; BP criticality reads the problem's spectrum (the
// unstable counts across the point), not the residual's time direction.
#include "rbcstab/continuation/continuation.hpp"
#include "rbcstab/continuation/normal_form.hpp"
#include "rbcstab/continuation/orbit.hpp"
#include "rbcstab/continuation/period_map_normal_form.hpp"

namespace rbcstab {

// Above this dimension no normal form is computed (dense SVDs and eigen-decompositions of J: the full model
// at large L is continued matrix-free).
inline constexpr Eigen::Index kNormalFormMaxDimension = 600;

// LP at (x, p): J v = 0, w^T J = 0, |v| = 1, <w, v> = 1, oriented so that <w, F_p> > 0. Coefficients
// "a" = <w, B(v, v)> / 2 (Kuznetsov: u' = <w, F_p> (p - p*) + a u^2), "w_Fp" = <w, F_p> and
// "p2" = -a / <w, F_p>: along the branch x = x* + s v + O(s^2), p = p* + p2 s^2.
NormalForm fold_normal_form(const ContinuationProblem& problem, const Eigen::VectorXd& x, double p);

// BP at (x, p). known: the known branch's direction in (x, p) (any length; e.g. its secant across the point).
// unstable_side: the sign of p - p* on which the known branch has the extra unstable eigenvalue (0: unknown).
// The algebraic bifurcation equation a al^2 + 2 b al be + c be^2 = 0 on X = X* + al e1 + be e2 with
// e1 = (v0, 0) (|v0| = 1, J v0 = 0), e2 = (w1, 1) (J w1 = -F_p, w1 . v0 = 0), psi^T J = 0:
// a = psi.B(e1, e1), b = psi.B(e1, e2), c = psi.B(e2, e2). Pitchfork when a vanishes (the new branch leaves along
// e1 with p = p* + p2 s^2, p2 from the cubic "d" = psi.C(e1, e1, e1)); transcritical otherwise.
NormalForm branch_point_normal_form(const ContinuationProblem& problem, const Eigen::VectorXd& x, double p,
                                    const Eigen::VectorXd& known, int unstable_side);

// HB at (x, p) with frequency near omega (> 0): the first Lyapunov coefficient "l1" (Kuznetsov's invariant
// formula, <q, q> = 1, <p, q> = 1), "omega", "alpha1" = dRe(lambda)/dp and the orbit's amplitude law. Degenerate
// when more than one pair is critical ("degenerate (k pairs)"), or J is singular (zero-Hopf).
NormalForm hopf_normal_form(const ContinuationProblem& problem, const Eigen::VectorXd& x, double p, double omega);

// The normal form of a located LP, BP or HB of `branch` (continued with `problem`), or of an LPC, PD or NS of an
// orbit branch (period_map_normal_form); not_computed (note says why) for a guess, another type or a problem above
// kNormalFormMaxDimension. Never throws for a problem that rejects a difference step (the note says so).
NormalForm normal_form(const ContinuationProblem& problem, const Branch& branch, const SpecialPoint& sp);

// Sets normal_form on every LP, BP and HB of an equilibrium branch and every LPC, PD and NS of a forced or
// autonomous orbit branch (what continue_branch does with options.normal_forms).
void attach_normal_forms(const ContinuationProblem& problem, Branch& branch);

}  // namespace rbcstab
