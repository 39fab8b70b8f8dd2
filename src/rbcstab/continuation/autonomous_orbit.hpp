#pragma once
// Autonomous ODEs x' = f(x, p): their equilibria and their periodic orbits of unknown period T, as
// ContinuationProblems. The orbit problem shoots in rescaled time (x' = T f(x, p) over [0, 1], segments of
// length 1 / N) through the forced orbits' shooting code (detail/shooting.hpp) and reports the Floquet
// multipliers without the trivial one, so the engine's LPC / PD / NS detection applies unchanged.
// Starting orbits at a Hopf point: orbit_switch.hpp.
#include <memory>
#include <span>
#include <string>
#include <vector>
#include "rbcstab/continuation/dense.hpp"

#include "rbcstab/continuation/forced_system.hpp"
#include "rbcstab/continuation/orbit.hpp"
#include "rbcstab/continuation/problem.hpp"

namespace rbcstab {

class AutonomousSystem {
 public:
  virtual ~AutonomousSystem() = default;
  virtual Eigen::Index dimension() const = 0;
  virtual void rhs(std::span<const double> x, double p, std::span<double> f) const = 0;
  virtual void jacobian(std::span<const double> x, double p, Eigen::MatrixXd& J) const = 0;  // df/dx
  // df/dp. Default: central differences (prefer an analytic one: see ForcedSystem::parameter_derivative).
  virtual void parameter_derivative(std::span<const double> x, double p, std::span<double> fp) const;
  virtual std::string parameter_name() const { return "p"; }
};

// f(x, p) = 0 with the analytic Jacobian: the branch whose HB points start orbit branches.
class AutonomousEquilibriumProblem final : public ContinuationProblem {
 public:
  explicit AutonomousEquilibriumProblem(const AutonomousSystem& system) : sys_(system) {}
  Eigen::Index dimension() const override { return sys_.dimension(); }
  void residual(const Eigen::VectorXd& x, double p, Eigen::VectorXd& F) const override;
  void jacobian(const Eigen::VectorXd& x, double p, Eigen::MatrixXd& J) const override;
  void parameter_derivative(const Eigen::VectorXd& x, double p, Eigen::VectorXd& Fp) const override;
  std::string parameter_name() const override { return sys_.parameter_name(); }
  const AutonomousSystem& system() const { return sys_; }

 private:
  const AutonomousSystem& sys_;
};

// F(X, p) = 0 for X = (x_0, ..., x_{N-1}, T), x_j the state at t_j = T j / N:
//   E_j = phi(T / N, x_j) - x_{j+1}  (x_N = x_0),   d E_j / dT = f(phi(T / N, x_j)) / N  (no extra integration),
//   the phase condition f_k(x_0, p) = 0: x_0 is an extremum of component k (a Poincare section that needs no
//   reference orbit; the Hopf switch picks k where the critical eigenvector is largest).
// Multipliers: the monodromy M restricted to the complement of f(x_0), its eigenvector of the trivial multiplier
// 1 (M f(x_0) = f(x_0), so the restriction's spectrum is the rest). The system must outlive the problem.
class AutonomousOrbitProblem final : public ContinuationProblem {
 public:
  AutonomousOrbitProblem(const AutonomousSystem& system, int phase_component, const OrbitOptions& options = {});
  ~AutonomousOrbitProblem() override;
  Eigen::Index dimension() const override { return n_ * N_ + 1; }
  void residual(const Eigen::VectorXd& X, double p, Eigen::VectorXd& F) const override;
  void jacobian(const Eigen::VectorXd& X, double p, Eigen::MatrixXd& J) const override;
  void parameter_derivative(const Eigen::VectorXd& X, double p, Eigen::VectorXd& Fp) const override;
  StabilityKind stability_kind() const override { return StabilityKind::multipliers; }
  Eigen::VectorXcd spectrum(const Eigen::VectorXd& X, double p) const override;
  // The nontrivial multipliers with first-order bounds for a monodromy off by |M f0 - f0| / |f0| relative (the
  // integration error the trivial eigenvector shows; at least rtol). refine is not implemented (no-op).
  CertifiedSpectrum certified_spectrum(const Eigen::VectorXd& X, double p, bool refine) const override;
  std::string parameter_name() const override { return sys_.parameter_name(); }
  // Every point reports its period T after p: a column of the branch's JSON (to_json of a MeasuredBranch).
  std::vector<std::string> parameter_names() const override { return {sys_.parameter_name(), "T"}; }
  std::vector<double> parameter_values(const Eigen::VectorXd& X, double p) const override { return {p, period(X)}; }

  int segments() const { return N_; }
  int phase_component() const { return k_; }
  const AutonomousSystem& system() const { return sys_; }
  const OrbitOptions& options() const { return o_; }
  static double period(const Eigen::VectorXd& X) { return X[X.size() - 1]; }
  Eigen::VectorXd state_at_zero(const Eigen::VectorXd& X) const { return X.head(n_); }
  // The unknowns of the trajectory through x0 over [0, T] (a start for Newton).
  Eigen::VectorXd shooting_guess(const Eigen::VectorXd& x0, double T, double p) const;
  Eigen::MatrixXd monodromy(const Eigen::VectorXd& X, double p) const;
  // The linearised solution through v0 at the segments' starts (v_{j+1} = M_j v_j); the PD switch's direction.
  Eigen::VectorXd variation(const Eigen::VectorXd& X, double p, const Eigen::VectorXd& v0) const;
  // d phi_T(x_0) / dp over the period of X (the segments' sensitivities carried through their maps); NaN on failure.
  Eigen::VectorXd flow_sensitivity(const Eigen::VectorXd& X, double p) const;
  // The state at time t > 0 from x (one plain integration, the shooting's options); NaN when it fails.
  Eigen::VectorXd flow(const Eigen::VectorXd& x, double t, double p) const;

 private:
  const ShootingFlows& shoot(const Eigen::VectorXd& X, double p) const;
  const AutonomousSystem& sys_;
  std::unique_ptr<ForcedSystem> flow_;  // sys_ as a ForcedSystem that ignores t
  int k_;
  OrbitOptions o_;
  Eigen::Index n_;
  int N_;
  mutable ShootingFlows cache_;
  mutable Eigen::VectorXd cache_X_;
  mutable double cache_p_ = 0;
  mutable bool cache_valid_ = false;
};

}  // namespace rbcstab
