#pragma once
// Maps y -> P(y, p) whose fixed points are periodic orbits, as problems the map normal forms differentiate
// (period_map_normal_form.hpp): the forced orbits' period map (in the .cpp) and the Poincare map of an autonomous
// orbit below. docs/continuation.md, "Normal forms of orbits: the period map and the Poincare map".
#include <string>

#include "rbcstab/continuation/autonomous_orbit.hpp"
#include "rbcstab/continuation/dense.hpp"
#include "rbcstab/continuation/problem.hpp"

namespace rbcstab {

// Residual P(y, p) - y (the normal forms' second and third differences are of it), Jacobian A - I with A = DP,
// parameter derivative P_p.
class MapProblem : public ContinuationProblem {
 public:
  virtual Eigen::MatrixXd map_jacobian(const Eigen::VectorXd& y, double p) const = 0;  // A = DP (NaN on failure)
  void jacobian(const Eigen::VectorXd& y, double p, Eigen::MatrixXd& J) const override {
    J = map_jacobian(y, p) - Eigen::MatrixXd::Identity(dimension(), dimension());
  }
  StabilityKind stability_kind() const override { return StabilityKind::multipliers; }
};

// The Poincare map of an autonomous orbit on the section S = {x : <n, x - x0> = 0} through the orbit's point x0
// (the state at t = 0 of X) with n = f(x0, p0) / |f(x0, p0)|, in orthonormal coordinates xi of n^perp (x = x0 +
// Q xi, n - 1 of them): P(xi) = Q^T (phi_tau(x) - x0), tau the first return near the period T of X, by Newton on
// <n, phi_tau(x) - x0> = 0 (derivative <n, f(phi_tau(x))>) with the orbit problem's integrator. The trivial
// multiplier 1 drops out: DP = Q^T (I - f n^T / <n, f>) M Q (f at the return point, M = d phi_tau / dx), and
// P_p = Q^T (I - f n^T / <n, f>) d phi_tau / dp. The orbit problem must outlive the map.
class PoincareMap final : public MapProblem {
 public:
  PoincareMap(const AutonomousOrbitProblem& orbit, const Eigen::VectorXd& X, double p);
  Eigen::Index dimension() const override { return Q_.cols(); }
  void residual(const Eigen::VectorXd& xi, double p, Eigen::VectorXd& F) const override;  // NaN when tau fails
  Eigen::MatrixXd map_jacobian(const Eigen::VectorXd& xi, double p) const override;
  void parameter_derivative(const Eigen::VectorXd& xi, double p, Eigen::VectorXd& Fp) const override;
  std::string parameter_name() const override { return orbit_.parameter_name(); }

  Eigen::VectorXd point(const Eigen::VectorXd& xi) const { return x0_ + Q_ * xi; }  // on S
  const Eigen::MatrixXd& basis() const { return Q_; }                               // Q (n x (n - 1))
  const Eigen::VectorXd& normal() const { return n_; }
  // The first return time near T from the section point of xi (NaN when Newton or an integration fails) and the
  // state reached.
  double return_time(const Eigen::VectorXd& xi, double p, Eigen::VectorXd* reached = nullptr) const;

 private:
  // I - f n^T / <n, f> at the return point y.
  Eigen::MatrixXd along_flow(const Eigen::VectorXd& y, double p) const;
  const AutonomousOrbitProblem& orbit_;
  Eigen::VectorXd x0_, n_;
  Eigen::MatrixXd Q_;
  double T_ = 0;
};

}  // namespace rbcstab
