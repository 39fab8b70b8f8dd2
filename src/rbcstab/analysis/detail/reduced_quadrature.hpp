#pragma once
// The reduced model plus one quadrature: y[3] = int_0^t sigma_R dt'. Because Upsilon_l is affine in sigma,
// G_l(T) = int_0^T Upsilon_l(sigma_R) dt = T Upsilon_l(y[3](T)/T) for every l at once, with the integrator's own
// error control on the integral (no resampling error).
#include <memory>

#include "rbcstab/model/coefficients.hpp"
#include "rbcstab/model/levels.hpp"

namespace rbcstab::detail {

class ReducedWithQuadrature final : public System {
 public:
  ReducedWithQuadrature(const Parameters& p, const InitialState& init)
      : reduced_(p, init), slope_(p.B / Gamma2(p.lambda, 2)) {}
  const ReducedModel& reduced() const { return reduced_; }
  ModelLevel level() const override { return ModelLevel::reduced; }
  std::size_t dimension() const override { return 4; }
  int L() const override { return reduced_.L(); }
  void rhs(double t, std::span<const double> y, std::span<double> dydt) const override {
    reduced_.rhs(t, y.first(3), dydt.first(3));
    dydt[3] = reduced_.sigma_from_mu(reduced_.mu(t, y.first(3)));
  }
  // d sigma_R / dy = (B / Gamma_2^2) d mu / dy and the reduced J's rank-one part is y (d mu/dy)^T, so the
  // quadrature row joins the rank-one part with v[3] = B / Gamma_2^2.
  void jacobian(double t, std::span<const double> y, StructuredJacobian& J, std::span<double> dfdt) const override {
    StructuredJacobian Jr;
    double dr[3];
    reduced_.jacobian(t, y.first(3), Jr, dr);
    J.resize(4);
    for (std::size_t i = 0; i < 3; ++i) {
      J.block_start[i] = Jr.block_start[i];
      J.diag[i] = Jr.diag[i];
      J.upper[i] = Jr.upper[i];
      J.lower[i] = Jr.lower[i];
      J.v[i] = Jr.v[i];
      J.w[i] = Jr.w[i];
      dfdt[i] = dr[i];
    }
    J.block_start[3] = 1;
    J.diag[3] = 0;
    J.v[3] = slope_;
    J.w[3] = 0;
    // d sigma_R/dt at fixed y = slope * d mu/dt, and d mu/dt = dfdt[2]/y[2] is not usable at w = 0; recompute.
    const double h = 1e-7 * (1 + std::abs(t));
    dfdt[3] = slope_ * (reduced_.mu(t + h, y.first(3)) - reduced_.mu(t - h, y.first(3))) / (2 * h);
  }
  Observation observe(double t, std::span<const double> y) const override { return reduced_.observe(t, y.first(3)); }
  std::vector<double> initial_state() const override {
    std::vector<double> y = reduced_.initial_state();
    y.push_back(0.0);
    return y;
  }
  ModeAmplitudes amplitudes(double t, std::span<const double> y) const override {
    return reduced_.amplitudes(t, y.first(3));
  }

 private:
  ReducedModel reduced_;
  double slope_;
};

}  // namespace rbcstab::detail
