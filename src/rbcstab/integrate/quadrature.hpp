#pragma once
// Quadratures integrated alongside a system: the state (x, q) with x' = F(t, x) and q' = g(t, x, F(t, x)).
// Integrals along a trajectory (the mean tension, a winding angle) then get the integrator's own error
// control instead of a resampling error.
#include <cstddef>
#include <functional>
#include <span>
#include <vector>

#include "rbcstab/model/reduced_model.hpp"
#include "rbcstab/model/system.hpp"

namespace rbcstab {

struct Quadrature {
  std::size_t count = 1;
  // Writes q' = g(t, x, f) (count values) given the base state x and its rate f = F(t, x).
  std::function<void(double t, std::span<const double> x, std::span<const double> f, std::span<double> rate)> rate;
  // For implicit steppers: an integrand affine in the base system's multiplier mu (the tension, or the
  // reduced model's mu), g_k = a_k(t) + b_k mu(t, x), has dg_k/dx = b_k grad mu, and grad mu is the w of the
  // base Jacobian's rank-one part v w^T: the quadrature rows join it as v = b_k, w = 0. One b_k per integrand;
  // empty: explicit steppers only (jacobian() throws std::logic_error).
  std::vector<double> multiplier_coefficients;
};

class WithQuadratures final : public System {
 public:
  // Keeps a reference to base: it must outlive this system.
  WithQuadratures(const System& base, Quadrature quadrature);
  ModelLevel level() const override { return base_.level(); }
  std::size_t dimension() const override { return n_ + q_.count; }
  int L() const override { return base_.L(); }
  void rhs(double t, std::span<const double> y, std::span<double> dydt) const override;
  // The base Jacobian plus the quadrature rows b_k w^T (zero 1x1 blocks); d/dt of g_k by a central difference.
  void jacobian(double t, std::span<const double> y, StructuredJacobian& J, std::span<double> dfdt) const override;
  Observation observe(double t, std::span<const double> y) const override { return base_.observe(t, y.first(n_)); }
  // The base's initial state with every quadrature at 0.
  std::vector<double> initial_state() const override;
  ModeAmplitudes amplitudes(double t, std::span<const double> y) const override {
    return base_.amplitudes(t, y.first(n_));
  }
  // The base's compact form with the quadratures kept as they are (after the base's components), if it has one.
  std::optional<CompactForm> compact_form(std::span<const double> y0) const override;
  // The base's x' then q' = g(t, y, F) at the base state y and rate F the form rebuilds. Uses a scratch of this
  // object: one integration at a time (as every use here).
  void compact_rhs(double t, std::span<const double> x, const CompactForm& form, std::span<double> dxdt) const override;

 private:
  const System& base_;
  std::size_t n_;
  Quadrature q_;
  mutable std::vector<double> scratch_;  // the base's y and F for compact_rhs
};

// int_0^t sigma_R dt' for the reduced model: sigma_R = Upsilon_2^-1(mu) is affine in mu (b = 1/slope_2). Because
// every Upsilon_l is affine in sigma, int_0^T Upsilon_l(sigma_R) dt = T Upsilon_l(<sigma_R>_T) for all l at once.
Quadrature tension_integral(const ReducedModel& model);  // refers to model: it must outlive the integrand

}  // namespace rbcstab
