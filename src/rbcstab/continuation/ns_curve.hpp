#pragma once
// Two-parameter continuation of a Neimark-Sacker (NS) curve of periodic orbits of a forced system
// (period 2 pi fixed) by minimal augmentation with the squared-monodromy bordered system, the cycle
// analogue of the Hopf curve's J^2 + kappa I (Govaerts 2000; MatCont's "NS" curve):
//   unknowns (X, p1, kappa), free p2, equations F(X, p1, p2) = 0 (the shooting system of orbit.hpp)
//   and two entries of G, where [M^2 - 2 kappa M + I, B; C^T, 0] [V; G] = [0; I_2], B, C in R^{n x 2},
// M the monodromy at t = 0. mu^2 - 2 kappa mu + 1 = 0 has the roots e^{+-i theta} with kappa = cos theta,
// so M^2 - 2 kappa M + I loses rank 2 exactly when the pair e^{+-i theta} are multipliers: G = 0 on
// the curve, and kappa = cos theta is smooth along it (no angle to unwrap).
//
// What the test function cannot tell apart: a real pair mu, 1/mu (a neutral saddle) also makes
// M^2 - 2 kappa M + I singular, with kappa = (mu + 1/mu)/2, |kappa| > 1. classify() reports it as such
// (never as an NS), and resonance_event() is a UZ event at |kappa| = 1 (the 1:1 / 1:2 resonances where
// the NS curve turns into a neutral-saddle curve).
//
// Conserved norm (the reduced in-plane system): M has the trivial multiplier 1 (x0^T M = x0^T), which
// gives M^2 - 2 kappa M + I the eigenvalue 2 (1 - kappa), nonzero for kappa < 1, i.e. everywhere on an
// NS curve away from its 1:1 end. So the full monodromy is used unchanged: no spurious zero, and no
// tangent-plane basis whose orientation could jump along the curve.
//
// Derivatives: the F rows are the shooting problem's analytic ones (variational equations); the two G
// rows by central differences of G (step cbrt(eps) (1 + |X_j|): truncation ~1e-11, rounding of the
// rtol-1e-12 integrations ~1e-7 relative). Only Newton's convergence rate depends on them: the curve
// points satisfy G = 0 to Newton's tolerance on residuals integrated at rtol 1e-12.
#include <array>
#include <string>
#include <vector>

#include "rbcstab/continuation/orbit.hpp"
#include "rbcstab/continuation/orbit_two_parameter.hpp"

namespace rbcstab {

// What a point of the curve is: kappa in [-1, 1] is an NS pair e^{+-i theta}; |kappa| > 1 a neutral
// saddle (real multipliers mu, 1/mu with mu + 1/mu = 2 kappa).
struct NeimarkSackerKind {
  bool neutral_saddle = false;
  double kappa = 0;
  double theta = 0;            // NS: arccos(kappa) in [0, pi]; neutral saddle: 0 (kappa > 1) or pi (kappa < -1)
  double real_multiplier = 0;  // neutral saddle: mu with |mu| >= 1; NS: 0
};

class NeimarkSackerCurveProblem final : public ContinuationProblem {
 public:
  // Starts from a located NS point of a one-parameter run of PeriodicOrbitProblem(ForcedSlice(system,
  // p2), options): X, p1 and the critical multiplier e^{i theta} (kappa = cos theta). The system must
  // outlive the problem.
  NeimarkSackerCurveProblem(const ForcedSystem2& system, const OrbitOptions& options, const SpecialPoint& ns,
                            double p2);
  Eigen::Index dimension() const override { return m_ + 2; }
  void residual(const Eigen::VectorXd& X, double p2, Eigen::VectorXd& R) const override;
  void jacobian(const Eigen::VectorXd& X, double p2, Eigen::MatrixXd& J) const override;
  StabilityKind stability_kind() const override { return StabilityKind::multipliers; }
  // The orbit's (nontrivial) multipliers; the pair e^{+-i theta} sits on the unit circle along the
  // curve (neutral to the engine, so no spurious NS points are reported).
  Eigen::VectorXcd spectrum(const Eigen::VectorXd& X, double p2) const override;
  CertifiedSpectrum certified_spectrum(const Eigen::VectorXd& X, double p2, bool refine) const override;
  std::string parameter_name() const override { return system_.name2(); }
  std::vector<std::string> parameter_names() const override { return {system_.name1(), system_.name2()}; }
  std::vector<double> parameter_values(const Eigen::VectorXd& X, double p2) const override { return {X[m_], p2}; }

  const Eigen::VectorXd& start() const { return start_; }  // (X, p1, kappa) at the NS point
  NeimarkSackerKind classify(const Eigen::VectorXd& X) const;
  // 1 - kappa^2: zero where the NS curve meets a 1:1 (kappa = 1) or 1:2 (kappa = -1) resonance and
  // continues as a neutral-saddle curve.
  UserEvent resonance_event(const std::string& name = "NS_resonance") const;
  // The 2 x 2 G of the bordered system (zero on the curve).
  Eigen::Matrix2d test_functions(const Eigen::VectorXd& X, double p1, double kappa, double p2) const;
  Floquet floquet(const Eigen::VectorXd& X, double p1, double p2) const;
  std::size_t integrations() const { return orbit_.integrations(); }

 private:
  void at(double p2) const;
  // The Jacobian with its first m rows (dF/dX, dF/dp1, 0) filled and the G rows zero.
  void shooting_rows(const Eigen::VectorXd& X, double p2, Eigen::MatrixXd& J) const;
  // dG/d(X, p1, kappa) for all four entries (rows: G00, G01, G10, G11).
  Eigen::MatrixXd g_derivatives(const Eigen::VectorXd& X, double p2) const;
  const ForcedSystem2& system_;
  mutable ForcedSlice slice_;
  PeriodicOrbitProblem orbit_;
  Eigen::Index n_, m_;
  Eigen::MatrixXd B_, C_;
  Eigen::VectorXd start_;
  std::array<int, 4> entries_{0, 0, 1, 1};
};

}  // namespace rbcstab
