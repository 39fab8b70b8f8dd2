#pragma once
// The Z2-reduced two-parameter curve of branch points of cycles of the in-plane ELLIPSOIDAL orbit of the
// modal model. On the modal orbit with a_l = 0 (l >= 3) and v~ = 0 the l = 2 block is the
// reduced in-plane orbit (ReducedForcedSystem), and each a_l direction decouples, da_l' = Upsilon_l(sigma(t))
// da_l, with Floquet multiplier exp(int_0^{2 pi} Upsilon_l dt) = exp(2 pi Upsilon_l(sigma_bar)) (Upsilon_l
// is affine in sigma; sigma_bar = period mean of sigma). The a_l -> -a_l pitchfork of cycles of mode l
// is therefore exactly where sigma_bar = sigma_l^c(alpha).
//
// Unknowns X = (shooting unknowns of the reduced orbit (3 N), p1), free parameter p2; equations
//   F(X, p1) = 0 (PeriodicOrbitProblem over ReducedForcedSystem at (p1, p2): the same shooting system),
//   g = sigma_bar - sigma_l^c(alpha) = Upsilon_l(sigma_bar) / |dUpsilon_l/dsigma| (an O(sigma) scale).
// sigma_bar is a quadrature state integrated along each shooting segment with the orbit (q' = sigma(t, y),
// same rk8pd at the shooting tolerance): accurate to the integration tolerance and as smooth in X as the
// shooting itself, with no sampling density to choose (a periodic trapezoid would need dense output).
// g's Jacobian row is a central difference (cbrt(eps) steps: error ~ rtol / h ~ 1e-7 relative, enough
// for Newton, whose converged point depends only on the residual); each x_j only moves segment j's
// integral, so the row costs 2 segment integrations per column. Cost is independent of L (L enters only
// through the admissible l <= L and the reported multipliers).
#include <string>
#include <vector>
#include "rbcstab/continuation/dense.hpp"

#include "rbcstab/continuation/continuation_parameter.hpp"
#include "rbcstab/continuation/orbit.hpp"
#include "rbcstab/continuation/orbit_two_parameter.hpp"
#include "rbcstab/continuation/problem.hpp"
#include "rbcstab/continuation/two_parameter.hpp"
#include "rbcstab/model/scene.hpp"

namespace rbcstab {

class ModalOrbitBranchPointCurve final : public ContinuationProblem {
 public:
  // scene: the in-plane modal scene (parameters.Delta the total excess area, as for ModalForcedSystem);
  // throws InvalidArgument("p2", ...) for a coupled pair (require_independent), ("l", ...) unless
  // 3 <= l <= scene.L, ("beta", ...) if beta is free or the rest shape has m = 1 content (sin 2 beta != 0
  // with Delta0 > 0, C finite): only without it is v~ = 0 invariant and the ellipsoidal orbit the reduced one.
  ModalOrbitBranchPointCurve(const Scene& scene, ContinuationParameter p1, ContinuationParameter p2, int l,
                             const OrbitOptions& options = {});
  // base_ refers to system_: not copyable.
  ModalOrbitBranchPointCurve(const ModalOrbitBranchPointCurve&) = delete;
  ModalOrbitBranchPointCurve& operator=(const ModalOrbitBranchPointCurve&) = delete;
  Eigen::Index dimension() const override { return n_ + 1; }
  void residual(const Eigen::VectorXd& X, double p2, Eigen::VectorXd& R) const override;
  void jacobian(const Eigen::VectorXd& X, double p2, Eigen::MatrixXd& J) const override;
  StabilityKind stability_kind() const override { return StabilityKind::multipliers; }
  // The modal ellipsoidal orbit's multipliers: the reduced orbit's two, exp(2 pi mean Upsilon_2) twice
  // (the v~ plane) and exp(2 pi Upsilon_k(sigma_bar)) for k = 3..L (k = l is 1 on the curve).
  Eigen::VectorXcd spectrum(const Eigen::VectorXd& X, double p2) const override;
  // The reduced orbit's certified multipliers; a closed-form one exp(2 pi Upsilon_k(sigma_bar)) is off
  // by 2 pi |mu| |dUpsilon_k/dsigma| times sigma_bar's error, estimated as rtol (1 + |sigma_bar|).
  CertifiedSpectrum certified_spectrum(const Eigen::VectorXd& X, double p2, bool refine) const override;
  std::string parameter_name() const override { return to_string(p2_); }
  std::vector<std::string> parameter_names() const override { return {to_string(p1_), to_string(p2_)}; }
  std::vector<double> parameter_values(const Eigen::VectorXd& X, double p2) const override { return {X[n_], p2}; }

  // No m = 1 rest-shape forcing (sin 2 beta = 0, or Delta0 = 0, or C = inf): only then is v~ = 0
  // invariant and the ellipsoidal orbit the reduced one (the constructor's condition besides a fixed beta).
  static bool has_untilted_rest_shape(const Scene& scene);
  int mode() const { return l_; }
  double start_parameter() const { return get_parameter(scene_, p2_); }
  Parameters parameters(double p1, double p2) const;
  // The period mean of sigma along the orbit with shooting unknowns X (3 N) at (p1, p2); NaN if an
  // integration fails (the residual then throws nothing: Newton sees a non-finite residual and stops).
  double sigma_bar(const Eigen::VectorXd& X, double p1, double p2) const;
  // (reduced shooting unknowns, p1) from a modal-orbit shooting vector (n_modal = 5 + L - 2 per segment,
  // same segments) at a BP in p1: the first three coordinates (Re z, Im z, w) of each segment.
  Eigen::VectorXd start_from_modal(const Eigen::VectorXd& X_modal, double p1_bp) const;
  const OrbitTwoParameterProblem& base() const { return base_; }
  // Integrations done so far (shooting and quadrature), a work counter for benchmarks.
  std::size_t quadratures() const { return quadratures_; }

 private:
  double segment_integral(const ReducedModel& m, const Eigen::Vector3d& x, int j) const;
  Scene scene_;
  ContinuationParameter p1_, p2_;
  int l_;
  OrbitOptions options_;
  ReducedForcedSystem2 system_;
  OrbitTwoParameterProblem base_;
  Eigen::Index n_;
  mutable std::size_t quadratures_ = 0;
};

// The critical mode of a symmetry-breaking BP of the ellipsoidal orbit: among l = 3..L the one whose
// Upsilon_l(sigma_bar) is closest to 0 (its multiplier exp(2 pi Upsilon_l(sigma_bar)) closest to 1).
int ellipsoidal_orbit_critical_mode(const Parameters& q, int L, double sigma_bar);

}  // namespace rbcstab
