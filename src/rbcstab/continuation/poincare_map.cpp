// The Poincare map of an autonomous orbit (poincare_map.hpp): first returns to a section by Newton in the time.
#include "rbcstab/continuation/poincare_map.hpp"

#include <cmath>
#include <limits>
#include <span>

#include "rbcstab/core/error.hpp"

namespace rbcstab {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

Eigen::VectorXd field_at(const AutonomousSystem& s, const Eigen::VectorXd& x, double p) {
  Eigen::VectorXd f(x.size());
  s.rhs(std::span<const double>(x.data(), static_cast<std::size_t>(x.size())), p,
        std::span<double>(f.data(), static_cast<std::size_t>(f.size())));
  return f;
}

}  // namespace

PoincareMap::PoincareMap(const AutonomousOrbitProblem& orbit, const Eigen::VectorXd& X, double p) : orbit_(orbit) {
  require(X.size() == orbit.dimension(), "X", static_cast<double>(X.size()), "the orbit problem's unknowns");
  x0_ = orbit.state_at_zero(X);
  T_ = AutonomousOrbitProblem::period(X);
  require(std::isfinite(T_) && T_ > 0, "T", T_, "a finite period > 0");
  const Eigen::VectorXd f = field_at(orbit.system(), x0_, p);
  require(f.allFinite() && f.norm() > 0, "|f(x0)|", f.norm(), "> 0 (an orbit's point, not an equilibrium)");
  n_ = f / f.norm();
  // The last n - 1 columns of the Householder reflection that maps n to a multiple of e_1 span n^perp.
  const Eigen::MatrixXd column = n_;
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(column);
  const Eigen::MatrixXd H = qr.householderQ() * Eigen::MatrixXd::Identity(n_.size(), n_.size());
  Q_ = H.rightCols(n_.size() - 1);
}

double PoincareMap::return_time(const Eigen::VectorXd& xi, double p, Eigen::VectorXd* reached) const {
  // Integrate to 0.9 T once, then Newton steps from there: each costs a tenth of a period. Quadratic convergence
  // from |tau - T| ~ |xi| stops below 1e-9 T, where the last linear correction is exact to ~1e-18.
  const double ta = 0.9 * T_;
  const Eigen::VectorXd ya = orbit_.flow(point(xi), ta, p);
  double tau = T_;
  if (!ya.allFinite()) return kNaN;
  for (int it = 0; it < 30; ++it) {
    const Eigen::VectorXd y = orbit_.flow(ya, tau - ta, p), f = field_at(orbit_.system(), y, p);
    const double slope = n_.dot(f), step = -n_.dot(y - x0_) / slope;
    if (!y.allFinite() || !std::isfinite(step) || !(tau + step > ta)) return kNaN;
    tau += step;
    if (std::abs(step) <= 1e-9 * T_) {
      if (reached) *reached = y + step * f;
      return tau;
    }
  }
  return kNaN;
}

void PoincareMap::residual(const Eigen::VectorXd& xi, double p, Eigen::VectorXd& F) const {
  Eigen::VectorXd y;
  if (!std::isfinite(return_time(xi, p, &y))) {
    F = Eigen::VectorXd::Constant(dimension(), kNaN);
    return;
  }
  F = Q_.transpose() * (y - x0_) - xi;
}

Eigen::MatrixXd PoincareMap::along_flow(const Eigen::VectorXd& y, double p) const {
  const Eigen::VectorXd f = field_at(orbit_.system(), y, p);
  return Eigen::MatrixXd::Identity(y.size(), y.size()) - f * n_.transpose() / n_.dot(f);
}

Eigen::MatrixXd PoincareMap::map_jacobian(const Eigen::VectorXd& xi, double p) const {
  Eigen::VectorXd y;
  const double tau = return_time(xi, p, &y);
  if (!std::isfinite(tau)) return Eigen::MatrixXd::Constant(dimension(), dimension(), kNaN);
  const Eigen::MatrixXd M = orbit_.monodromy(orbit_.shooting_guess(point(xi), tau, p), p);
  return Q_.transpose() * along_flow(y, p) * M * Q_;
}

void PoincareMap::parameter_derivative(const Eigen::VectorXd& xi, double p, Eigen::VectorXd& Fp) const {
  Eigen::VectorXd y;
  const double tau = return_time(xi, p, &y);
  if (!std::isfinite(tau)) {
    Fp = Eigen::VectorXd::Constant(dimension(), kNaN);
    return;
  }
  Fp = Q_.transpose() * along_flow(y, p) * orbit_.flow_sensitivity(orbit_.shooting_guess(point(xi), tau, p), p);
}

}  // namespace rbcstab
