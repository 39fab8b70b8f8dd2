#include "rbcstab/integrate/quadrature.hpp"

#include <cmath>
#include <stdexcept>
#include <utility>

#include "rbcstab/core/error.hpp"

namespace rbcstab {

WithQuadratures::WithQuadratures(const System& base, Quadrature quadrature)
    : base_(base), n_(base.dimension()), q_(std::move(quadrature)) {
  require(q_.count >= 1, "quadrature count", static_cast<double>(q_.count), ">= 1");
  require(q_.multiplier_coefficients.empty() || q_.multiplier_coefficients.size() == q_.count,
          "multiplier_coefficients", static_cast<double>(q_.multiplier_coefficients.size()),
          "empty or one per quadrature");
}

void WithQuadratures::rhs(double t, std::span<const double> y, std::span<double> dydt) const {
  const std::span<const double> x = y.first(n_);
  const std::span<double> f = dydt.first(n_);
  base_.rhs(t, x, f);
  q_.rate(t, x, f, dydt.subspan(n_, q_.count));
}

void WithQuadratures::jacobian(double t, std::span<const double> y, StructuredJacobian& J,
                               std::span<double> dfdt) const {
  if (q_.multiplier_coefficients.empty())
    throw std::logic_error("these quadratures have no Jacobian: integrate them with an explicit stepper");
  StructuredJacobian Jb;
  base_.jacobian(t, y.first(n_), Jb, dfdt.first(n_));
  J.resize(dimension());
  for (std::size_t i = 0; i < n_; ++i) {
    J.block_start[i] = Jb.block_start[i];
    J.diag[i] = Jb.diag[i];
    J.upper[i] = Jb.upper[i];
    J.lower[i] = Jb.lower[i];
    J.v[i] = Jb.v[i];
    J.w[i] = Jb.w[i];
  }
  // dg/dt at fixed x: a central difference (the base exposes only dF/dt, which mixes dmu/dt into v).
  const double h = 1e-7 * (1 + std::abs(t));
  std::vector<double> f(n_), gp(q_.count), gm(q_.count);
  base_.rhs(t + h, y.first(n_), f);
  q_.rate(t + h, y.first(n_), f, gp);
  base_.rhs(t - h, y.first(n_), f);
  q_.rate(t - h, y.first(n_), f, gm);
  for (std::size_t k = 0; k < q_.count; ++k) {
    const std::size_t i = n_ + k;
    J.block_start[i] = 1;
    J.diag[i] = 0;
    J.v[i] = q_.multiplier_coefficients[k];
    J.w[i] = 0;
    dfdt[i] = (gp[k] - gm[k]) / (2 * h);
  }
}

std::optional<CompactForm> WithQuadratures::compact_form(std::span<const double> y0) const {
  std::optional<CompactForm> form = base_.compact_form(y0.first(n_));
  if (!form) return form;
  for (std::size_t k = 0; k < q_.count; ++k) form->keep(y0[n_ + k]);
  return form;
}

void WithQuadratures::compact_rhs(double t, std::span<const double> x, const CompactForm& form,
                                  std::span<double> dxdt) const {
  const std::size_t nx = x.size() - q_.count;
  // The base's components come first in both x and y: the base reads its own from the same form.
  base_.compact_rhs(t, x.first(nx), form, dxdt.first(nx));
  scratch_.resize(2 * n_);
  const std::span<double> y(scratch_.data(), n_), f(scratch_.data() + n_, n_);
  for (std::size_t k = 0; k < n_; ++k) {
    y[k] = form.y(k, x);
    f[k] = form.rate(k, dxdt);
  }
  q_.rate(t, y, f, dxdt.subspan(nx, q_.count));
}

std::vector<double> WithQuadratures::initial_state() const {
  std::vector<double> y = base_.initial_state();
  y.resize(y.size() + q_.count, 0.0);
  return y;
}

Quadrature tension_integral(const ReducedModel& model) {
  Quadrature q;
  q.rate = [&model](double t, std::span<const double> x, std::span<const double>, std::span<double> rate) {
    rate[0] = model.sigma(t, x);
  };
  q.multiplier_coefficients = {1 / model.Upsilon2().slope};
  return q;
}

}  // namespace rbcstab
