#include "rbcstab/continuation/equilibrium.hpp"

#include <cmath>
#include <vector>

#include "rbcstab/continuation/dense.hpp"

#include "rbcstab/continuation/detail/rest_direction.hpp"
#include "rbcstab/continuation/detail/sphere_constraint.hpp"
#include "rbcstab/core/constants.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/integrate/integrator.hpp"

namespace rbcstab {

ReducedEquilibriumProblem::ReducedEquilibriumProblem(const Scene& scene, ContinuationParameter free)
    : scene_(scene), free_(free) {
  scene_.validate();
  init_ = oriented_initial_state(scene_);
  model(start_parameter());  // throws InvalidArgument("beta", ...) for a forced scene
}

const ReducedModel& ReducedEquilibriumProblem::model(double p) const {
  if (!cache_ || cache_p_ != p) {
    const Scene at = with_parameter(scene_, free_, p);  // throws InvalidArgument outside p's domain
    // beta turns the rest shape: its direction is rebuilt per value.
    cache_.emplace(at.parameters, free_ == ContinuationParameter::beta ? oriented_initial_state(at) : init_);
    cache_p_ = p;
    // The domain of an equilibrium (at every p, not only the start: a branch in Delta0 from 0 or in
    // beta from 0 would otherwise walk into a forced system read at t = 0).
    if (at.parameters.inv_Lambda_S() > 0 && std::abs(cache_->z0(0)) > 0) {
      cache_.reset();
      const std::string where =
          free_ == ContinuationParameter::beta ? "" : " at " + to_string(free_) + " = " + format_value(p);
      throw InvalidArgument("beta", "beta = " + format_value(at.beta) +
                                        " gives an in-plane rest-shape component (r0 > 0)" + where +
                                        ": the reduced system is forced with period 2 pi and has no equilibria; use "
                                        "beta = 0, Delta0 = 0, or continue periodic orbits");
    }
  }
  return *cache_;
}

void ReducedEquilibriumProblem::parameter_derivative(const Eigen::VectorXd& y, double p, Eigen::VectorXd& Fp) const {
  if (free_ != ContinuationParameter::beta) {
    ContinuationProblem::parameter_derivative(y, p, Fp);
    return;
  }
  // Wherever an equilibrium exists, F does not move with beta: either kappa = 0 (no rest-shape pull)
  // or beta = 0 exactly, where the direction's slope vanishes (z0 ~ sin^2 beta, w0' ~ sin 2 beta) — and
  // a difference in beta would step off that one-point domain.
  model(p);  // the domain check
  const detail::RestDirection r = detail::rest_direction(p, false);
  const double kappa = with_parameter(scene_, free_, p).parameters.inv_Lambda_S();
  const Eigen::Vector3d dg(r.dz0, 0.0, r.dw0);
  Fp = kappa * (dg - y.dot(dg) / y.squaredNorm() * y);
}

void ReducedEquilibriumProblem::residual(const Eigen::VectorXd& y, double p, Eigen::VectorXd& G) const {
  G.resize(3);
  model(p).rhs(0, std::span<const double>(y.data(), 3), std::span<double>(G.data(), 3));
  detail::add_sphere_constraint(y, G);
}

void ReducedEquilibriumProblem::jacobian(const Eigen::VectorXd& y, double p, Eigen::MatrixXd& J) const {
  StructuredJacobian sj;
  double dfdt[3];
  model(p).jacobian(0, std::span<const double>(y.data(), 3), sj, dfdt);
  Eigen::Matrix<double, 3, 3, Eigen::RowMajor> D;
  sj.to_dense(std::span<double>(D.data(), 9));
  J = D;
  detail::add_sphere_constraint_jacobian(y, J);
}

Eigen::VectorXcd ReducedEquilibriumProblem::spectrum(const Eigen::VectorXd& y, double p) const {
  return certified_spectrum(y, p, false).values;
}

CertifiedSpectrum ReducedEquilibriumProblem::certified_spectrum(const Eigen::VectorXd& y, double p, bool) const {
  StructuredJacobian sj;
  double dfdt[3];
  model(p).jacobian(0, std::span<const double>(y.data(), 3), sj, dfdt);
  Eigen::Matrix<double, 3, 3, Eigen::RowMajor> D;
  sj.to_dense(std::span<double>(D.data(), 9));
  return detail::certified_tangent_spectrum(Eigen::MatrixXd(D), y, assembly_accuracy(3));
}

Eigen::VectorXd ReducedEquilibriumProblem::relaxed_state(double T) const {
  require(std::isfinite(T) && T > 0, "T", T, "a finite number > 0");
  const ReducedModel& m = model(start_parameter());
  const std::vector<double> y0 = m.initial_state();
  const double grid[1] = {T};
  IntegratorOptions o;
  o.rtol = 1e-10;
  o.atol = 1e-12;
  const IntegrationResult r = integrate(m, y0, 0.0, grid, o, {});
  return Eigen::Vector3d(r.y[0], r.y[1], r.y[2]);
}

PolarState polar(const Eigen::VectorXd& y) {
  PolarState s;
  const double q = y.norm();
  s.r = std::hypot(y[0], y[1]) / q;
  s.Psi = -std::atan2(y[1], y[0]);
  if (s.Psi <= -kPi) s.Psi += 2 * kPi;
  return s;
}

}  // namespace rbcstab
