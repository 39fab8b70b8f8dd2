#include "rbcstab/model/reduced_model.hpp"

#include <cmath>

#include "rbcstab/core/phasor.hpp"
#include "rbcstab/model/tension.hpp"

namespace rbcstab {

// State y = (Re z, Im z, w) with z = r e^{-i Psi} = f22 sqrt(2 a2/Delta), w = -f20 sqrt(a2/Delta).
// The multiplier mu keeps Q = |z|^2 + w^2 exactly constant:  mu Q = Im(z)/Lambda - kappa (Re(conj(z) z0) + w w0),
// which on Q = 1 is Upsilon_2 of Eq. red_eqs; r' and Psi' of Eq. red_eqs follow from z' by the chain rule.
ReducedModel::ReducedModel(const Parameters& p, const InitialState& init)
    : p_(p), L_(init.f.L), Upsilon2_(Upsilon_l(p, 2)) {
  p_.validate();
  const double a2 = 2;
  const double Delta2 = init.f.excess_area(2);
  const double fs = std::sqrt(2 * a2 / Delta2);
  const std::complex<double> z = init.f.at(2, 2) * fs;
  double w = -init.f.at(2, 0).real() * std::sqrt(a2 / Delta2);
  // Drop the m = +-1 content (zero for beta in {0, pi/2}) and renormalise onto the sphere.
  const double q = std::sqrt(std::norm(z) + w * w);
  y0_ = {z.real() / q, z.imag() / q, w / q};
  inv_Lambda_ = 1 / p.Lambda();
  kappa_ = p.inv_Lambda_S();
  const double Delta0 = init.g.excess_area(2);
  if (Delta0 > 0 && kappa_ > 0) {
    z00_ = init.g.at(2, 2) * std::sqrt(2 * a2 / Delta0);
    w0_ = -init.g.at(2, 0).real() * std::sqrt(a2 / Delta0);
    const double q0 = std::sqrt(std::norm(z00_) + w0_ * w0_);
    z00_ /= q0;
    w0_ /= q0;
  } else {
    z00_ = 0;
    w0_ = 0;
  }
}

std::complex<double> ReducedModel::z0(double t) const { return z00_ * unit_phasor(t); }

// The area balance of tension.hpp with the multiplier mu as the one rate (slope 1, zero 0):
// (1/2) Q' = mu Q + y.h with h = (kappa z0, -1/Lambda, kappa w0) (the rotation does no work).
// zz0 = z0(t): every evaluation at t computes the phasor once (it was a quarter of an orbit shooting's time).
AreaBalance ReducedModel::balance(std::complex<double> zz0, std::span<const double> y) const {
  AreaBalance b;
  b.add_mode(GrowthRate{1.0, 0.0}, y[0] * y[0] + y[1] * y[1] + y[2] * y[2]);
  b.add_work(kappa_ * (y[0] * zz0.real() + y[1] * zz0.imag() + y[2] * w0_) - inv_Lambda_ * y[1]);
  return b;
}

double ReducedModel::mu(double t, std::span<const double> y) const { return balance(z0(t), y).sigma(); }

void ReducedModel::rhs_at(std::complex<double> zz0, double m, std::span<const double> y, std::span<double> dydt) const {
  dydt[0] = m * y[0] - y[1] + kappa_ * zz0.real();
  dydt[1] = y[0] + m * y[1] - inv_Lambda_ + kappa_ * zz0.imag();
  dydt[2] = m * y[2] + kappa_ * w0_;
}

void ReducedModel::rhs(double t, std::span<const double> y, std::span<double> dydt) const {
  const std::complex<double> zz0 = z0(t);
  rhs_at(zz0, balance(zz0, y).sigma(), y, dydt);
}

// df/dy = mu I + (rotation) + y (grad mu)^T, grad mu_i = the change of mu when y_i moves (the area balance).
void ReducedModel::jacobian(double t, std::span<const double> y, StructuredJacobian& J, std::span<double> dfdt) const {
  const std::complex<double> zz0 = z0(t);
  const AreaBalance b = balance(zz0, y);
  const double m = b.sigma();
  J.resize(3);
  J.block_start = {2, 0, 1};
  J.diag = {m, m, m};
  J.upper[0] = -1;
  J.lower[0] = 1;
  J.v = {y[0], y[1], y[2]};
  grad_mu(zz0, b, y, J.w);
  // z0' = i z0
  const double dz0r = -zz0.imag(), dz0i = zz0.real();
  const double dmu_dt = b.sigma_change(kappa_ * (y[0] * dz0r + y[1] * dz0i), 0.0);
  dfdt[0] = kappa_ * dz0r + y[0] * dmu_dt;
  dfdt[1] = kappa_ * dz0i + y[1] * dmu_dt;
  dfdt[2] = y[2] * dmu_dt;
}

void ReducedModel::grad_mu(std::complex<double> zz0, const AreaBalance& b, std::span<const double> y,
                           std::span<double> g) const {
  const double dwork[3] = {kappa_ * zz0.real(), kappa_ * zz0.imag() - inv_Lambda_, kappa_ * w0_};
  for (int i = 0; i < 3; ++i) g[i] = b.sigma_change(dwork[i], 2 * y[i]);
}

ReducedModel::DenseTerms ReducedModel::dense_terms(double t, std::span<const double> y) const {
  DenseTerms d;
  const std::complex<double> zz0 = z0(t);
  const AreaBalance b = balance(zz0, y);
  const double m = b.sigma();
  rhs_at(zz0, m, y, d.f);
  double g[3];
  grad_mu(zz0, b, y, g);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) d.J[3 * i + j] = (i == j ? m : 0.0) + y[i] * g[j];
  d.J[1] -= 1;  // the rotation (-y1, y0, 0)
  d.J[3] += 1;
  d.direction[0] = zz0.real(), d.direction[1] = zz0.imag(), d.direction[2] = w0_;
  return d;
}

void ReducedModel::coefficient_derivatives(std::span<const double> y, const double g[3], double dinvL[3],
                                           double dkappa[3]) {
  const double Q = y[0] * y[0] + y[1] * y[1] + y[2] * y[2];
  const double yg = y[0] * g[0] + y[1] * g[1] + y[2] * g[2];
  for (int i = 0; i < 3; ++i) {
    dinvL[i] = y[1] / Q * y[i] - (i == 1 ? 1.0 : 0.0);
    dkappa[i] = g[i] - yg / Q * y[i];
  }
}

Observation ReducedModel::observe(double t, std::span<const double> y) const {
  Observation o;
  o.Delta_l.assign(L_ - 1, 0.0);
  const double Q = y[0] * y[0] + y[1] * y[1] + y[2] * y[2];
  o.Delta_l[0] = p_.Delta * Q;
  o.Delta2 = o.Delta_l[0];
  o.sigma = sigma_from_mu(mu(t, y));
  o.f22 = std::sqrt(p_.Delta / 4) * std::complex<double>(y[0], y[1]);
  return o;
}

ModeAmplitudes ReducedModel::amplitudes(double, std::span<const double> y) const {
  ModeAmplitudes f(L_);
  const std::complex<double> f22 = std::sqrt(p_.Delta / 4) * std::complex<double>(y[0], y[1]);
  f.at(2, 2) = f22;
  f.at(2, -2) = std::conj(f22);
  f.at(2, 0) = -std::sqrt(p_.Delta / 2) * y[2];
  return f;
}

}  // namespace rbcstab
