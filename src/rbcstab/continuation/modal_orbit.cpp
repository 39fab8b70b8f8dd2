#include "rbcstab/continuation/modal_orbit.hpp"

#include <cmath>
#include <complex>
#include <limits>

#include "rbcstab/continuation/detail/finite_difference.hpp"
#include "rbcstab/continuation/detail/rest_direction.hpp"
#include "rbcstab/core/constants.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/core/phasor.hpp"
#include "rbcstab/integrate/integrator.hpp"
#include "rbcstab/integrate/simulation.hpp"
#include "rbcstab/model/coefficients.hpp"
#include "rbcstab/model/scene.hpp"

namespace rbcstab {

namespace {

using detail::fd_step;

// Mode l of entry i of x (2 for the l = 2 block).
int mode_of(Eigen::Index i) { return i < 5 ? 2 : static_cast<int>(i) - 2; }

}  // namespace

Scene total_area_scene(const Scene& simulated) {
  Scene s = simulated;
  s.parameters.Delta = initial_state(simulated).f.total_excess_area();
  return s;
}

ModalForcedSystem::ModalForcedSystem(const Scene& scene, ContinuationParameter free)
    : scene_(scene), free_(free), L_(scene.L) {
  scene_.validate();
  require_L(L_, 3, kMaxL, "the modal orbit needs at least one mode l >= 3");
  direction_ = direction_of(scene_);
}

ModalForcedSystem::Direction ModalForcedSystem::direction_of(const Scene& scene) {
  // The rest shape's direction (its size is kappa = 1/(Lambda S), so a branch may pass Delta0 = 0).
  const InitialState init = oriented_initial_state(scene);
  for (int l = 3; l <= init.g.L; ++l)
    if (init.g.excess_area(l) != 0)
      throw InvalidArgument("rest_delta_l", "the modal model cannot hold a stress-free shape with l >= 3 content");
  const std::complex<double> z0 = std::sqrt(2.0) * init.g.at(2, 2), v0 = std::sqrt(2.0) * init.g.at(2, 1);
  const double w0 = -init.g.at(2, 0).real();
  const double q0 = std::sqrt(std::norm(z0) + w0 * w0 + std::norm(v0));
  Direction d;
  if (q0 > 0) {
    d.z0 = z0 / q0;
    d.v0 = v0 / q0;
    d.w0 = w0 / q0;
  }
  return d;
}

const ModalForcedSystem::Direction& ModalForcedSystem::direction(double p) const {
  if (free_ != ContinuationParameter::beta) return direction_;
  auto it = directions_.find(p);
  if (it != directions_.end()) return it->second;
  if (directions_.size() >= 8) directions_.clear();  // no reference is held across calls
  return directions_.emplace(p, direction_of(with_parameter(scene_, free_, p))).first->second;
}

const ModalCoefficients& ModalForcedSystem::coefficients(double p) const {
  auto it = cache_.find(p);
  if (it != cache_.end()) return it->second;
  if (cache_.size() >= 8) cache_.clear();  // no reference is held across calls
  return cache_.emplace(p, modal_coefficients(with_parameter(scene_, free_, p).parameters, L_, 0.0)).first->second;
}

Eigen::VectorXd ModalForcedSystem::forcing_with(double t, double inv_Lambda, double k, const Direction& d) const {
  Eigen::VectorXd h = Eigen::VectorXd::Zero(dimension());
  const std::complex<double> zt = d.z0 * unit_phasor(t);
  h[0] = k * zt.real();
  h[1] = -inv_Lambda + k * zt.imag();
  h[2] = k * d.w0;
  h[3] = k * d.v0.real();  // co-rotating frame: the m = 1 forcing is constant
  h[4] = k * d.v0.imag();
  return h;
}

Eigen::VectorXd ModalForcedSystem::forcing(double t, double p) const {
  const ModalCoefficients& c = coefficients(p);
  return forcing_with(t, c.inv_Lambda, c.parameters.inv_Lambda_S(), direction(p));
}

void ModalForcedSystem::rhs(double t, std::span<const double> x, double p, std::span<double> f) const {
  const Eigen::Map<const Eigen::VectorXd> X(x.data(), dimension());
  Eigen::Map<Eigen::VectorXd> F(f.data(), dimension());
  modal_dynamics(coefficients(p), X, forcing(t, p), 0.0, F);
}

void ModalForcedSystem::jacobian(double t, std::span<const double> x, double p, Eigen::MatrixXd& J) const {
  const Eigen::Map<const Eigen::VectorXd> X(x.data(), dimension());
  modal_dynamics_jacobian(coefficients(p), X, forcing(t, p), 0.0, J);
}

const ModalForcedSystem::Slopes& ModalForcedSystem::slopes(double p) const {
  auto it = slopes_.find(p);
  if (it != slopes_.end()) return it->second;
  if (free_ == ContinuationParameter::beta) {
    // beta turns the rest shape only: no coefficient depends on it (and beta = 0, pi are both edges
    // of its domain, where a difference would step outside). Its forcing term: parameter_derivative.
    Slopes d;
    d.dups0.assign(static_cast<std::size_t>(L_ - 1), 0.0);
    d.dslope.assign(static_cast<std::size_t>(L_ - 1), 0.0);
    const detail::RestDirection r = detail::rest_direction(p, true);  // exact
    d.dg.z0 = r.dz0, d.dg.w0 = r.dw0, d.dg.v0 = r.dv0;
    if (slopes_.size() >= 8) slopes_.clear();
    return slopes_.emplace(p, std::move(d)).first->second;
  }
  const double h = fd_step(p);
  auto at = [&](double q) { return modal_coefficients(with_parameter(scene_, free_, q).parameters, L_, 0.0); };
  const ModalCoefficients c0 = at(p), plus = at(p + h);
  // Central differences, or second-order one-sided ones on the edge of the domain (lambda = 0).
  ModalCoefficients minus, c2;
  bool central = true;
  try {
    minus = at(p - h);
  } catch (const InvalidArgument&) {
    central = false;
    c2 = at(p + 2 * h);
  }
  auto slope = [&](auto get) {
    return central ? (get(plus) - get(minus)) / (2 * h) : (4 * get(plus) - 3 * get(c0) - get(c2)) / (2 * h);
  };
  Slopes d;
  for (int l = 2; l <= L_; ++l) {
    const std::size_t k = static_cast<std::size_t>(l - 2);
    d.dups0.push_back(slope([k](const ModalCoefficients& c) { return c.Upsilon[k](0.0); }));
    d.dslope.push_back(slope([k](const ModalCoefficients& c) { return c.Upsilon[k].slope; }));
  }
  d.dinvL = slope([](const ModalCoefficients& c) { return c.inv_Lambda; });
  d.dkappa = slope([](const ModalCoefficients& c) { return c.parameters.inv_Lambda_S(); });
  if (slopes_.size() >= 8) slopes_.clear();
  return slopes_.emplace(p, std::move(d)).first->second;
}

void ModalForcedSystem::parameter_derivative(double t, std::span<const double> x, double p,
                                             std::span<double> fp) const {
  // F_i = Y_l(i) x_i + R x + h_i with Y_l = Y_l(0) + slope_l sigma and sigma from the sums N, D of
  // modal_area_balance: dsigma/dp from dN = sum q_l dY_l(0)/dp + x.dh, dD = sum q_l dslope_l/dp,
  //   dF_i/dp = (dups0_l + dslope_l sigma + slope_l dsigma) x_i + dh_i   (h is linear in 1/Lambda, kappa,
  //   and in the rest direction g; beta moves only g).
  const Eigen::Map<const Eigen::VectorXd> X(x.data(), dimension());
  const ModalCoefficients& c = coefficients(p);
  const Slopes& d = slopes(p);
  const Eigen::VectorXd h = forcing(t, p);
  Eigen::VectorXd dh = forcing_with(t, d.dinvL, d.dkappa, direction(p));
  // h = kappa g(beta) + shear: dh/dbeta = kappa g'(beta), g' exact (detail/rest_direction.hpp).
  if (free_ == ContinuationParameter::beta) dh += forcing_with(t, 0.0, c.parameters.inv_Lambda_S(), d.dg);
  const AreaBalance b = modal_area_balance(c, X, h);
  const double s = b.sigma();
  double dN = X.dot(dh), dD = 0;
  for (Eigen::Index i = 0; i < dimension(); ++i) {
    const std::size_t k = static_cast<std::size_t>(mode_of(i) - 2);
    const double q = X[i] * X[i];
    dN += q * d.dups0[k];
    dD += q * d.dslope[k];
  }
  const double ds = b.sigma_change(dN, dD);
  for (Eigen::Index i = 0; i < dimension(); ++i) {
    const std::size_t k = static_cast<std::size_t>(mode_of(i) - 2);
    fp[static_cast<std::size_t>(i)] = (d.dups0[k] + d.dslope[k] * s + c.Upsilon[k].slope * ds) * X[i] + dh[i];
  }
}

ModalState ModalForcedSystem::observe(double t, const Eigen::VectorXd& x, double p) const {
  const ModalCoefficients& c = coefficients(p);
  const double Delta = c.parameters.Delta;
  ModalState s;
  s.sigma = modal_sigma(c, x, forcing(t, p));
  const double q2 = std::hypot(std::hypot(x[0], x[1]), x[2]);
  s.r = q2 > 0 ? std::hypot(x[0], x[1]) / q2 : 0.0;
  s.Psi = -std::atan2(x[1], x[0]);
  if (s.Psi <= -kPi) s.Psi += 2 * kPi;
  s.Delta_l.assign(static_cast<std::size_t>(L_ - 1), 0.0);
  s.Delta_l[0] = Delta * x.head(5).squaredNorm();
  for (int l = 3; l <= L_; ++l) {
    const double a = x[ModalEquilibriumProblem::index_of_mode(l)];
    s.Delta_l[static_cast<std::size_t>(l - 2)] = Delta * a * a;
  }
  return s;
}

std::vector<double> ModalForcedSystem::to_modal_model_state(double t, const Eigen::VectorXd& x, double p) const {
  const double Delta = coefficients(p).parameters.Delta;
  const double a2 = a_l(2);
  const double fz = std::sqrt(Delta / (2 * a2)), fw = -std::sqrt(Delta / a2);
  const std::complex<double> v = std::complex<double>(x[3], x[4]) * unit_phasor(0.5 * t);  // lab frame
  std::vector<double> y = {fw * x[2], fz * v.real(), fz * v.imag(), fz * x[0], fz * x[1]};
  for (int l = 3; l <= L_; ++l) {
    const double al = x[ModalEquilibriumProblem::index_of_mode(l)];
    require(al != 0, "a_l", al, "non-zero (the modal model carries ln Delta_l)");
    y.push_back(std::log(Delta * al * al));
  }
  return y;
}

Eigen::VectorXd ModalForcedSystem::from_modal_model_state(const ModalModel& m, double t, std::span<const double> y,
                                                          double p) const {
  const double Delta = coefficients(p).parameters.Delta;
  const double a2 = a_l(2);
  const double fz = std::sqrt(Delta / (2 * a2)), fw = -std::sqrt(Delta / a2);
  const std::complex<double> v = std::complex<double>(y[1], y[2]) * unit_phasor(-0.5 * t);  // co-rotating
  // Built through a std::vector (GCC 12 flags element writes into a fresh dynamic Eigen vector).
  std::vector<double> x = {y[3] / fz, y[4] / fz, y[0] / fw, v.real() / fz, v.imag() / fz};
  x.resize(static_cast<std::size_t>(dimension()), 0.0);
  const std::vector<int>& active = m.active_modes();
  for (std::size_t j = 0; j < active.size(); ++j)
    if (active[j] <= L_)
      x[static_cast<std::size_t>(ModalEquilibriumProblem::index_of_mode(active[j]))] =
          std::sqrt(std::exp(y[5 + j]) / Delta);
  return Eigen::Map<const Eigen::VectorXd>(x.data(), dimension());
}

Eigen::VectorXd ModalForcedSystem::relaxed_state(const Scene& simulated, double T, const std::function<void()>& poll,
                                                 double rtol, std::string* failure) const {
  require(std::isfinite(T) && T > 0, "T", T, "a finite number > 0");
  simulated.validate();
  const ModalModel m(simulated.parameters, initial_state(simulated));
  const std::vector<double> y0 = m.initial_state();
  const double grid[1] = {kTwoPi * std::ceil(T / kTwoPi)};
  IntegratorOptions o;
  o.rtol = rtol;
  o.atol = 1e-13;
  o.poll = poll;
  const IntegrationResult r = integrate(m, y0, 0.0, grid, o, {});
  if (r.status != IntegrationStatus::success) {
    if (!failure) throw InvalidArgument("T", "the relaxing simulation failed: " + r.reason);
    *failure = run_reason(r.status, r.reason, simulated.parameters);
    return Eigen::VectorXd::Constant(Eigen::Index(dimension()), std::numeric_limits<double>::quiet_NaN());
  }
  return from_modal_model_state(m, grid[0], r.y, start_parameter());
}

}  // namespace rbcstab
