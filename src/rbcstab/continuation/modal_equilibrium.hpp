#pragma once
// Equilibria of the modal model (docs/theory.md) in regular coordinates, continued in any
// ContinuationParameter, and the two-parameter curve of its symmetry-breaking branch points.
//
// Coordinates (all scaled by the total excess area Delta, so that the area is the unit sphere):
//   x = (Re z, Im z, w, Re v, Im v, a_3, ..., a_L),
//   z = f22 sqrt(2 a2/Delta), w = -f20 sqrt(a2/Delta), v = f21 sqrt(2 a2/Delta),  Delta_l = Delta a_l^2,
// so Delta_2 = Delta (|z|^2 + w^2 + |v|^2) and the area constraint is |x|^2 = 1. The modal model's
// u_l = ln Delta_l is singular at Delta_l = 0 (the ellipsoidal branch, where the bifurcations are);
// the signed amplitude a_l is regular there and carries the Z2 symmetry a_l -> -a_l of every mode.
//
// Equations (re-derived in docs/continuation.md; checked against ModalModel::rhs in the tests):
//   z' = (i + Y_2) z - i/Lambda,  w' = Y_2 w + kappa w0,  v' = (i/2 + Y_2) v,  a_l' = Y_l a_l,
// Y_l = Upsilon_l(sigma) (Delta_l' = 2 Y_l Delta_l gives a_l' = Y_l a_l), kappa = 1/(Lambda S), and
// sigma from the area constraint x.x' = 0, which is linear in sigma because Y_l is:
//   sigma = -[sum_l q_l Y_l(0) + x.h] / sum_l q_l dY_l/dsigma,  q_2 = |z|^2 + w^2 + |v|^2, q_l = a_l^2,
// with h the forcing (0, -1/Lambda, kappa w0, 0, 0, 0...). The denominator is < 0 for x != 0.
//
// Which equilibria exist: as for the reduced system (equilibrium.hpp), the l = 2 block is autonomous
// only without a rotating rest-shape forcing, i.e. an out-of-plane rest shape (beta = 0) or no elastic
// memory (Delta0 = 0 or C = inf); otherwise the problem throws InvalidArgument("beta", ...). Modes
// l >= 3 are never forced (the rest shape has no l >= 3 content at the modal level).
//
// Newton system G = F + (|x|^2 - 1) x (x.F = 0 identically, so x.G = (|x|^2 - 1)|x|^2 forces the
// sphere); stability is the spectrum of DF on the tangent plane x^perp, which DF leaves invariant.
// On the ellipsoidal branch (a = 0) the a_l directions are eigenvectors with eigenvalue Y_l(sigma):
// mode l's branch point (a pitchfork, by the Z2 symmetry) is where sigma crosses sigma_l^c.
#include <optional>
#include <vector>

#include "rbcstab/continuation/dense.hpp"

#include "rbcstab/continuation/continuation_parameter.hpp"
#include "rbcstab/continuation/problem.hpp"
#include "rbcstab/model/coefficients.hpp"
#include "rbcstab/model/scene.hpp"
#include "rbcstab/model/tension.hpp"

namespace rbcstab {

// The coefficients of the equations above at one parameter set.
struct ModalCoefficients {
  Parameters parameters;
  int L = 2;
  double inv_Lambda = 0;            // 1/Lambda: the shear drive of z
  double kappa_w0 = 0;              // kappa w0: the rest shape's pull on w
  std::vector<GrowthRate> Upsilon;  // Upsilon_l, index l - 2
  const GrowthRate& rate(int l) const { return Upsilon[static_cast<std::size_t>(l - 2)]; }
  double upsilon(int l, double sigma) const { return rate(l)(sigma); }
};

// The coefficients at a parameter set for modes 2..L, with the rest shape's pull kappa w0 (w0 = +-1).
ModalCoefficients modal_coefficients(const Parameters& q, int L, double w0);

// The modal dynamics on the sphere for any x-independent forcing h (layout of x) and rotation rate
// omega_v of v (1/2 in the lab frame, 0 in the frame co-rotating with an m = 1 forcing):
//   F = Y x + R x + h,  R z = i z, R v = i omega_v v,  Y = Upsilon_l(sigma) on mode l's entries,
// with sigma from the area constraint x.F = 0 (linear in sigma, denominator < 0 for x != 0).
// Shared by equilibria (h = (0, -1/Lambda, kappa w0, 0, ...), omega_v = 1/2) and the forced orbits
// of modal_orbit.hpp (h(t)).
// The area balance (model/tension.hpp) in these coordinates: Delta_l/Delta = q_l, work x.h.
AreaBalance modal_area_balance(const ModalCoefficients& c, const Eigen::Ref<const Eigen::VectorXd>& x,
                               const Eigen::Ref<const Eigen::VectorXd>& h);
double modal_sigma(const ModalCoefficients& c, const Eigen::Ref<const Eigen::VectorXd>& x,
                   const Eigen::Ref<const Eigen::VectorXd>& h);
// Writes F (sized like x) and returns sigma.
double modal_dynamics(const ModalCoefficients& c, const Eigen::Ref<const Eigen::VectorXd>& x,
                      const Eigen::Ref<const Eigen::VectorXd>& h, double omega_v, Eigen::Ref<Eigen::VectorXd> F);
// DF = dF/dx = diag(Y) + R + u grad(sigma)^T with u_i = slope_i x_i, grad sigma = -(2 x_i Y_i + h_i)/D.
void modal_dynamics_jacobian(const ModalCoefficients& c, const Eigen::Ref<const Eigen::VectorXd>& x,
                             const Eigen::Ref<const Eigen::VectorXd>& h, double omega_v, Eigen::MatrixXd& DF);

// Observables of a modal equilibrium state.
struct ModalState {
  double sigma = 0;
  double r = 0, Psi = 0;        // of the l = 2 block's (z, w): r = |z| / sqrt(|z|^2 + w^2)
  std::vector<double> Delta_l;  // Delta_l for l = 2..L (index l - 2); Delta_2 includes |v|^2
};

class ModalEquilibriumProblem final : public ContinuationProblem {
 public:
  // The scene supplies every parameter but the free one, the rest shape's orientation and L (>= 3).
  ModalEquilibriumProblem(const Scene& scene, ContinuationParameter free);

  Eigen::Index dimension() const override { return 5 + (L_ - 2); }
  void residual(const Eigen::VectorXd& x, double p, Eigen::VectorXd& G) const override;
  void jacobian(const Eigen::VectorXd& x, double p, Eigen::MatrixXd& J) const override;
  Eigen::VectorXcd spectrum(const Eigen::VectorXd& x, double p) const override;
  // The tangent-plane spectrum of the analytic Jacobian with first-order error bounds.
  CertifiedSpectrum certified_spectrum(const Eigen::VectorXd& x, double p, bool refine) const override;
  // Central differences, except for beta: zero wherever the problem is defined (kappa = 0, or the
  // one-point domain beta = 0 of a pulling rest shape, where a difference would step outside).
  void parameter_derivative(const Eigen::VectorXd& x, double p, Eigen::VectorXd& Fp) const override;
  std::string parameter_name() const override { return to_string(free_); }

  int L() const { return L_; }
  ContinuationParameter free_parameter() const { return free_; }
  const Scene& scene() const { return scene_; }
  double start_parameter() const { return get_parameter(scene_, free_); }
  // Throws InvalidArgument("beta", ...) unless the scene's l = 2 block is autonomous (no rest-shape
  // m = 1, 2 content that rotates with the flow, or kappa = 0): where equilibria exist.
  static void require_autonomous(const Scene& scene);
  static Eigen::Index index_of_mode(int l) { return 5 + (l - 3); }  // the a_l entry

  // Coefficients at a full parameter set (two-parameter problems use this) or at the free value p.
  ModalCoefficients coefficients_at(const Parameters& q) const;
  const ModalCoefficients& coefficients(double p) const;  // cached for the last p

  // sigma from the area constraint, F (the dynamics), its Jacobian DF, at any x != 0.
  static double sigma(const ModalCoefficients& c, const Eigen::VectorXd& x);
  static void dynamics(const ModalCoefficients& c, const Eigen::VectorXd& x, Eigen::VectorXd& F);
  static void dynamics_jacobian(const ModalCoefficients& c, const Eigen::VectorXd& x, Eigen::MatrixXd& DF);
  // The l = 2 rows of F at a given sigma (five equations in x.head(5)) and their x-Jacobian
  // (d/dsigma of row i is slope_2 x_i): the equilibrium equations of the l = 2 block.
  static void l2_dynamics(const ModalCoefficients& c, const Eigen::VectorXd& x2, double sigma, Eigen::VectorXd& F2);
  static void l2_jacobian(const ModalCoefficients& c, double sigma, Eigen::MatrixXd& J2);

  // The ellipsoidal equilibrium (a = 0, v = 0) at p, from the closed form (analysis/steady_states).
  Eigen::VectorXd ellipsoidal_state(double p) const;
  ModalState observe(const Eigen::VectorXd& x, double p) const;
  // The ModalModel state (f20, Re f21, Im f21, Re f22, Im f22, ln Delta_3, ..., ln Delta_L) of x
  // (every a_l != 0), for cross-checks against ModalModel::rhs.
  std::vector<double> to_modal_model_state(const Eigen::VectorXd& x, double p) const;

 private:
  Scene scene_;
  ContinuationParameter free_;
  int L_;
  double w0_ = 1;  // orientation of the rest shape's l = 2 axis (+-1; irrelevant when kappa = 0)
  mutable std::optional<ModalCoefficients> cache_;
  mutable double cache_p_ = 0;
};

// The symmetry-breaking branch-point curve of mode l in two parameters: the
// ellipsoidal state (a = 0) continued in p2 with p1 free and the extra equation Upsilon_l(sigma) = 0.
// Unknowns X = (x_2 (the five l = 2 coordinates), p1); the equations are the l = 2 rows of G and
// Upsilon_l(sigma) = 0, so the curve is a branch of the same engine.
class ModalBranchPointCurve final : public ContinuationProblem {
 public:
  // Throws InvalidArgument("p2", ...) unless p1, p2 are independent (not equal, not Lambda with Delta or
  // lambda, not S with C or Delta0), and InvalidArgument("l", ...) unless 3 <= l <= L.
  ModalBranchPointCurve(const Scene& scene, ContinuationParameter p1, ContinuationParameter p2, int l);
  Eigen::Index dimension() const override { return 6; }
  void residual(const Eigen::VectorXd& X, double p2, Eigen::VectorXd& R) const override;
  Eigen::VectorXcd spectrum(const Eigen::VectorXd& X, double p2) const override;
  CertifiedSpectrum certified_spectrum(const Eigen::VectorXd& X, double p2, bool refine) const override;
  std::string parameter_name() const override { return to_string(p2_); }
  std::vector<std::string> parameter_names() const override { return {to_string(p1_), to_string(p2_)}; }
  std::vector<double> parameter_values(const Eigen::VectorXd& X, double p2) const override { return {X[5], p2}; }
  int mode() const { return l_; }
  // (x_2, p1) at a BP of a one-parameter modal run in p1 (with p2 at the scene's value).
  Eigen::VectorXd start(const Eigen::VectorXd& x_bp, double p1_bp) const;
  double start_parameter() const { return get_parameter(scene_, p2_); }
  Parameters parameters(double p1, double p2) const;

 private:
  Scene scene_;
  ContinuationParameter p1_, p2_;
  int l_;
  ModalEquilibriumProblem base_;
};

// The mode of a symmetry-breaking branch point at x: among the modes with a_l = 0 (whose a_l
// direction is an eigenvector with eigenvalue Upsilon_l(sigma)), the one with Upsilon_l closest to 0.
// Throws InvalidArgument("x", ...) when every a_l is non-zero.
int critical_mode(const ModalEquilibriumProblem& problem, const Eigen::VectorXd& x, double p);

}  // namespace rbcstab
