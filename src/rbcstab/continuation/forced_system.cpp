// The forced systems' parameter derivative by central differences, and the in-plane reduced system with its
// exact one.
#include "rbcstab/continuation/forced_system.hpp"

#include <cmath>
#include <complex>
#include <span>
#include <utility>
#include <vector>

#include "rbcstab/continuation/detail/finite_difference.hpp"
#include "rbcstab/continuation/detail/rest_direction.hpp"
#include "rbcstab/core/constants.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/core/phasor.hpp"
#include "rbcstab/integrate/integrator.hpp"

namespace rbcstab {

namespace {

// Central-difference step in p: cube root of eps balances truncation against rounding.
using detail::fd_step;

}  // namespace

void ForcedSystem::parameter_derivative(double t, std::span<const double> x, double p, std::span<double> fp) const {
  const double h = fd_step(p);
  std::vector<double> fm(fp.size());
  rhs(t, x, p + h, fp);
  rhs(t, x, p - h, fm);
  for (std::size_t i = 0; i < fp.size(); ++i) fp[i] = (fp[i] - fm[i]) / (2 * h);
}

void ForcedSystem::flow_terms(double t, std::span<const double> x, double p, std::span<double> f, Eigen::MatrixXd& J,
                              std::span<double> fp) const {
  rhs(t, x, p, f);
  jacobian(t, x, p, J);
  if (!fp.empty()) parameter_derivative(t, x, p, fp);
}

// ---------------------------------------------------------------- reduced in-plane system

ReducedForcedSystem::ReducedForcedSystem(const Scene& scene, ContinuationParameter free) : scene_(scene), free_(free) {
  scene_.validate();
  init_ = oriented_initial_state(scene_);
}

const ReducedModel& ReducedForcedSystem::model(double p) const {
  auto it = cache_.find(p);
  if (it == cache_.end()) {
    if (cache_.size() >= 8) cache_.clear();             // no reference is held across calls (see parameter_derivative)
    const Scene at = with_parameter(scene_, free_, p);  // throws InvalidArgument outside p's domain
    // beta turns the rest shape: its direction is rebuilt per value (cached with the model).
    it = cache_.try_emplace(p, at.parameters, free_ == ContinuationParameter::beta ? oriented_initial_state(at) : init_)
             .first;
  }
  return it->second;
}

void ReducedForcedSystem::rhs(double t, std::span<const double> x, double p, std::span<double> f) const {
  model(p).rhs(t, x, f);
}

void ReducedForcedSystem::jacobian(double t, std::span<const double> x, double p, Eigen::MatrixXd& J) const {
  StructuredJacobian sj;
  double dfdt[3];
  model(p).jacobian(t, x, sj, dfdt);
  Eigen::Matrix<double, 3, 3, Eigen::RowMajor> D;
  sj.to_dense(std::span<double>(D.data(), 9));
  J = D;
}

ReducedForcedSystem::Slopes ReducedForcedSystem::coefficient_slopes(double p) const {
  auto it = slopes_.find(p);
  if (it != slopes_.end()) return it->second;
  // d(1/Lambda)/dp and d kappa/dp by central differences of two scalar functions of the parameters
  // (constants during an integration, so their rounding does not disturb the error control).
  auto coefficients = [&](double q) {
    const Parameters pq = with_parameter(scene_, free_, q).parameters;
    return std::pair<double, double>(1 / pq.Lambda(), pq.inv_Lambda_S());
  };
  Slopes d;
  if (free_ == ContinuationParameter::beta) {
    // beta turns the rest shape only: 1/Lambda and kappa do not depend on it (and beta = 0, pi are
    // both edges of its domain, where a difference would step outside); the direction's slope is exact.
    d.kappa = coefficients(p).second;
    const detail::RestDirection r = detail::rest_direction(p, false);
    d.dz0 = r.dz0, d.dw0 = r.dw0;
    if (slopes_.size() >= 8) slopes_.clear();
    slopes_.emplace(p, d);
    return d;
  }
  const double h = fd_step(p);
  const auto c0 = coefficients(p), plus = coefficients(p + h);
  d.kappa = c0.second;
  try {
    const auto minus = coefficients(p - h);
    d.dinvL = (plus.first - minus.first) / (2 * h);
    d.dkappa = (plus.second - minus.second) / (2 * h);
  } catch (const InvalidArgument&) {
    // p on the edge of its domain (lambda = 0): second-order one-sided difference.
    const auto c2 = coefficients(p + 2 * h);
    d.dinvL = (4 * plus.first - 3 * c0.first - c2.first) / (2 * h);
    d.dkappa = (4 * plus.second - 3 * c0.second - c2.second) / (2 * h);
  }
  if (slopes_.size() >= 8) slopes_.clear();
  slopes_.emplace(p, d);
  return d;
}

void ReducedForcedSystem::parameter_derivative(double t, std::span<const double> x, double p,
                                               std::span<double> fp) const {
  const ReducedModel& m = model(p);
  const std::complex<double> z0 = m.z0(t);
  const double g[3] = {z0.real(), z0.imag(), m.w0()};
  parameter_derivative(t, x, p, g, fp);
}

void ReducedForcedSystem::parameter_derivative(double t, std::span<const double> x, double p, const double g[3],
                                               std::span<double> fp) const {
  // f depends on p only through 1/Lambda and kappa = 1/(Lambda S) (ReducedModel::coefficient_derivatives), with
  // g = (Re z0(t), Im z0(t), w0) the rest shape's direction, so df/dp is exact in y and t.
  // Central differences of f itself would put rounding noise (~eps |f| / h) into the sensitivity
  // equation and force rk8pd at rtol 1e-12 into small steps (measured: ~6x slower shooting).
  // beta enters only through the direction g (1/Lambda and kappa fixed): df/dbeta = kappa (g' - (y.g'/Q) y)
  // with g' = (Re, Im of z0'(0) e^{it}, w0') exact (detail/rest_direction.hpp); zero when kappa = 0.
  const bool beta = free_ == ContinuationParameter::beta;
  const Slopes d = coefficient_slopes(p);
  if (d.kappa == 0 && !beta) {
    // kappa = 0: the model dropped the rest shape's direction; difference f in p instead.
    ForcedSystem::parameter_derivative(t, x, p, fp);
    return;
  }
  double dg[3] = {0, 0, 0};
  if (beta) {
    const std::complex<double> dz0 = d.dz0 * unit_phasor(t);
    dg[0] = dz0.real(), dg[1] = dz0.imag(), dg[2] = d.dw0;
  }
  const double Q = x[0] * x[0] + x[1] * x[1] + x[2] * x[2];
  const double ydg = x[0] * dg[0] + x[1] * dg[1] + x[2] * dg[2];
  double dfdinvL[3], dfdkappa[3];
  ReducedModel::coefficient_derivatives(x, g, dfdinvL, dfdkappa);
  for (std::size_t i = 0; i < 3; ++i) {
    const double dfdg = d.kappa * (dg[i] - ydg / Q * x[i]);
    fp[i] = d.dinvL * dfdinvL[i] + d.dkappa * dfdkappa[i] + dfdg;
  }
}

void ReducedForcedSystem::flow_terms(double t, std::span<const double> x, double p, std::span<double> f,
                                     Eigen::MatrixXd& J, std::span<double> fp) const {
  const ReducedModel::DenseTerms d = model(p).dense_terms(t, x);
  J.resize(3, 3);
  for (int i = 0; i < 3; ++i) {
    f[i] = d.f[i];
    for (int j = 0; j < 3; ++j) J(i, j) = d.J[3 * i + j];
  }
  if (!fp.empty()) parameter_derivative(t, x, p, d.direction, fp);
}

Eigen::VectorXd ReducedForcedSystem::relaxed_state(double T, const std::function<void()>& poll) const {
  require(std::isfinite(T) && T > 0, "T", T, "a finite number > 0");
  const ReducedModel& m = model(start_parameter());
  const std::vector<double> y0 = m.initial_state();
  const double grid[1] = {kTwoPi * std::ceil(T / kTwoPi)};
  IntegratorOptions o;
  o.rtol = 1e-10;
  o.atol = 1e-12;
  o.poll = poll;
  const IntegrationResult r = integrate(m, y0, 0.0, grid, o, {});
  return Eigen::Vector3d(r.y[0], r.y[1], r.y[2]);
}

}  // namespace rbcstab
