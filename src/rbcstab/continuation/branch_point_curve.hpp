#pragma once
// Two-parameter continuation of a branch-point (BP) curve. What is implemented, and why:
// a BP of a one-parameter problem F(x, p1) is a point where [F_x F_p1] (n x (n+1)) has rank n - 1.
// Generically that is codimension 2 in (p1, p2), so BP *curves* exist where a structure keeps the BP
// alive: a symmetry (the Z2 pitchfork of the ellipsoidal branch when Upsilon_l crosses zero) or an
// invariant subspace (a trivial solution shared by all parameter values: the transcritical case).
// We continue the regular extended system (Govaerts 2000, sec. 3.5: "the BP system")
//     F(x, p1, p2) + mu psi = 0,   F_x^T psi = 0,   F_p1^T psi = 0,   psi^T psi = 1
// in X = (x, p1, mu, psi) (2n + 2 unknowns) with p2 free. It is regular at a simple BP, so Newton
// converges quadratically there (the fold-curve system degenerates at a BP). mu is the unfolding
// parameter: mu = 0 along the curve of a structurally stable BP (the tests check it to 1e-12); if p2
// breaks the symmetry, mu != 0 measures the imperfection and a BP exists only where mu = 0.
#include <string>

#include "rbcstab/continuation/fold_curve.hpp"

namespace rbcstab {

class BranchPointCurveProblem final : public ContinuationProblem {
 public:
  // Starts from a located BP point of SliceProblem(base, p2); psi from the SVD of [F_x F_p1] there.
  BranchPointCurveProblem(const TwoParameterProblem& base, const SpecialPoint& bp, double p2);
  Eigen::Index dimension() const override { return 2 * base_.dimension() + 2; }
  void residual(const Eigen::VectorXd& X, double p2, Eigen::VectorXd& R) const override;
  Eigen::VectorXcd spectrum(const Eigen::VectorXd& X, double p2) const override;  // the base problem's
  CertifiedSpectrum certified_spectrum(const Eigen::VectorXd& X, double p2, bool refine) const override;
  // The base problem's kind: eigenvalues, or Floquet multipliers for a BP curve of cycles.
  StabilityKind stability_kind() const override { return base_.stability_kind(); }
  std::string parameter_name() const override { return base_.name2(); }
  std::vector<std::string> parameter_names() const override { return {base_.name1(), base_.name2()}; }
  std::vector<double> parameter_values(const Eigen::VectorXd& X, double p2) const override {
    return {X[base_.dimension()], p2};
  }
  const Eigen::VectorXd& start() const { return start_; }  // (x, p1, mu = 0, psi) at the BP
  double mu(const Eigen::VectorXd& X) const { return X[base_.dimension() + 1]; }
  Eigen::VectorXd psi(const Eigen::VectorXd& X) const { return X.tail(base_.dimension()); }

 private:
  const TwoParameterProblem& base_;
  Eigen::VectorXd start_;
};

}  // namespace rbcstab
