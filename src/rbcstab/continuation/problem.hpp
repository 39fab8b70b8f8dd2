#pragma once
// What the continuation engine continues: a square system F(x, p) = 0 in n unknowns x and one free
// parameter p. The engine knows nothing else about the problem (equilibria, fold curves, orbits):
// every problem kind is an implementation of this interface (BifurcationKit's shape: one engine).
#include <string>
#include <vector>
#include "rbcstab/continuation/dense.hpp"

namespace rbcstab {

// A spectrum with an error estimate for each value (aligned with it; >= 0, NaN where none is known):
// what a point's stability certificate reads (continuation.hpp, certify).
struct CertifiedSpectrum {
  Eigen::VectorXcd values;
  Eigen::VectorXd errors;
};

// The eigenvalues of A, each with the first-order bound
//   e_i = kappa_i (||A v_i - lambda_i v_i|| / ||v_i|| + eta ||A||_F),   kappa_i = ||u_i|| ||v_i|| / |u_i^H v_i|,
// v_i the computed right and u_i the left eigenvector (row i of V^-1). Why: lambda_i is an exact
// eigenvalue of A + E with ||E||_2 = the residual term (the backward error of the computed pair), A itself
// is off by at most eta ||A||_F (its relative accuracy, e.g. rounding in its assembly), and a simple
// eigenvalue moves by at most kappa_i ||E|| + O(||E||^2) under a perturbation E (Wilkinson; Bauer-Fike
// gives the same kappa for a diagonalisable A). A (nearly) defective eigenvalue has kappa = inf. The
// values are bit for bit Eigen::EigenSolver's eigenvalues of A.
CertifiedSpectrum certified_eigenvalues(const Eigen::MatrixXd& A, double eta);
// `values` with the bounds of the eigenvalues of J (certified_eigenvalues(J, eta)): each value within
// the bound of an eigenvalue of J gets the nearest such one's, any other NaN (no bound known).
CertifiedSpectrum bound_by_eigenvalues(const Eigen::VectorXcd& values, const Eigen::MatrixXd& J, double eta);
// The relative accuracy of an n x n matrix assembled in floating point from exact formulas: 8 n eps
// (a few roundings per entry, and n-term sums in products such as T^T A T).
double assembly_accuracy(Eigen::Index n);
// The relative accuracy of the default central-difference jacobian(): truncation ~ h^2 and rounding
// ~ eps / h with h = eps^(1/3) scaled, so ~ eps^(2/3) = 4e-11; 1e-10 leaves room for the scale.
constexpr double kFiniteDifferenceAccuracy = 1e-10;

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
  // spectrum(x, p) with an error estimate per value. refine: also run the problem's costlier check
  // (orbits: the monodromy recomputed with twice the segments at rtol / 100); the engine asks for it
  // near the stability boundary only. Default: the values of spectrum(); each one that lies within the
  // bound of an eigenvalue of jacobian() (certified_eigenvalues, central-difference accuracy) gets that
  // bound, any other NaN. Problems that override spectrum() override this with the same values.
  virtual CertifiedSpectrum certified_spectrum(const Eigen::VectorXd& x, double p, bool refine) const;
  // Names for output: the free parameter, and the parameter(s) a point reports (two-parameter curves
  // carry the second parameter inside x); parameter_values returns them in the same order.
  virtual std::string parameter_name() const { return "p"; }
  virtual std::vector<std::string> parameter_names() const { return {parameter_name()}; }
  virtual std::vector<double> parameter_values(const Eigen::VectorXd& /*x*/, double p) const { return {p}; }
};

// Number of unstable modes in a spectrum: Re > tol (eigenvalues) or |mu| > 1 + tol (multipliers).
int count_unstable(const Eigen::VectorXcd& spectrum, StabilityKind kind, double tol);

}  // namespace rbcstab
