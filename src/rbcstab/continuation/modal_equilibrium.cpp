#include "rbcstab/continuation/modal_equilibrium.hpp"

#include <cmath>
#include <complex>

#include "rbcstab/continuation/dense.hpp"

#include "rbcstab/analysis/steady_states.hpp"
#include "rbcstab/continuation/detail/sphere_constraint.hpp"
#include "rbcstab/core/constants.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/model/coefficients.hpp"
#include "rbcstab/model/scene.hpp"

namespace rbcstab {

ModalEquilibriumProblem::ModalEquilibriumProblem(const Scene& scene, ContinuationParameter free)
    : scene_(scene), free_(free), L_(scene.L) {
  scene_.validate();
  require_L(L_, 3, kMaxL, "the modal problem needs at least one mode l >= 3");
  const double g20 = oriented_initial_state(scene_).g.at(2, 0).real();
  w0_ = g20 <= 0 ? 1.0 : -1.0;  // w0 = -g20 sqrt(a2/Delta0) normalised: +1 for beta = 0
  require_autonomous(scene_);
}

void ModalEquilibriumProblem::require_autonomous(const Scene& scene) {
  // g_{2,m} is proportional to D^(2)_{m,0}(beta) (initial_state): read the orientation from it
  // directly (initial_state would also validate the perturbations against a continued Delta).
  const std::vector<double> D = wigner_column(2, scene.beta);
  const double in_plane = std::abs(D[3]) + std::abs(D[4]);
  if (scene.parameters.inv_Lambda_S() > 0 && in_plane > 0)
    throw InvalidArgument("beta", "beta = " + format_value(scene.beta) +
                                      " gives the rest shape m = 1, 2 content that rotates with the flow: the modal "
                                      "l = 2 block is forced with period 2 pi and has no equilibria; use beta = 0, "
                                      "Delta0 = 0, or continue periodic orbits");
}

void ModalEquilibriumProblem::parameter_derivative(const Eigen::VectorXd& x, double p, Eigen::VectorXd& Fp) const {
  if (free_ != ContinuationParameter::beta) {
    ContinuationProblem::parameter_derivative(x, p, Fp);
    return;
  }
  coefficients(p);  // the domain check
  Fp = Eigen::VectorXd::Zero(dimension());
}

ModalCoefficients modal_coefficients(const Parameters& q, int L, double w0) {
  q.validate();
  ModalCoefficients c;
  c.parameters = q;
  c.L = L;
  c.inv_Lambda = 1 / q.Lambda();
  c.kappa_w0 = q.inv_Lambda_S() * w0;
  for (int l = 2; l <= L; ++l) c.Upsilon.push_back(Upsilon_l(q, l));
  return c;
}

ModalCoefficients ModalEquilibriumProblem::coefficients_at(const Parameters& q) const {
  return modal_coefficients(q, L_, w0_);
}

const ModalCoefficients& ModalEquilibriumProblem::coefficients(double p) const {
  if (!cache_ || cache_p_ != p) {
    const Scene at = with_parameter(scene_, free_, p);  // throws InvalidArgument outside p's domain
    // At every p, not only the start: a branch in Delta0 from 0 or in beta from 0 would otherwise
    // walk into a forced system read as autonomous.
    require_autonomous(at);
    cache_ = coefficients_at(at.parameters);
    cache_p_ = p;
  }
  return *cache_;
}

namespace {

// The equilibrium problem's (autonomous) forcing: the shear drive of z and the rest shape's pull on w.
Eigen::VectorXd steady_forcing(const ModalCoefficients& c, Eigen::Index n) {
  Eigen::VectorXd h = Eigen::VectorXd::Zero(n);
  h[1] = -c.inv_Lambda;
  h[2] = c.kappa_w0;
  return h;
}

}  // namespace

AreaBalance modal_area_balance(const ModalCoefficients& c, const Eigen::Ref<const Eigen::VectorXd>& x,
                               const Eigen::Ref<const Eigen::VectorXd>& h) {
  AreaBalance b;
  b.add_mode(c.rate(2), x.head(5).squaredNorm());
  b.add_work(x.dot(h));  // the forcing's work on the sphere
  for (int l = 3; l <= c.L; ++l) {
    const Eigen::Index i = ModalEquilibriumProblem::index_of_mode(l);
    b.add_mode(c.rate(l), x[i] * x[i]);
  }
  return b;
}

double modal_sigma(const ModalCoefficients& c, const Eigen::Ref<const Eigen::VectorXd>& x,
                   const Eigen::Ref<const Eigen::VectorXd>& h) {
  return modal_area_balance(c, x, h).sigma();
}

double modal_dynamics(const ModalCoefficients& c, const Eigen::Ref<const Eigen::VectorXd>& x,
                      const Eigen::Ref<const Eigen::VectorXd>& h, double omega_v, Eigen::Ref<Eigen::VectorXd> F) {
  const double s = modal_sigma(c, x, h);
  const double Y2 = c.upsilon(2, s);
  F[0] = Y2 * x[0] - x[1] + h[0];
  F[1] = x[0] + Y2 * x[1] + h[1];
  F[2] = Y2 * x[2] + h[2];
  F[3] = Y2 * x[3] - omega_v * x[4] + h[3];
  F[4] = omega_v * x[3] + Y2 * x[4] + h[4];
  for (int l = 3; l <= c.L; ++l) {
    const Eigen::Index i = ModalEquilibriumProblem::index_of_mode(l);
    F[i] = c.upsilon(l, s) * x[i] + h[i];
  }
  return s;
}

void modal_dynamics_jacobian(const ModalCoefficients& c, const Eigen::Ref<const Eigen::VectorXd>& x,
                             const Eigen::Ref<const Eigen::VectorXd>& h, double omega_v, Eigen::MatrixXd& DF) {
  const Eigen::Index n = x.size();
  const AreaBalance b = modal_area_balance(c, x, h);
  const double s = b.sigma();
  DF.setZero(n, n);
  const double Y2 = c.upsilon(2, s);
  for (Eigen::Index i = 0; i < 5; ++i) DF(i, i) = Y2;
  DF(0, 1) = -1;
  DF(1, 0) = 1;
  DF(3, 4) = -omega_v;
  DF(4, 3) = omega_v;
  // DF += u grad(sigma)^T, u = dF/dsigma = slope_l x_i; grad sigma from the sums (dq_l/dx_i = 2 x_i).
  Eigen::VectorXd u(n), grad(n);
  const GrowthRate& R2 = c.rate(2);
  for (Eigen::Index i = 0; i < 5; ++i) {
    u[i] = R2.slope * x[i];
    grad[i] = b.sigma_change(2 * x[i] * R2(0.0) + h[i], 2 * x[i] * R2.slope);
  }
  for (int l = 3; l <= c.L; ++l) {
    const Eigen::Index i = ModalEquilibriumProblem::index_of_mode(l);
    const GrowthRate& Rl = c.rate(l);
    DF(i, i) = Rl(s);
    u[i] = Rl.slope * x[i];
    grad[i] = b.sigma_change(2 * x[i] * Rl(0.0) + h[i], 2 * x[i] * Rl.slope);
  }
  DF += u * grad.transpose();
}

double ModalEquilibriumProblem::sigma(const ModalCoefficients& c, const Eigen::VectorXd& x) {
  return modal_sigma(c, x, steady_forcing(c, x.size()));
}

void ModalEquilibriumProblem::l2_dynamics(const ModalCoefficients& c, const Eigen::VectorXd& x2, double sigma,
                                          Eigen::VectorXd& F2) {
  const double Y2 = c.upsilon(2, sigma);
  F2.resize(5);
  F2[0] = Y2 * x2[0] - x2[1];
  F2[1] = x2[0] + Y2 * x2[1] - c.inv_Lambda;
  F2[2] = Y2 * x2[2] + c.kappa_w0;
  F2[3] = Y2 * x2[3] - 0.5 * x2[4];
  F2[4] = 0.5 * x2[3] + Y2 * x2[4];
}

void ModalEquilibriumProblem::l2_jacobian(const ModalCoefficients& c, double sigma, Eigen::MatrixXd& J2) {
  const double Y2 = c.upsilon(2, sigma);
  J2 = Y2 * Eigen::MatrixXd::Identity(5, 5);
  J2(0, 1) = -1;
  J2(1, 0) = 1;
  J2(3, 4) = -0.5;
  J2(4, 3) = 0.5;
}

void ModalEquilibriumProblem::dynamics(const ModalCoefficients& c, const Eigen::VectorXd& x, Eigen::VectorXd& F) {
  F.resize(x.size());
  modal_dynamics(c, x, steady_forcing(c, x.size()), 0.5, F);
}

void ModalEquilibriumProblem::dynamics_jacobian(const ModalCoefficients& c, const Eigen::VectorXd& x,
                                                Eigen::MatrixXd& DF) {
  modal_dynamics_jacobian(c, x, steady_forcing(c, x.size()), 0.5, DF);
}

void ModalEquilibriumProblem::residual(const Eigen::VectorXd& x, double p, Eigen::VectorXd& G) const {
  dynamics(coefficients(p), x, G);
  detail::add_sphere_constraint(x, G);
}

void ModalEquilibriumProblem::jacobian(const Eigen::VectorXd& x, double p, Eigen::MatrixXd& J) const {
  dynamics_jacobian(coefficients(p), x, J);
  detail::add_sphere_constraint_jacobian(x, J);
}

Eigen::VectorXcd ModalEquilibriumProblem::spectrum(const Eigen::VectorXd& x, double p) const {
  return certified_spectrum(x, p, false).values;
}

CertifiedSpectrum ModalEquilibriumProblem::certified_spectrum(const Eigen::VectorXd& x, double p, bool) const {
  Eigen::MatrixXd DF;
  dynamics_jacobian(coefficients(p), x, DF);
  return detail::certified_tangent_spectrum(DF, x, assembly_accuracy(DF.rows()));
}

Eigen::VectorXd ModalEquilibriumProblem::ellipsoidal_state(double p) const {
  const OutOfPlaneEquilibrium e = out_of_plane_equilibrium(with_parameter(scene_, free_, p).parameters);
  // The closed form is written for w0 = +1; the system is odd in (w, w0). (Built through a
  // std::vector with the values first: GCC 12 flags element writes into a fresh dynamic Eigen vector as null
  // dereferences.)
  std::vector<double> x = {e.r * std::cos(e.Psi), -e.r * std::sin(e.Psi), w0_ * e.w};
  x.resize(static_cast<std::size_t>(dimension()), 0.0);
  return Eigen::Map<const Eigen::VectorXd>(x.data(), dimension());
}

ModalState ModalEquilibriumProblem::observe(const Eigen::VectorXd& x, double p) const {
  const ModalCoefficients& c = coefficients(p);
  const double Delta = c.parameters.Delta;
  ModalState s;
  s.sigma = sigma(c, x);
  const double q2 = std::hypot(std::hypot(x[0], x[1]), x[2]);
  s.r = q2 > 0 ? std::hypot(x[0], x[1]) / q2 : 0.0;  // no l = 2 area (never an equilibrium): r = 0
  s.Psi = -std::atan2(x[1], x[0]);
  if (s.Psi <= -kPi) s.Psi += 2 * kPi;
  s.Delta_l.assign(static_cast<std::size_t>(L_ - 1), 0.0);
  s.Delta_l[0] = Delta * x.head(5).squaredNorm();
  for (int l = 3; l <= L_; ++l)
    s.Delta_l[static_cast<std::size_t>(l - 2)] = Delta * x[index_of_mode(l)] * x[index_of_mode(l)];
  return s;
}

std::vector<double> ModalEquilibriumProblem::to_modal_model_state(const Eigen::VectorXd& x, double p) const {
  const double Delta = coefficients(p).parameters.Delta;
  const double a2 = a_l(2);
  const double fz = std::sqrt(Delta / (2 * a2)), fw = -std::sqrt(Delta / a2);
  std::vector<double> y = {fw * x[2], fz * x[3], fz * x[4], fz * x[0], fz * x[1]};
  for (int l = 3; l <= L_; ++l) {
    const double al = x[index_of_mode(l)];
    require(al != 0, "a_l", al, "non-zero (the modal model carries ln Delta_l)");
    y.push_back(std::log(Delta * al * al));
  }
  return y;
}

int critical_mode(const ModalEquilibriumProblem& problem, const Eigen::VectorXd& x, double p) {
  const ModalCoefficients& c = problem.coefficients(p);
  const double s = ModalEquilibriumProblem::sigma(c, x);
  int best = 0;
  for (int l = 3; l <= c.L; ++l) {
    if (x[ModalEquilibriumProblem::index_of_mode(l)] != 0) continue;  // not an eigendirection there
    if (best == 0 || std::abs(c.upsilon(l, s)) < std::abs(c.upsilon(best, s))) best = l;
  }
  require(best != 0, "x", 0.0, "a state with at least one mode l >= 3 at zero amplitude");
  return best;
}

// ---- the branch-point curve ----

ModalBranchPointCurve::ModalBranchPointCurve(const Scene& scene, ContinuationParameter p1, ContinuationParameter p2,
                                             int l)
    : scene_(scene), p1_(p1), p2_(p2), l_(l), base_(scene, p1) {
  require_independent(p1, p2, "p2");
  require(l >= 3 && l <= scene.L, "l", l, "in [3, L = " + std::to_string(scene.L) + "]");
}

Parameters ModalBranchPointCurve::parameters(double p1, double p2) const {
  const Scene at = with_parameter(with_parameter(scene_, p2_, p2), p1_, p1);
  ModalEquilibriumProblem::require_autonomous(at);
  return at.parameters;
}

void ModalBranchPointCurve::residual(const Eigen::VectorXd& X, double p2, Eigen::VectorXd& R) const {
  const ModalCoefficients c = base_.coefficients_at(parameters(X[5], p2));
  Eigen::VectorXd x = Eigen::VectorXd::Zero(base_.dimension());
  x.head(5) = X.head(5);
  const double s = ModalEquilibriumProblem::sigma(c, x);
  Eigen::VectorXd F2;
  ModalEquilibriumProblem::l2_dynamics(c, x.head(5), s, F2);
  R.resize(6);
  R.head(5) = F2 + (x.squaredNorm() - 1) * x.head(5);
  // Upsilon_l / |slope_l| = sigma - sigma_l^c: the same zero, scaled to O(sigma).
  R[5] = c.upsilon(l_, s) / std::abs(c.rate(l_).slope);
}

Eigen::VectorXcd ModalBranchPointCurve::spectrum(const Eigen::VectorXd& X, double p2) const {
  return certified_spectrum(X, p2, false).values;
}

CertifiedSpectrum ModalBranchPointCurve::certified_spectrum(const Eigen::VectorXd& X, double p2, bool) const {
  Eigen::VectorXd x = Eigen::VectorXd::Zero(base_.dimension());
  x.head(5) = X.head(5);
  const ModalCoefficients c = base_.coefficients_at(parameters(X[5], p2));
  Eigen::MatrixXd DF;
  ModalEquilibriumProblem::dynamics_jacobian(c, x, DF);
  return detail::certified_tangent_spectrum(DF, x, assembly_accuracy(DF.rows()));
}

Eigen::VectorXd ModalBranchPointCurve::start(const Eigen::VectorXd& x_bp, double p1_bp) const {
  Eigen::VectorXd X(6);
  X << x_bp.head(5), p1_bp;
  return X;
}

}  // namespace rbcstab
