#include "rbcstab/continuation/equilibrium.hpp"

#include <cmath>
#include <vector>

#include <Eigen/Eigenvalues>
#include <Eigen/QR>

#include "rbcstab/continuation/detail/sphere_constraint.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/integrate/integrator.hpp"

namespace rbcstab {

ReducedEquilibriumProblem::ReducedEquilibriumProblem(const Scene& scene, ContinuationParameter free)
    : scene_(scene), free_(free) {
  scene_.validate();
  // Only the rest shape's orientation enters (ReducedModel normalises g onto the sphere; its size is
  // kappa = 1/(Lambda S) from the parameters), so build it with Delta0 = Delta > 0: a branch started
  // at Delta0 = 0 keeps the orientation when continued in Delta0.
  Scene oriented = scene_;
  oriented.parameters.Delta0 = oriented.parameters.Delta;
  init_ = initial_state(oriented);
  const ReducedModel& m = model(start_parameter());
  if (scene_.parameters.inv_Lambda_S() > 0 && std::abs(m.z0(0)) > 0)
    throw InvalidArgument("beta", "beta = " + format_value(scene_.beta) +
                                      " gives an in-plane rest-shape component (r0 > 0): the reduced system is "
                                      "forced with period 2 pi and has no equilibria; use beta = 0, Delta0 = 0, "
                                      "or continue periodic orbits");
}

const ReducedModel& ReducedEquilibriumProblem::model(double p) const {
  if (!cache_ || cache_p_ != p) {
    cache_.emplace(with_parameter(scene_.parameters, free_, p), init_);
    cache_p_ = p;
  }
  return *cache_;
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
  StructuredJacobian sj;
  double dfdt[3];
  model(p).jacobian(0, std::span<const double>(y.data(), 3), sj, dfdt);
  Eigen::Matrix<double, 3, 3, Eigen::RowMajor> D;
  sj.to_dense(std::span<double>(D.data(), 9));
  return detail::tangent_spectrum(Eigen::MatrixXd(D), y);
}

Eigen::VectorXd ReducedEquilibriumProblem::scene_state() const {
  const std::vector<double> y0 = model(start_parameter()).initial_state();
  return Eigen::Vector3d(y0[0], y0[1], y0[2]);
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
  if (s.Psi <= -M_PI) s.Psi += 2 * M_PI;
  return s;
}

}  // namespace rbcstab
