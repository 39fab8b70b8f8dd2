#pragma once
// What the continuation engine continues: a square system F(x, p) = 0 in n unknowns x and one free
// parameter p. The engine knows nothing else about the problem (equilibria, fold curves, orbits):
// every problem kind is an implementation of this interface (BifurcationKit's shape: one engine).
#include <Eigen/Dense>
#include <string>
#include <vector>

namespace rbcstab {

// How a point's stability is read: eigenvalues of a Jacobian (unstable: Re > 0) or Floquet
// multipliers (unstable: |mu| > 1). It also selects the AUTO-07p labels (LP/HB vs LPC/NS/PD).
enum class StabilityKind { eigenvalues, multipliers };

class ContinuationProblem {
 public:
  virtual ~ContinuationProblem() = default;
  virtual Eigen::Index dimension() const = 0;
  // F(x, p). May throw InvalidArgument when p leaves the problem's domain; the engine then stops
  // the branch with status outside_domain and the message.
  virtual void residual(const Eigen::VectorXd& x, double p, Eigen::VectorXd& F) const = 0;
  // dF/dx. Default: central differences of residual (step sqrt(eps)-scaled, error ~ 1e-10 relative),
  // which is enough for Newton (the solution accuracy depends on F only) but not for test functions
  // that need exact singularity; problems with an analytic Jacobian should override.
  virtual void jacobian(const Eigen::VectorXd& x, double p, Eigen::MatrixXd& J) const;
  // dF/dp. Default: central differences (only the tangent uses it).
  virtual void parameter_derivative(const Eigen::VectorXd& x, double p, Eigen::VectorXd& Fp) const;
  virtual StabilityKind stability_kind() const { return StabilityKind::eigenvalues; }
  // The spectrum whose crossings define stability and the LP/HB/PD/NS test functions. Default: the
  // eigenvalues of jacobian(x, p). Problems whose Newton system differs from the dynamics (e.g. a
  // constraint added to remove a conserved quantity) override it with the dynamical spectrum.
  virtual Eigen::VectorXcd spectrum(const Eigen::VectorXd& x, double p) const;
  // Names for output: the free parameter, and the parameter(s) a point reports (two-parameter curves
  // carry the second parameter inside x); parameter_values returns them in the same order.
  virtual std::string parameter_name() const { return "p"; }
  virtual std::vector<std::string> parameter_names() const { return {parameter_name()}; }
  virtual std::vector<double> parameter_values(const Eigen::VectorXd& /*x*/, double p) const { return {p}; }
};

// Number of unstable modes in a spectrum: Re > tol (eigenvalues) or |mu| > 1 + tol (multipliers).
int count_unstable(const Eigen::VectorXcd& spectrum, StabilityKind kind, double tol);

}  // namespace rbcstab
