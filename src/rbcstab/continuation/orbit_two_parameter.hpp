#pragma once
// Periodic orbits of forced systems with two parameters: the system (ForcedSystem2) and its slice at fixed
// p2, the shooting problem with both parameters free (OrbitTwoParameterProblem, the base of the LPC, PD, NS
// and event curves) and the PD curve.
#include <span>
#include <string>
#include "rbcstab/continuation/dense.hpp"

#include "rbcstab/continuation/continuation.hpp"
#include "rbcstab/continuation/fold_curve.hpp"
#include "rbcstab/continuation/forced_system.hpp"
#include "rbcstab/continuation/orbit.hpp"
#include "rbcstab/continuation/problem.hpp"

namespace rbcstab {

// Two-parameter forced systems and LPC curves. An LPC of a fixed-period orbit is a fold of the
// shooting system F(X, p1) = 0 (its Jacobian is singular where a multiplier crosses 1), so the fold
// curve machinery of fold_curve.hpp (minimal augmentation) continues it in (p1, p2) unchanged:
// FoldCurveProblem(OrbitTwoParameterProblem(system, options), lpc, p2).
class ForcedSystem2 {
 public:
  virtual ~ForcedSystem2() = default;
  virtual Eigen::Index dimension() const = 0;
  virtual void rhs(double t, std::span<const double> x, double p1, double p2, std::span<double> f) const = 0;
  virtual void jacobian(double t, std::span<const double> x, double p1, double p2, Eigen::MatrixXd& J) const = 0;
  // df/dp1. Default: central differences (see ForcedSystem::parameter_derivative).
  virtual void parameter_derivative(double t, std::span<const double> x, double p1, double p2,
                                    std::span<double> fp) const;
  virtual bool conserves_norm() const { return false; }
  virtual std::string name1() const { return "p1"; }
  virtual std::string name2() const { return "p2"; }
};

// The two-parameter system as a one-parameter ForcedSystem in p1 at fixed p2.
class ForcedSlice final : public ForcedSystem {
 public:
  ForcedSlice(const ForcedSystem2& base, double p2) : base_(base), p2_(p2) {}
  Eigen::Index dimension() const override { return base_.dimension(); }
  void rhs(double t, std::span<const double> x, double p, std::span<double> f) const override {
    base_.rhs(t, x, p, p2_, f);
  }
  void jacobian(double t, std::span<const double> x, double p, Eigen::MatrixXd& J) const override {
    base_.jacobian(t, x, p, p2_, J);
  }
  void parameter_derivative(double t, std::span<const double> x, double p, std::span<double> fp) const override {
    base_.parameter_derivative(t, x, p, p2_, fp);
  }
  bool conserves_norm() const override { return base_.conserves_norm(); }
  std::string parameter_name() const override { return base_.name1(); }
  void set_p2(double p2) { p2_ = p2; }
  double p2() const { return p2_; }

 private:
  const ForcedSystem2& base_;
  double p2_;
};

// The shooting system with both parameters free (base of FoldCurveProblem for LPC curves).
class OrbitTwoParameterProblem final : public TwoParameterProblem {
 public:
  OrbitTwoParameterProblem(const ForcedSystem2& system, const OrbitOptions& options = {})
      : system_(system), slice_(system, 0.0), orbit_(slice_, options) {}
  Eigen::Index dimension() const override { return orbit_.dimension(); }
  void residual(const Eigen::VectorXd& X, double p1, double p2, Eigen::VectorXd& F) const override;
  void jacobian(const Eigen::VectorXd& X, double p1, double p2, Eigen::MatrixXd& J) const override;
  void parameter_derivative(const Eigen::VectorXd& X, double p1, double p2, Eigen::VectorXd& Fp) const override;
  std::string name1() const override { return system_.name1(); }
  std::string name2() const override { return system_.name2(); }
  void antiperiodic_jacobian(const Eigen::VectorXd& X, double p1, double p2, Eigen::MatrixXd& J) const;
  Eigen::VectorXcd multipliers(const Eigen::VectorXd& X, double p1, double p2) const;
  OrbitSummary summary(const Eigen::VectorXd& X, double p1, double p2) const;
  OrbitPoint point_at(const Eigen::VectorXd& X, double p1, double p2, double t) const;
  // Curves over this problem (LPC) report the orbits' Floquet multipliers.
  Eigen::VectorXcd spectrum(const Eigen::VectorXd& X, double p1, double p2) const override {
    return multipliers(X, p1, p2);
  }
  CertifiedSpectrum certified_spectrum(const Eigen::VectorXd& X, double p1, double p2, bool refine) const override;
  StabilityKind stability_kind() const override { return StabilityKind::multipliers; }

 private:
  void at(double p2) const;
  const ForcedSystem2& system_;
  mutable ForcedSlice slice_;
  PeriodicOrbitProblem orbit_;
};

// PD curve by minimal augmentation: unknowns (X, p1), free p2, equations F = 0 and g = 0 where
// [J_PD b; c^T 0][v; g] = [0; 1] with J_PD the anti-periodic shooting Jacobian and b, c its left/right
// singular vectors at the starting PD point. The spectrum is the orbit's multipliers (one is -1 along
// the curve: the engine treats it as neutral, so no spurious PD points are reported).
class PeriodDoublingCurveProblem final : public SingularityCurveProblem {
 public:
  PeriodDoublingCurveProblem(const OrbitTwoParameterProblem& base, const SpecialPoint& pd, double p2);
  StabilityKind stability_kind() const override { return StabilityKind::multipliers; }
  Eigen::VectorXcd spectrum(const Eigen::VectorXd& X, double p2) const override;

 protected:
  void singular_matrix(const Eigen::VectorXd& X, double p1, double p2, Eigen::MatrixXd& A) const override {
    orbit_base_.antiperiodic_jacobian(X, p1, p2, A);
  }

 private:
  const OrbitTwoParameterProblem& orbit_base_;
};

}  // namespace rbcstab
