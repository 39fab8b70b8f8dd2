#pragma once
// The attractor a simulated state has reached: the periodic orbit of a forced system through a nearby state
// (an equilibrium is a periodic orbit of any period), refined from the state's own time by a chord Newton
// iteration on the period map, with its Floquet multipliers and their first-order error bounds. Certified
// early termination (verdict/certified_run.hpp) decides from it.
//
// The iteration solves E(x) = |x|^2 phi(x) - x = 0 for norm-conserving systems (the shooting problem of
// orbit.hpp with one segment starting at t0: |x*| = 1 at a zero), phi the period map from t0. One
// variational run at the start x0 gives the monodromy M = dphi/dx and the chord matrix DE; every further
// iterate costs one plain run. The chord converges at the rate q ~ |M(x*) - M(x0)| / |DE| ~ |x0 - x*|, so a
// measured q well below 1 says that x0 lies where the orbit's linearisation holds.
#include <numbers>
#include <string>
#include <vector>
#include "rbcstab/continuation/dense.hpp"

#include "rbcstab/continuation/modal_equilibrium.hpp"
#include "rbcstab/continuation/modal_orbit.hpp"
#include "rbcstab/continuation/orbit.hpp"
#include "rbcstab/continuation/problem.hpp"
#include "rbcstab/core/constants.hpp"
#include "rbcstab/integrate/integrator.hpp"
#include "rbcstab/integrate/quadrature.hpp"

namespace rbcstab {

struct PeriodicRefinementOptions {
  double period = 2 * kPi;  // of the forcing (every level's, in its own frame)
  // The period map at the iterates: its accuracy bounds the residual that can be reached.
  IntegratorOptions plain = {Stepper::rk8pd, 1e-10, 1e-13};
  // The monodromy at the start: it only steers the chord and gives the multipliers, whose error bound
  // includes its tolerance (a margin far above it is what a certificate needs).
  IntegratorOptions variational = {Stepper::rk8pd, 1e-7, 1e-10};
  double residual_tol = 1e-9;     // |phi(x*) - x*| (states have |x| = 1) that accepts x* as periodic
  int max_iterations = 6;         // chord iterations after the variational run
  double max_contraction = 0.25;  // a slower chord: x0 is too far from the orbit for its linearisation
  void validate() const;          // throws InvalidArgument naming the field
};

struct PeriodicRefinement {
  bool converged = false;
  std::string reason;      // why not converged
  Eigen::VectorXd x;       // x*: the orbit's state at t0 (modulo the period)
  double residual = 0;     // |phi(x*) - x*|
  double distance = 0;     // |x0 - x*|
  double contraction = 0;  // ratio of the last two chord steps
  int iterations = 0;      // chord iterations
  // Phi(t0 + period, t0) at x0 on the tangent plane x0^perp (orthonormal basis) when the system conserves
  // |x|^2 (the trivial multiplier 1 removed), else the whole monodromy.
  Eigen::MatrixXd monodromy;
  // Its eigenvalues, each with a first-order bound (certified_eigenvalues) for a monodromy whose relative
  // error is the largest of the variational tolerance, x0's periodicity defect and the change of M
  // between x0 and x* that the chord contraction measures.
  CertifiedSpectrum multipliers;
  // sum_k M^k (x0 - x*) = (I - M)^{-1} (x0 - x*) on the tangent plane (the radial part, a change of |x|, does not
  // decay): to first order, the deviations of the later trajectory at the start's phase add up to this, so an
  // integral along it exceeds the orbit's by the integral's change from x* to x* + deviation_sum.
  Eigen::VectorXd deviation_sum;
  Eigen::VectorXd integrals;  // the caller's integrands over one period along x*
  IntegrationCounters work;   // every run
};

// Refines the orbit of `system` (at parameter p) through the state x0 at time t0. Failures are a reason in
// the result, not exceptions. `integrands` (count > 0 and a rate) are integrated along every plain run.
PeriodicRefinement refine_periodic_orbit(const ForcedSystem& system, double p, double t0, const Eigen::VectorXd& x0,
                                         const PeriodicRefinementOptions& options = {},
                                         const Quadrature& integrands = {0, {}, {}});

// One period of `system` from (t0, x0) with the caller's integrands (as refine_periodic_orbit's): the
// periodicity defect |phi(x0) - x0| screens a refinement, and the integrals along a perturbed orbit state give
// their first-order change.
struct PeriodRun {
  bool ok = false;
  std::string reason;  // why not ok
  Eigen::VectorXd x;   // phi(x0)
  Eigen::VectorXd integrals;
  IntegrationCounters work;
};
PeriodRun run_period(const ForcedSystem& system, double p, double t0, const Eigen::VectorXd& x0, double period,
                     const IntegratorOptions& options, const Quadrature& integrands = {0, {}, {}});

// The modal orbit problem (ModalForcedSystem, regular coordinates, v~ co-rotating, period 2 pi) restricted
// to the l = 2 block and the modes l >= 3 in `modes`: the invariant subspace where every other mode is zero.
// On an orbit there the other modes decouple (a_l' = Upsilon_l(sigma) a_l, multiplier
// exp(int Upsilon_l(sigma) dt)), so their variational equations need not be integrated. Coordinates
// x = (Re z, Im z, w, Re v~, Im v~, a_l for l in modes). The parameter argument of rhs and jacobian is
// ignored: the subsystem is built at one value p of the full system's parameter.
class ModalSubsystem final : public ForcedSystem {
 public:
  // Keeps a reference to full (it must outlive this); modes: increasing, in [3, full.L()].
  ModalSubsystem(const ModalForcedSystem& full, double p, std::vector<int> modes);
  Eigen::Index dimension() const override { return 5 + static_cast<Eigen::Index>(modes_.size()); }
  void rhs(double t, std::span<const double> x, double p, std::span<double> f) const override;
  void jacobian(double t, std::span<const double> x, double p, Eigen::MatrixXd& J) const override;
  bool conserves_norm() const override { return true; }
  const std::vector<int>& modes() const { return modes_; }
  // The subsystem's coordinates of a full state, and a full state from the subsystem's (other modes zero).
  Eigen::VectorXd restrict(const Eigen::VectorXd& x_full) const;
  Eigen::VectorXd embed(const Eigen::VectorXd& x) const;
  // sigma at (t, x): the tension every mode's growth rate Upsilon_l(sigma) is evaluated at.
  double sigma(double t, std::span<const double> x) const;
  const GrowthRate& rate(int l) const { return full_.coefficients(p_).rate(l); }

 private:
  // The forcing at t into h_: h(t) = h0 + cos(t) h_cos + sin(t) h_sin (affine in e^{it}, modal_orbit.hpp),
  // without the full system's allocation per call (this is the inner loop of every run).
  const Eigen::VectorXd& forcing(double t) const;
  const ModalForcedSystem& full_;
  double p_;
  std::vector<int> modes_;
  ModalCoefficients c_;  // Upsilon_2 and the rates of `modes`, relabelled l = 3, 4, ... in order
  Eigen::VectorXd h0_, h_cos_, h_sin_;
  mutable Eigen::VectorXd h_;
};

}  // namespace rbcstab
