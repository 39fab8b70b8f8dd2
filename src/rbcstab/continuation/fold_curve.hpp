#pragma once
// Two-parameter continuation of a fold (LP) curve by minimal augmentation (Govaerts): unknowns
// (x, p1), free parameter p2, equations F(x, p1, p2) = 0 and g(x, p1, p2) = 0 where g solves the
// bordered system [J b; c^T 0] [v; g] = [0; 1]. g vanishes exactly where J = dF/dx is singular, and
// the bordered matrix stays regular along the curve when b, c are the left/right null vectors at the
// starting LP. Only one scalar is added, so the curve is a branch of the same engine.
#include <string>

#include "rbcstab/continuation/continuation.hpp"

namespace rbcstab {

// F(x, p1, p2): the problem with two free parameters.
class TwoParameterProblem {
 public:
  virtual ~TwoParameterProblem() = default;
  virtual Eigen::Index dimension() const = 0;
  virtual void residual(const Eigen::VectorXd& x, double p1, double p2, Eigen::VectorXd& F) const = 0;
  // dF/dx; default: central differences.
  virtual void jacobian(const Eigen::VectorXd& x, double p1, double p2, Eigen::MatrixXd& J) const;
  // dF/dp1; default: central differences (the BP curve's equations use it).
  virtual void parameter_derivative(const Eigen::VectorXd& x, double p1, double p2, Eigen::VectorXd& Fp) const;
  virtual std::string name1() const { return "p1"; }
  virtual std::string name2() const { return "p2"; }
  // The dynamical spectrum of the point (x, p1) at p2 and how to read it; curves report the stability
  // of their underlying points with it. Default: eigenvalues of jacobian (problems whose Newton system
  // differs from the dynamics, e.g. the sphere-regularised equilibria, override it).
  virtual Eigen::VectorXcd spectrum(const Eigen::VectorXd& x, double p1, double p2) const;
  // The same with an error estimate per value (ContinuationProblem::certified_spectrum). Default: the
  // bounds of jacobian()'s eigenvalues where they are the values (bound_by_eigenvalues), else NaN.
  virtual CertifiedSpectrum certified_spectrum(const Eigen::VectorXd& x, double p1, double p2, bool refine) const;
  virtual StabilityKind stability_kind() const { return StabilityKind::eigenvalues; }
};

// The one-parameter problem in p1 at fixed p2 (where LP points are found first).
class SliceProblem final : public ContinuationProblem {
 public:
  SliceProblem(const TwoParameterProblem& base, double p2) : base_(base), p2_(p2) {}
  Eigen::Index dimension() const override { return base_.dimension(); }
  void residual(const Eigen::VectorXd& x, double p, Eigen::VectorXd& F) const override { base_.residual(x, p, p2_, F); }
  void jacobian(const Eigen::VectorXd& x, double p, Eigen::MatrixXd& J) const override { base_.jacobian(x, p, p2_, J); }
  void parameter_derivative(const Eigen::VectorXd& x, double p, Eigen::VectorXd& Fp) const override {
    base_.parameter_derivative(x, p, p2_, Fp);
  }
  std::string parameter_name() const override { return base_.name1(); }
  // The base problem's dynamics at p2, so its points are certified as the curves' are.
  Eigen::VectorXcd spectrum(const Eigen::VectorXd& x, double p) const override { return base_.spectrum(x, p, p2_); }
  CertifiedSpectrum certified_spectrum(const Eigen::VectorXd& x, double p, bool refine) const override {
    return base_.certified_spectrum(x, p, p2_, refine);
  }
  StabilityKind stability_kind() const override { return base_.stability_kind(); }

 private:
  const TwoParameterProblem& base_;
  double p2_;
};

// A curve in (p1, p2) of points where the solution x of F(x, p1, p2) = 0 makes a matrix A(x, p1, p2)
// singular, by minimal augmentation: unknowns X = (x, p1), free p2, equations F = 0 and g = 0 with
// [A b; c^T 0][v; g] = [0; 1], b and c the left/right singular vectors of A's smallest singular value
// at the start. Fold curves take A = dF/dx; PD curves of orbits the anti-periodic shooting Jacobian.
class SingularityCurveProblem : public ContinuationProblem {
 public:
  Eigen::Index dimension() const override { return base_.dimension() + 1; }
  void residual(const Eigen::VectorXd& X, double p2, Eigen::VectorXd& R) const override;
  std::string parameter_name() const override { return base_.name2(); }
  std::vector<std::string> parameter_names() const override { return {base_.name1(), base_.name2()}; }
  std::vector<double> parameter_values(const Eigen::VectorXd& X, double p2) const override {
    return {X[X.size() - 1], p2};
  }
  const Eigen::VectorXd& start() const { return start_; }  // (x, p1) at the special point
  // The base problem's certified spectrum at (x, p1) (fold and PD curves report the base's spectrum).
  CertifiedSpectrum certified_spectrum(const Eigen::VectorXd& X, double p2, bool refine) const override;
  double test_function(const Eigen::VectorXd& x, double p1, double p2) const;  // g

 protected:
  explicit SingularityCurveProblem(const TwoParameterProblem& base) : base_(base) {}
  // The matrix whose singularity defines the curve.
  virtual void singular_matrix(const Eigen::VectorXd& x, double p1, double p2, Eigen::MatrixXd& A) const = 0;
  // Checks the start point's size and takes the bordering vectors there (call from the derived constructor).
  void start_at(const SpecialPoint& point, double p2);
  const TwoParameterProblem& base_;

 private:
  Eigen::VectorXd b_, c_, start_;
};

class FoldCurveProblem final : public SingularityCurveProblem {
 public:
  // Starts from an LP of SliceProblem(base, p2) (status located), or an LPC of a fixed-period orbit
  // problem (orbit.hpp).
  FoldCurveProblem(const TwoParameterProblem& base, const SpecialPoint& lp, double p2);
  // Stability of the points along the fold: the base problem's spectrum (one eigenvalue ~0, or one
  // multiplier ~1 on an LPC curve).
  Eigen::VectorXcd spectrum(const Eigen::VectorXd& X, double p2) const override;
  StabilityKind stability_kind() const override { return base_.stability_kind(); }

 protected:
  void singular_matrix(const Eigen::VectorXd& x, double p1, double p2, Eigen::MatrixXd& A) const override {
    base_.jacobian(x, p1, p2, A);
  }
};

}  // namespace rbcstab
