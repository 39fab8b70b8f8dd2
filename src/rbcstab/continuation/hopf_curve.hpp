#pragma once
// Two-parameter continuation of a Hopf (HB) curve by minimal augmentation with the squared-Jacobian
// bordered system (Govaerts 2000, sec. 4.4; MatCont's "Hopf" curve): unknowns (x, p1, kappa), free
// parameter p2, equations F = 0 and two entries of G, where
//   [J^2 + kappa I, B; C^T, 0] [V; G] = [0; I_2],   B, C in R^{n x 2}.
// J^2 + kappa I has rank n - 2 exactly when +-i sqrt(kappa) are eigenvalues of J, so the curve is
// where G = 0; two of its four entries suffice (the pair is chosen at the start so the augmented
// Jacobian is best conditioned). kappa = omega^2 stays smooth through the curve; kappa < 0 would be
// a neutral saddle (real pair +-sqrt(-kappa)), reported, not hidden. Only n + 2 unknowns, so the
// curve is one more branch of the same engine.
#include <array>
#include <string>

#include "rbcstab/continuation/fold_curve.hpp"

namespace rbcstab {

class HopfCurveProblem final : public ContinuationProblem {
 public:
  // Starts from a located HB point of SliceProblem(base, p2): x, p1 and omega = Im of its eigenvalue.
  HopfCurveProblem(const TwoParameterProblem& base, const SpecialPoint& hb, double p2);
  Eigen::Index dimension() const override { return base_.dimension() + 2; }
  void residual(const Eigen::VectorXd& X, double p2, Eigen::VectorXd& R) const override;
  // The base Jacobian's eigenvalues (the pair +- i omega is on the imaginary axis along the curve).
  Eigen::VectorXcd spectrum(const Eigen::VectorXd& X, double p2) const override;
  CertifiedSpectrum certified_spectrum(const Eigen::VectorXd& X, double p2, bool refine) const override;
  std::string parameter_name() const override { return base_.name2(); }
  std::vector<std::string> parameter_names() const override { return {base_.name1(), base_.name2()}; }
  std::vector<double> parameter_values(const Eigen::VectorXd& X, double p2) const override {
    return {X[base_.dimension()], p2};
  }
  const Eigen::VectorXd& start() const { return start_; }  // (x, p1, kappa) at the HB point
  // omega = sqrt(kappa) of a curve point (kappa <= 0: a neutral saddle, omega reported as 0).
  double omega(const Eigen::VectorXd& X) const;

 private:
  Eigen::Matrix2d G(const Eigen::VectorXd& x, double p1, double kappa, double p2) const;
  const TwoParameterProblem& base_;
  Eigen::MatrixXd B_, C_;
  Eigen::VectorXd start_;
  std::array<int, 4> entries_{0, 0, 1, 1};
};

}  // namespace rbcstab
