#pragma once
// Equilibria of the reduced (ellipsoidal) system in its regular coordinates y = (Re z, Im z, w) on
// the unit sphere, continued in any ContinuationParameter.
//
// Which equilibria exist: the reduced system is z' = (i + mu) z - i/Lambda + kappa z0(t),
// w' = mu w + kappa w0 with z0(t) = z0(0) e^{it}, kappa = 1/(Lambda S). It is autonomous iff
// kappa z0(0) = 0: an out-of-plane rest shape (beta = 0, r0 = 0) or no elastic memory (Delta0 = 0,
// C = inf). No rotating frame removes the forcing otherwise (the shear term -i/Lambda is fixed in
// the lab frame while z0 turns), so in-plane states are periodic orbits of period 2 pi (orbit.hpp).
//
// The flow conserves Q = |y|^2 (the excess area), so its Jacobian is singular along the family of
// spheres. The Newton system is G(y) = F(y) + (Q - 1) y: y.G = (Q - 1) Q forces Q = 1 at a zero, and
// DG = DF + 2 y y^T is regular at a hyperbolic equilibrium (y is DF's left null vector). Stability
// is read from DF restricted to the sphere's tangent plane, which DF leaves invariant.
#include <optional>

#include "rbcstab/continuation/continuation_parameter.hpp"
#include "rbcstab/continuation/problem.hpp"
#include "rbcstab/model/reduced_model.hpp"
#include "rbcstab/model/scene.hpp"

namespace rbcstab {

class ReducedEquilibriumProblem final : public ContinuationProblem {
 public:
  // The scene supplies every parameter but the free one (which may be beta, the rest shape's
  // orientation). Throws InvalidArgument("beta", ...) when the system is forced (see above), at the
  // start and at any later parameter value (the engine ends the branch there: outside_domain).
  ReducedEquilibriumProblem(const Scene& scene, ContinuationParameter free);

  Eigen::Index dimension() const override { return 3; }
  void residual(const Eigen::VectorXd& y, double p, Eigen::VectorXd& G) const override;
  void jacobian(const Eigen::VectorXd& y, double p, Eigen::MatrixXd& J) const override;
  Eigen::VectorXcd spectrum(const Eigen::VectorXd& y, double p) const override;
  // The tangent-plane spectrum of the analytic Jacobian with first-order error bounds.
  CertifiedSpectrum certified_spectrum(const Eigen::VectorXd& y, double p, bool refine) const override;
  // Central differences, except for beta: exact (the equilibrium's domain in beta is one point when
  // the rest shape pulls, where a difference would step outside; see equilibrium.cpp).
  void parameter_derivative(const Eigen::VectorXd& y, double p, Eigen::VectorXd& Fp) const override;
  std::string parameter_name() const override { return to_string(free_); }

  double start_parameter() const { return get_parameter(scene_, free_); }
  // The reduced state after relaxing for time T from the scene's initial state (a start on the
  // stable branch when one attracts it).
  Eigen::VectorXd relaxed_state(double T) const;
  const ReducedModel& model(double p) const;  // cached for the last p

 private:
  Scene scene_;
  ContinuationParameter free_;
  InitialState init_;
  mutable std::optional<ReducedModel> cache_;
  mutable double cache_p_ = 0;
};

// (r, Psi) of a reduced state: z = r e^{-i Psi}; r = |z| / |y| (0 <= r <= 1), Psi in (-pi, pi].
struct PolarState {
  double r = 0, Psi = 0;
};
PolarState polar(const Eigen::VectorXd& y);

}  // namespace rbcstab
